#pragma once
// bench-classification's scoring of one frame's classification against the simulator's ground
// truth: labels/NNNNNN.png (instance id per pixel), objects.txt (each object's moving flag and
// rigid-core pose: a person's torso, a car's body) and groundtruth.tum (camera poses).
//  - dynamic class: a feature is truly dynamic when its pixel's label is an object that moves
//    in this frame; it is predicted dynamic when its class is not Static;
//  - non-moving objects (standing person, parked car): the frame counts as "static" when at
//    least half of the features whose pixels show the object are Static (objects with >= 3);
//  - rigid sets: the set's object is the label most of its members show; its camera-frame
//    motion M (q = R p + t) becomes the world motion A = T_wc(k) M T_wc(k-1)^-1 and is compared
//    with the torso's (car's) A_gt = L_k L_{k-1}^-1: rotation error angle(R_A^T R_gt), translation
//    error |A(c) - A_gt(c)| at the world position c of the set's virtual centroid in frame k-1
//    (the displacement of the points it stands for).
#include <dynslam/core/Frame.h>
#include <dynslam/core/ObjectGroundTruth.h>

#include <map>
#include <string>
#include <vector>

namespace dynslam::bench {

struct Truth {
  cv::Mat labels;  ///< CV_16UC1
  std::vector<core::ObjectGroundTruthRow> objects;
  Eigen::Isometry3d T_world_camera = Eigen::Isometry3d::Identity();
};

struct ClassificationScore {
  size_t tp = 0, fp = 0, fn = 0, tn = 0;
  /// Where the errors come from: false positives on background pixels (a mask or a carried
  /// membership that took background) vs on non-moving objects (judged moving); false negatives
  /// on features given to no object (no mask held them) vs on objects judged static.
  size_t fpBackground = 0, fpNonMovingObject = 0, fnNoObject = 0, fnJudgedStatic = 0;
  /// The same four counts over the features with a depth reading only (scene flow, Eq. 11,
  /// needs the 3-D point: beyond the sensor's range a feature can only be classified by its
  /// object's earlier decisions).
  size_t tpDepth = 0, fpDepth = 0, fnDepth = 0, tnDepth = 0;
  /// category -> frames a non-moving object was seen with >= 3 features, and of those, static.
  std::map<std::string, std::pair<size_t, size_t>> nonMoving;
  std::map<std::string, std::pair<size_t, size_t>> moving;  ///< same for moving: dynamic
  std::map<std::string, std::vector<double>> rotErrDeg, transErrM;  ///< per category
  size_t rigidSetsUnmatched = 0;  ///< sets whose members mostly show no moving object
  /// category -> the frames a non-moving object was judged moving, by where most of its
  /// features that were not Static went: "own track (matched)" / "(coasting)" (the track whose
  /// last matched detection is that object, matched this frame or not), "another object's
  /// mask" (another track's mask holds the pixel this frame), "another object's carried
  /// membership" (no mask of that track holds it: carried over from the last frame), "no
  /// track". Tracks are known by their detections' simulator ids (the ground-truth detector).
  std::map<std::string, std::map<std::string, size_t>> nonMovingMisses;
  /// The false negatives without a depth reading, by "category, distance band: where" (the
  /// object's rigid core 0-5 / 5-10 / 10-20 / 20+ m ahead; where: "static in an object judged
  /// dynamic" (the feature's own tests kept it Static), "given to an object without scene flow",
  /// "given to an object judged static", "in a depthless box" (outside its middle half, which
  /// far_object_min_depth measures), "in a masked box, outside its mask", "in a track's box
  /// only", "in no box").
  std::map<std::string, size_t> depthlessMisses;
  /// The same for the false negatives with a depth reading.
  std::map<std::string, size_t> depthMisses;
  /// The false positives, by "what the pixel shows: whose feature it was" (what: background, a
  /// non-moving car or person; whose: "its own mask's" (the mask of the object's own track holds
  /// its pixel), "a mask's" (another object's mask holds it), "carried" (its object's membership
  /// carried over from the last frame), "a depthless box's", "no object's"), and with or without
  /// depth.
  std::map<std::string, size_t> falsePositives;
  /// Track id -> the simulator id of the detection it last matched (ground-truth detector).
  std::map<int, int> trackTruth;
  /// Feature tracking error, px, of the features with depth tracked from the last frame, by what
  /// their pixel shows now ("background", "moving car", "non-moving car", ...): the distance
  /// from their last pixel to where the true motions (camera, and the object's rigid core) put
  /// the point seen now. The depth's noise enters only through the parallax (second order). A
  /// person's pose is its torso's: its limbs' tracks read their swing as error.
  std::map<std::string, std::vector<double>> trackingErrorPx;
  std::map<std::int64_t, cv::Point2f> lastPixel;  ///< feature id -> its pixel in the last frame
  /// Background features with depth, none at a depth edge, whose true flow from the last frame
  /// is 1 px or more: their tracked flow's length along the true flow over the true flow's
  /// ([0] nearer than kNearFlowDepth, [1] farther). A median under 1 is a tracker whose flows
  /// come out short, and a trajectory built on them short too. Per feature and by the median,
  /// because a depth reading off the point (a silhouette) makes a wrong "true" flow.
  std::vector<double> backgroundFlowRatio[2];
  static constexpr double kNearFlowDepth = 4.0;  ///< m

  void add(const core::Frame& frame, const Truth& truth, const Truth* previous);
  double precision() const { return tp + fp ? double(tp) / double(tp + fp) : 0; }
  double recall() const { return tp + fn ? double(tp) / double(tp + fn) : 0; }
  double precisionWithDepth() const {
    return tpDepth + fpDepth ? double(tpDepth) / double(tpDepth + fpDepth) : 0;
  }
  double recallWithDepth() const {
    return tpDepth + fnDepth ? double(tpDepth) / double(tpDepth + fnDepth) : 0;
  }
};

}  // namespace dynslam::bench
