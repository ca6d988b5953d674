#pragma once
// Scene-flow classification of the tracked features (method.md section 3) with the adaptive
// rigid point sets of the dynamic objects (section 4). Per frame:
//  1. each feature belongs to the object whose mask holds it (ObjectMembership.h), else to the
//     background;
//  2. the camera's motion since the previous frame (CameraMotion.h: gyro rotation and the
//     background's registered translation, a 6-DoF background registration without a gyro, or
//     the poses of an earlier stage);
//  3. the scene flow F (Eq. 11) of every object feature; the object's speed is the size of its
//     features' flow divided by the time it spans; dynamic when above speed_threshold;
//  4. dynamic objects update their AdaptiveRigidPointSet from the frame-to-frame pairs;
//  5. classes: background and non-moving objects Static (a parked car, a standing person);
//     dynamic rigid objects (cars) Rigid, except the pairs their registration rejected, which do
//     not move with the body (NonRigid); dynamic non-rigid objects Rigid inside the rigid set,
//     NonRigid outside it.
//
// Departures from the letter of the method, each settable back to it, and why (figures from
// bench-classification on the simulator's D455-like depth, sigma = 1.5 mm/m^2 z^2):
//  - speed_window (default 10 frames): F is measured from the oldest position of each feature
//    within the window, with the composed camera motion, and divided by the time between. The
//    frame-to-frame F of a static point 3 m away is ~2 cm of noise, 0.6 m/s at 30 Hz, six
//    times the 0.1 m/s threshold. speed_window = 1 is the method's frame interval.
//  - speed_statistic = median_flow (default): the norm of the component-wise median of the
//    features' flow vectors, not the mean of their norms (mean_norm, the method's wording). A
//    mean of norms adds up the noise of every feature instead of averaging it out, and one
//    feature on a depth edge (background depth on an object pixel) moves the mean by metres.
//  - depth_window (default 5 px): a feature's 3-D point takes the median depth of the window
//    around it (pixels on the surface of its own reading only: within 5 cm, 2 % or 3 sigma of
//    the difference of two readings, camera.depth_sigma_z2), not the single reading at its
//    pixel: with independent per-pixel noise that is 4x less noise for 25 pixels, which the
//    speed of a standing person and the rotation of a rigid set both need. 1: the reading.
//  - speed_noise_sigmas (default 2): the speed must exceed the threshold by twice its expected
//    noise (from the depth noise model and the features' depths and spans, plus the standard
//    error of the camera translations the flow removed over its span). A parked car 8 m
//    away has sigma(z) = 10 cm per reading: even with the window depth and a third of a second
//    its features' velocities scatter by ~0.1 m/s, the threshold itself, while a person a metre
//    away measures to a few mm/s. 0: the plain threshold.
//  - still_feature_speed (default 0 = off): a feature classified Static on the last frame whose
//    own scene flow over the window stays below this speed stays Static, whichever object's
//    mask now holds it. A mask holds every pixel of its box within its depth range: where a
//    walker passes less than e = 0.5 m from a standing person, or the standing person's
//    detection is missed, the walker's mask takes the standing person's pixels and their
//    features took the walker's class (indoor_people_high with the pipeline's masks: the
//    standing person static in 68 % of frames, 78 % with 0.2 m/s; dynamic precision 0.878 ->
//    0.904, recall 0.844 -> 0.840; estimator APE 0.0170 -> 0.0157 m with remove). Only features
//    that were Static: a walker's foot planted on the floor is still for a third of a second
//    too, and letting such features turn Static (tried) broke the estimator (19 restarts, APE
//    2.4 m), as they move again before the window's speed says so.
//    still_feature_in_still_box (default false) widens that to features that were not Static
//    where the pixel lies in the box of another object judged not to move: the standing
//    person's features that a walker's mask held from the frame they appeared in (the walker
//    passing in front or behind it, within e) never were Static. A walker's planted foot is
//    rarely inside a standing person's box. indoor_people_high seeds 1-6, pipeline masks:
//    standing person static 0.889 / 0.924 / 0.894 / 0.830 / 0.903 / 0.825 -> 0.906 / 0.946 /
//    0.905 / 0.845 / 0.911 / 0.831, dynamic precision +0.001-0.003, recall -0.000-0.003.
//    unmeasured_feature_by_depth (default false) does the same for the features with no scene
//    flow yet, new corners, whose motion says nothing: in a moving object's mask and in the box
//    of an object judged not to move, a feature is Static when its depth is nearer the still
//    object's d_t than the moving one's. Where a walker passes within e of a standing person,
//    the standing person's new corners were the largest share of its features judged moving
//    (indoor_people_high seed 6: 715 of 1603; 609 more measured faster than 0.8 m/s, tracks that
//    slid with the walker's silhouette).
//    still_carried_outside_box (default false): membership carries over from frame to frame
//    for a feature that no mask holds (the detector missed the object, or the mask was cut
//    short), and so it did for background that a mask once spilled over: a walker beside a
//    wall within e of it takes the wall's new corners into its mask, and they stayed the
//    walker's as long as they were tracked (outdoor_street_high: the largest share of false
//    dynamic features, 1485 of 4159 over seeds 1-6). Such a feature, slower than
//    still_feature_speed and outside the track's box this frame, is Static and leaves the
//    object; inside the box it may be a planted foot and stays. Street precision 0.934 ->
//    0.951 (mean of seeds 1-6), recall 0.714 -> 0.717; indoors within 0.001.
//    still_above_feet_fraction (default 0 = off): a mask holds every pixel of its box within e
//    of d_t, so a walker passing a wall within e of it takes the wall's pixels (the next
//    largest share of the street's false dynamic features: walker 45 on outdoor_street_high
//    seed 5, along a shop front, 265 features more than 20 px from its body). The only parts
//    of a walking person that stand still are its planted feet: a feature slower than
//    still_feature_speed in a non-rigid object's mask, above this fraction of the box's height
//    from its bottom, is Static. 0.25: street precision 0.951 -> 0.955 (every seed >= 0.95),
//    indoor recall 0.9466 -> 0.9421.
//  - moving_feature_speed (default 0 = off): the converse. A feature in the mask of an object
//    judged not to move whose own scene flow over the window exceeds this speed is NonRigid:
//    a walker passing less than e behind or in front of a standing person puts its pixels
//    into the standing person's mask (most of the walkers' features classified static on
//    indoor_people_high were there), and a still object's own features measure a few cm/s.
//    Up to moving_feature_max_speed: a faster flow is a depth jump at a silhouette or a
//    feature whose track slid from one surface onto another (on indoor_people_high a third of
//    the still objects' features above 0.8 m/s read more than 3 m/s; the walkers', 0.6-1.7).
//    Faster by speed_noise_sigmas of the flow's depth noise, as every speed test here: a parked
//    car 9-10 m away has about 1 m/s of noise on a flow over a frame or two (outdoor_street_high
//    seed 6: 284 of its own features NonRigid; with the margin precision 0.880 -> 0.932).
//  - max_nonrigid_flow_speed (default 0 = off): such flows, faster than a person moves (by
//    speed_noise_sigmas of their depth noise: 7 m away a one-frame flow has metres per second
//    of it), on a person's features are no measurement at all: they do not count towards the
//    object's speed and the feature is unmeasured (unmeasured_feature_by_depth decides it).
//    Where a walker passes a standing person, the standing person's features read up to 100
//    m/s (a track that slid off the silhouette onto the wall behind, a window depth that
//    flipped surfaces), and with half its features such the component-wise median said it
//    moved.
//  - far_object_min_depth (default 0 = off): objects beyond the depth range. A detection whose
//    box has too little depth has no mask (core::ObjectMask::valid false) and, the method
//    deciding by scene flow, its features stayed Static: on outdoor_street_high, where the
//    depth ends at 10 m, 2586 of the 3430 dynamic features missed had no depth, 1755 of them in
//    the boxes of such detections (bench-classification seed 1). Set to the depth camera's range
//    (or less): the features without depth in the middle half of such a box (nearer its edge:
//    mostly background and silhouette corners) belong to its object and are taken to be at
//    least that far, and FarPointMotion.h bounds their own motion from below from their pixels
//    and the camera's motion; the object is dynamic when the median of those bounds over the
//    window, per second, exceeds speed_threshold by speed_noise_sigmas of its noise
//    (far_object_pixel_sigma of tracking error per pixel, and the camera's translation), and
//    then its depthless features moving faster than speed_threshold by themselves are NonRigid
//    (no depth: no rigid set), the others (background seen through the box) Static.
// The camera's motion between frames, which the scene flow removes, is the gyro's rotation and
// a translation registered on background features (CameraMotion.h). Background means outside
// every detection box and every track's box (background_outside_boxes), not merely outside the
// masks: a mask misses a tenth of a walker's pixels and a missed detection leaves a walker with
// no mask at all, and a handful of such near features outvote the far wall, whose depth noise
// admits any centimetre-sized translation. On indoor_people_high the translation then followed
// a walker by 1-2 cm per frame for ten frames, and the standing person's features, the same ones
// whose speed read 0.06 m/s with the ground-truth masks, read 0.25 m/s: dynamic. With fewer
// than camera.min_inliers such pairs the camera motion is the gyro's rotation with the recent
// translation (CameraMotion.h), not a registration on the features inside boxes.
// Membership beyond the masks: a feature that no mask holds but that was on a tracked object in
// the previous frame stays with that object while its track lives, unless the object's mask box
// holds the pixel (then the mask says the feature left it): a detector miss (the track coasts)
// or a box a few pixels short does not throw the object's features into the background.
// start_moving_frames (default 1 = off): where an object judged still (a standing person) reads
// "moving", it is most often a passing walker's surface or corners sliding with a silhouette in
// its mask, in runs of a few frames (indoor_people_high seed 6: frames 243-247, 424-426); with
// K it turns dynamic on the K-th measured frame in a row that says so, which removes the
// one-frame runs and shortens the others. A new object, or one already moving, is decided at
// once.
// Objects without a speed (fewer than min_flow_features features with flow: just appeared, or
// beyond the depth range) keep their last decision; a new track takes the majority decision of
// the objects its features were on in the last frame (trackers re-number objects); without
// either it is not dynamic, as no scene flow says it moves (the method decides by flow alone).
#include <dynslam/core/Frame.h>
#include <dynslam/frontend/CameraMotion.h>
#include <dynslam/frontend/RigidPointSet.h>

