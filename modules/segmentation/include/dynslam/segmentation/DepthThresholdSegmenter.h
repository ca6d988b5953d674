#pragma once
// Depth-threshold instance segmentation of detector boxes (method.md section 1, paper 4.1):
// the object's depth d_t and an occluder's depth d_o from 2-means over an even grid of depth
// samples in the box's central half, the background depth d_b from the upper half of the box,
// thresholds T_min / T_max between them, and the mask = pixels of the box with depth in
// [T_min, T_max]. Overlapping boxes are segmented each with their own thresholds; a pixel
// both claim goes to one of them (mutual occlusion; the method: the nearer). Which cluster is
// the object, which object takes a shared pixel and what d_t reports have variants besides the
// method's (the enums below); the defaults are the shipped ones, methodParams() the method's.
// MRPT-free; the stage wraps it.
#include <dynslam/core/Perception.h>
#include <dynslam/segmentation/TwoMeans.h>

#include <opencv2/core/mat.hpp>

#include <vector>

namespace dynslam::segmentation {

/// Which 2-means cluster of the candidate box's depths is the object (step 3).
enum class ObjectCluster {
  Far,     ///< method.md: the far cluster (the near one is an occluder)
  Larger,  ///< the cluster with more samples (the far one on a tie); not the method: for boxes
           ///< whose centre shows background
  /// NOT the method: when the two clusters are more than e apart, the near one is an occluder
  /// only if another detection claims it (its box overlaps the candidate box, its bottom edge
  /// is lower in the image, i.e. it stands nearer on the floor, and one of its own clusters is
  /// within e of the near depth); otherwise the near cluster is the object and the far one is
  /// background seen through gaps (between a walker's legs, beside the arms).
  OccluderAware
};

/// Which object a pixel goes to when several masks hold it (step 9).
enum class OverlapRule {
  Nearer,  ///< method.md: the nearer object (smallest d_t)
  /// NOT the method: the object whose d_t is closest to the pixel's depth (the nearer one on a
  /// tie). With e = 0.5 m the near person's range [T_min, T_max] often holds a person walking
  /// less than e behind; "nearer" then gives the near person all of the other's pixels in
  /// the overlap. Measured gain: docs/notes/perception.md, 2026-11-28 (overlap_rule).
  ClosestDepth,
  /// NOT the method: a shared pixel goes to the object whose surface reaches it, searching
  /// breadth-first from each mask's own pixels across neighbours less than 5 cm apart in depth
  /// (resolveByConnectivity); pixels no surface reaches fall back to closest_depth. A person's
  /// body slants and bends (turned shoulders, swinging arms, a leg stepping back), so its
  /// pixels are often nearer another person's d_t than its own; a surface is continuous where
  /// two people are not. Measured gain and cost: docs/notes/perception.md, 2026-11-28
  /// (overlap_rule).
  Connected
};

/// What d_t reports once the masks are final.
enum class ObjectDepth {
  ClusterMean,  ///< method.md step 3: the mean of the object's 2-means cluster
  /// NOT the method: the median depth of the object's final mask (after step 9), or the
  /// cluster mean when the mask is empty. The cluster mean is the mean of 10-40 grid samples
  /// of the candidate box, which catch the floor, an arm swung forward or a neighbour's edge;
  /// the mask holds the whole visible surface. Measured gain: docs/notes/perception.md,
  /// 2026-11-28 (object_depth).
  MaskMedian
};

/// The segmenter's settings; the defaults are the shipped, best-measured ones (those of
/// params/sim_vio.ini's [Segmentation]), methodParams() the method as method.md states it.
/// Keys, ranges, meanings: SegmentationOptions::describe() in SegmentationStage.cpp;
/// docs/parameters.md.
struct DepthThresholdParams {
  int m = 64;
  int n = 64;
  double e_person = 0.5;  ///< m
  double e_car = 3.0;     ///< m
  double min_valid_fraction = 0.25;
  double max_height_person = 2.2;  ///< m; 0 = off
  double expected_depth_band = 0;
  bool retry_taken_surface = false;
  bool joint_occluders = true;
  ObjectCluster object_cluster = ObjectCluster::OccluderAware;
  OverlapRule overlap_rule = OverlapRule::Connected;
  ObjectDepth object_depth = ObjectDepth::MaskMedian;
};

/// method.md section 1 as written: the far cluster is the object, the nearer object takes a
/// shared pixel, d_t is the cluster's mean, no size bound and no joint occluders.
DepthThresholdParams methodParams();

struct BoxClusters;    // src/ClusterChoice.h
struct ClusterChoice;  // src/ClusterChoice.h

class DepthThresholdSegmenter {
 public:
  explicit DepthThresholdSegmenter(DepthThresholdParams params = {});

  const DepthThresholdParams& params() const { return params_; }

  /// The margin e used for a detection: e_person for people and other non-rigid classes,
  /// e_car for cars and other rigid classes.
  double marginFor(const core::Detection& detection) const;

