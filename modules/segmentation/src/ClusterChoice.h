#pragma once
// Which of a box's two depth clusters is its object (method.md section 1, step 3, and the
// variants that are not the method): shared by DepthThresholdSegmenter.cpp (the segmentation),
// OccluderAwareChoice.cpp (the choice with the other detections in view) and
// TakenSurfaceRetry.cpp (retry_taken_surface). Internal to the module.
#include "dynslam/segmentation/DepthThresholdSegmenter.h"

#include <opencv2/core/types.hpp>

#include <vector>

namespace dynslam::segmentation {

/// The candidate box M of a box: the same centre, half its width and height (step 1).
inline cv::Rect2d candidateBox(const cv::Rect& roi) {
  const cv::Rect2d box(roi);
  return {box.x + box.width / 4, box.y + box.height / 4, box.width / 2, box.height / 2};
}

/// Two 2-means clusters more than e apart are two surfaces (an object and what lies behind or
/// before it), not the spread of one.
inline bool twoSurfaces(const TwoMeansResult& c, double e) {
  return c.two_clusters && c.far_mean - c.near_mean > e;
}

/// The mean of all the values a 2-means split.
inline double meanOfAll(const TwoMeansResult& c) {
  return (c.near_mean * c.near_count + c.far_mean * c.far_count) /
         double(c.near_count + c.far_count);
}

/// The cluster choice a depth expected for the object makes: near when its mean is nearer that
/// depth in ratio. `expected` <= 0 or one cluster: `rule`, the choice without it.
bool nearIsExpected(const TwoMeansResult& c, double expected, bool rule);

/// expected_depth_band: the clusters with the object's replaced by the depths within `band` of
/// `expected` among m grid samples over the whole box `roi` (the hidden person shows above or
/// beside its occluder, not in the candidate box it covers) when neither cluster of `c` is
/// within 15 % of it: a partly hidden person's own surface is then a third depth, between an
/// occluder and the wall or behind two occluders, that 2-means merged into another cluster.
/// False, and `c` and `nearIsObject` untouched, otherwise (or with fewer than 3 such samples).
/// The nearest of `c`'s clusters stays beside the object: as its occluder when in front of it.
bool objectAtExpected(const cv::Mat& depth, const cv::Rect& roi, int m, double expected,
                      double band, TwoMeansResult& c, bool& nearIsObject);

/// One detection's box as the occluder-aware choice sees it (steps 1-3 done).
struct BoxClusters {
  cv::Rect roi;         ///< the box in whole pixels, clipped to the image
  double e = 0;         ///< the detection's depth margin
  double maxDepth = 0;  ///< max_height_person's bound (infinity: none)
  bool ok = false;      ///< enough depth in the candidate box for the clusters below
  TwoMeansResult clusters;
  std::vector<float> samples;  ///< the candidate box's valid samples up to maxDepth, sorted
};

/// The clusters a mask is cut on, and whether the near one is the object.
struct ClusterChoice {
  TwoMeansResult clusters;
  bool nearIsObject = false;
};

/// OccluderAware for box i of `boxes` (ok), with the others in view: when its two clusters are
/// more than e apart, the near one is an occluder only if another detection (or, with
/// joint_occluders, several together) is seen standing in front of it; the object is then
/// sought behind that surface. Otherwise the near cluster is the object, unless `expected`
/// (> 0: a track's depth) says the far one is; then expected_depth_band.
ClusterChoice chooseWithOthersInView(const cv::Mat& depth, const std::vector<BoxClusters>& boxes,
                                     size_t i, double expected, const DepthThresholdParams& p);

/// retry_taken_surface: did mask i (`before` pixels before the overlap step) lose its surface
/// to another mask? When the step left it empty, or with under a fifth of its pixels while
/// another overlapping mask lies on the same body (e: mask i's margin).
bool takenSurface(const std::vector<core::ObjectMask>& masks, size_t i, int before, double e);

/// retry_taken_surface: the clusters of an object hidden behind another's `surface`: m grid
/// points over its whole box `roi` more than e / 2 behind the surface and not beyond
/// `maxDepth`, of whose 2-means the nearer cluster when more than e apart (the object before the
/// wall), else their mean, is the object (far cluster) and the surface its occluder (near
/// cluster). False with fewer than 4 such points.
bool clustersBehind(const cv::Mat& depth, const cv::Rect& roi, double surface, double e, int m,
                    double maxDepth, TwoMeansResult& out);

}  // namespace dynslam::segmentation