#include <cstdint>
#include <deque>
#include <map>
#include <optional>
#include <unordered_map>
#include <unordered_set>
#include <vector>

namespace dynslam::frontend {

struct ObjectRegion;  // ObjectMembership.h

enum class SpeedStatistic { MedianFlow, MeanNorm };

struct DynamicClassifierParams {
  double speed_threshold = 0.1;  ///< m/s (method.md)
  int speed_window = 10;         ///< frames the scene flow spans at most (1: the method's)
  SpeedStatistic speed_statistic = SpeedStatistic::MedianFlow;
  /// Dynamic only when the speed exceeds speed_threshold by this many sigmas of its own noise
  /// (from the depth noise model camera.depth_sigma_z2 and the features' depths and spans);
  /// 0: the plain threshold of the method. See the file comment.
  double speed_noise_sigmas = 2.0;
  int min_flow_features = 3;     ///< fewer features with flow: the speed is not measured
  /// An object judged not to move turns dynamic only once its speed test says so on this many
  /// measured frames in a row (not the method; 1: at once, the method). See the file comment.
  int start_moving_frames = 1;
  /// A Static feature whose own scene flow over the window stays slower than this (m/s) stays
  /// Static whichever object's mask takes it (not the method, which decides per object; 0:
  /// off). See the file comment.
  double still_feature_speed = 0.0;
  /// ... and so does a feature that was not Static when its pixel lies in the box of another
  /// object judged not to move (not the method; false: off). See the file comment.
  bool still_feature_in_still_box = false;
  /// A feature with no scene flow yet (a new corner) in a moving object's mask is Static when
  /// its pixel lies in the box of another object judged not to move whose d_t is nearer the
  /// feature's depth than the moving object's (not the method; false: off). See the file
  /// comment.
  bool unmeasured_feature_by_depth = false;
  /// A feature that no mask holds this frame, on an object only through last frame's
  /// membership, outside that object's track box, and whose own scene flow stays slower than
  /// still_feature_speed is Static and leaves the object (not the method; false: off). See the
  /// file comment.
  bool still_carried_outside_box = false;
  /// A feature slower than still_feature_speed in a non-rigid object's mask, above this
  /// fraction of its box's height from the bottom, is Static (not the method; 0: off). See the
  /// file comment.
  double still_above_feet_fraction = 0.0;
  /// A feature in a non-moving object's mask whose own scene flow over the window is faster
  /// than this (m/s) is NonRigid (not the method; 0: off). See the file comment.
  double moving_feature_speed = 0.0;
  double moving_feature_max_speed = 2.5;  ///< m/s; faster flows do not count (see above)
  /// m/s; > 0: a feature of a non-rigid object (a person) whose scene flow over the window is
  /// faster than this, by speed_noise_sigmas of its depth noise, measured a depth jump, not a
  /// motion: its flow does not count towards the object's speed and the feature is unmeasured
  /// (not the method; 0: off). See the file comment.
  double max_nonrigid_flow_speed = 0.0;
  /// Side of the window whose robust median depth places each feature in 3-D (1: the
  /// feature's own depth reading). See the file comment.
  int depth_window = 5;
  /// The camera's translation is registered on features outside every detection box and every
  /// track's box, not just outside the masks (true); with fewer than camera.min_inliers such
  /// pairs, constant velocity. See the file comment.
  bool background_outside_boxes = true;
  /// m; > 0: the features without depth in the box of an object with too little depth are at
  /// least this far (the depth camera's range) and measure the object's motion from their
  /// pixels (not the method; 0: off). See the file comment.
  double far_object_min_depth = 0.0;
  double far_object_pixel_sigma = 0.5;  ///< px; feature tracking noise of one pixel position
  RigidPointSetParams rigid;     ///< the objects' rigid sets (method.md section 4)
  CameraMotionParams camera;     ///< the background registration
  /// Depth noise sigma(z) = depth_sigma_z2 z^2 (1/m): DynamicClassifier gives it to the camera
  /// motion and the rigid sets (their own depth_sigma_z2 is set from it).
  double depth_sigma_z2 = 0.0015;
  int seed = 1;                  ///< RANSAC draws (deterministic runs)
};

/// Counters for the stage's log and the bench.
struct ClassifierCounts {
  size_t frames = 0, features = 0, object_features = 0, dynamic_objects = 0, rigid_sets = 0;
  std::map<CameraMotionSource, size_t> camera_sources;
};

class DynamicClassifier {
 public:
  /// Throws std::invalid_argument naming a parameter that breaks a rule between keys
  /// (depth_window odd, moving_feature_max_speed above moving_feature_speed); the ranges of
  /// single keys are checked where the options are read (DynamicClassificationOptions).
  explicit DynamicClassifier(DynamicClassifierParams params = {});