  /// The farthest the detection's object can be by max_height_person and the box's height;
  /// infinity when that is off, for other categories than person, or with fy <= 0. A box h
  /// pixels tall holds nothing of a person beyond max_height_person * fy / h (a taller person,
  /// or one farther away, would have a smaller box), so candidate samples beyond that depth are
  /// background seen past the person: they take no part in the 2-means, and the mask stops
  /// there. A box cut by an occluder or the image's edge is smaller than the person: the bound
  /// only loosens. People only: a car seen along its length reaches far beyond its nearest
  /// point, which is what its box height measures (measured: docs/notes/perception.md,
  /// 2026-11-28, max_height_person).
  double maxDepthFor(const core::Detection& detection, double fy) const;

  /// Steps 1-8 for one box, without mutual occlusion. `depth`: CV_32FC1 metres, 0 = invalid
  /// (std::invalid_argument otherwise). The box is rounded to whole pixels and clipped to the
  /// image first (ObjectMask::roi); an empty roi or too few valid depths in the candidate box
  /// give valid = false with an empty mask. `expectedDepth` > 0 and `fy`: as in segment().
  core::ObjectMask segmentOne(const cv::Mat& depth, const core::Detection& detection,
                              int detectionIndex, double expectedDepth = 0, double fy = 0) const;

  /// One ObjectMask per detection, same order, mutual occlusion resolved (and, with
  /// OccluderAware, the object cluster chosen with the other detections in view).
  /// `expectedDepth` (empty, or one per detection; <= 0: none), not the method: where given,
  /// of a box's two clusters the one nearer (in ratio) that depth is the object, whatever the
  /// rule above says, unless OccluderAware saw another detection standing in front of it (a
  /// track's depth: SegmentationStage's boxes = tracked_detections).
  /// `fy`: the camera's vertical focal length in pixels, for max_height_person (0: no bound).
  std::vector<core::ObjectMask> segment(const cv::Mat& depth,
                                        const std::vector<core::Detection>& detections,
                                        const std::vector<double>& expectedDepth = {},
                                        double fy = 0) const;

 private:
  /// Steps 1-3 for one box: the 2-means of its candidate box, or nothing without enough depth.
  /// `samples`: the valid depth samples up to `maxDepth` (all of them when fewer than two
  /// are), sorted.
  bool candidateClusters(const cv::Mat& depth, const cv::Rect& roi, double maxDepth,
                         TwoMeansResult& out, std::vector<float>& samples) const;
  /// Steps 4-8 with the object's cluster given; the mask ends at `maxDepth`.
  core::ObjectMask segmentWith(const cv::Mat& depth, const core::Detection& detection,
                               int detectionIndex, const TwoMeansResult& clusters,
                               bool objectIsNear, double maxDepth) const;

  /// OccluderAware, steps 1-3 for every box (their margins and max_height_person's bounds too).
  std::vector<BoxClusters> clusterBoxes(const cv::Mat& depth,
                                        const std::vector<core::Detection>& detections,
                                        double fy) const;
  /// Step 9 by params_.overlap_rule; then, with object_depth = mask_median, each d_t from its
  /// final mask.
  void resolveOverlaps(std::vector<core::ObjectMask>& masks, const cv::Mat& depth) const;
  /// retry_taken_surface: step 9; then each mask the step left without its surface
  /// (takenSurface) is cut again behind the surface it was cut on (clustersBehind; with nothing
  /// there, an empty mask takes its other cluster when more than e away), and step 9 runs again.
  /// `chosen`: the clusters each mask of `masks` was cut on.
  void retryTakenSurfaces(const cv::Mat& depth, const std::vector<core::Detection>& detections,
                          const std::vector<BoxClusters>& boxes,
                          const std::vector<ClusterChoice>& chosen,
                          std::vector<core::ObjectMask>& masks) const;

  DepthThresholdParams params_;
};

/// Step 9: where valid masks overlap, a pixel set in several of them stays only in the one
/// with the smallest d_t (the nearer object; equal d_t: the earlier mask).
void resolveMutualOcclusion(std::vector<core::ObjectMask>& masks);

/// Step 9 with OverlapRule::ClosestDepth: a pixel set in several valid masks stays only in the
/// one whose d_t is closest to its depth in `depth` (the smaller d_t on a tie).
void resolveByClosestDepth(std::vector<core::ObjectMask>& masks, const cv::Mat& depth);

/// Step 9 with OverlapRule::Connected (see there): only the overlaps' bounding rectangle is
/// searched; masks past the 64th keep their pixels.
void resolveByConnectivity(std::vector<core::ObjectMask>& masks, const cv::Mat& depth);

/// The median depth of the mask's pixels with valid depth, sampling every `stride`-th row and
/// column (a person close up holds tens of thousands of pixels); 0 for an empty or invalid mask.
double maskMedianDepth(const core::ObjectMask& mask, const cv::Mat& depth, int stride = 2);

/// The detection box in whole pixels (edges rounded), clipped to an image of `size`.
cv::Rect pixelRoi(const cv::Rect2f& box, cv::Size size);

}  // namespace dynslam::segmentation