  /// Fills frame.features[*].object_id and feature_class, frame.object_motions and
  /// frame.rigid_sets. Reads frame.features (ids, pixels, depths), object_masks, tracks, imu,
  /// the sensor extrinsics and T_world_camera. Frames must come in order.
  void process(core::Frame& frame);

  const CameraMotionEstimate& lastCameraMotion() const { return camera_; }
  const ClassifierCounts& counts() const { return counts_; }
  const DynamicClassifierParams& params() const { return params_; }
  // Object ids are never reused, and a street sees thousands of tracks a minute: what is kept per
  // object is forgotten once the object has not been decided for this long (s). That is longer
  // than a track coasts (max_age, seconds) and than a lost id can be revived (reid_memory 10 s in
  // the shipped inis); a revived id older than this is decided as a new track is.
  static constexpr double kObjectMemoryS = 30.0;
  /// Objects whose decision is kept (those decided within the last kObjectMemoryS).
  std::size_t rememberedObjects() const { return objects_.size(); }

 private:
  struct Observation {
    std::size_t frame = 0;  ///< counter of processed frames
    double t = 0;
    Eigen::Vector3d P;      ///< camera frame of that frame
  };

  /// far_object_min_depth: decides the objects of the depthless boxes from their features
  /// without depth (farOf: feature index -> the box holding it, or nullptr), appends their
  /// ObjectMotionState and sets `dynamic`; returns each such feature's lower bound of its own
  /// speed over the window (m/s, FarPointMotion.h; -1: not measured), by feature index.
  std::vector<double> decideFarObjects(core::Frame& frame,
                                       const std::vector<const ObjectRegion*>& farOf,
                                       std::map<int, bool>& dynamic);
  /// Object `id`'s last decision (dynamic or not), if it is remembered.
  std::optional<bool> lastDecision(int id) const;
  /// Records object `id`'s decision of this frame (time `t`, s).
  void remember(int id, bool dynamic, double t);
  /// Drops what is kept per object for the objects not decided since time `t` (s).
  void forgetObjectsUnseenSince(double t);
  /// Summed variance (m^2) of the camera translations of the frames after `frame` up to now.
  double cameraVarianceSince(std::size_t frame) const;
  /// T_{C(cur) <- C(frame)} from the chain of estimated camera motions.
  Eigen::Isometry3d cameraFromPast(std::size_t frame) const;

  DynamicClassifierParams params_;
  CameraMotionEstimator cameraEstimator_;
  CameraMotionEstimate camera_;
  ClassifierCounts counts_;
  std::size_t frame_ = 0;  ///< counter of this frame
  std::optional<double> prevT_;
  std::optional<Eigen::Isometry3d> prevPose_;
  /// T_{O <- C(frame)}: camera poses in the frame of the first one, last speed_window + 1.
  std::deque<std::pair<std::size_t, Eigen::Isometry3d>> odometry_;
  /// Variance of each frame's camera translation (m^2), frame counter -> value, same span.
  std::deque<std::pair<std::size_t, double>> cameraVar_;
  std::unordered_map<std::int64_t, std::deque<Observation>> history_;  ///< per feature id
  struct PixelObservation {
    std::size_t frame = 0;
    double t = 0;
    cv::Point2f pixel;
  };
  /// Per depthless feature id, its pixels over the window (far_object_min_depth > 0 only).
  std::unordered_map<std::int64_t, std::deque<PixelObservation>> pixelHistory_;
  /// What is kept of an object between frames (forgotten after kObjectMemoryS).
  struct ObjectMemory {
    bool dynamic = false;  ///< its last decision
    int moving_run = 0;    ///< measured frames in a row over the threshold, up to that one
    double decided_t = 0;  ///< when it was last decided (s)
  };
  std::map<int, ObjectMemory> objects_;                                ///< per object id
  std::map<int, AdaptiveRigidPointSet> sets_;                          ///< per object id
  std::map<std::int64_t, int> objectOf_;  ///< feature id -> object id, last frame
  std::unordered_set<std::int64_t> wasStatic_;  ///< features classified Static last frame
};

const char* toString(CameraMotionSource source);

}  // namespace dynslam::frontend
