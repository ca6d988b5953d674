#pragma once
// K-means with K = 2 on scalars (method.md section 1, step 3), solved exactly.
//
// In one dimension the optimal 2-means clusters are contiguous in sorted order, so sorting the
// values and trying every split point finds the global minimum of the within-cluster sum of
// squares in O(m log m). cv::kmeans solves the same objective iteratively from random centres
// (cv::theRNG): it can stop in a local minimum and its result depends on the RNG state, which
// a segmentation that must give the same masks run after run (and in tests) cannot accept.
#include <vector>

namespace dynslam::segmentation {

struct TwoMeansResult {
  double near_mean = 0, far_mean = 0;  ///< means of the smaller-valued and larger-valued clusters
  int near_count = 0, far_count = 0;
  /// False when every value is the same (or fewer than two values): no split exists; then
  /// far_mean holds the mean of all values and the near cluster is empty (near_count = 0).
  bool two_clusters = false;
};

/// Exact 2-means of `values` (any order; the vector is sorted in place). Ties between equally
/// good splits go to the first (nearest-valued) split, so the result is deterministic. An empty
/// input gives all zeros.
TwoMeansResult twoMeans(std::vector<float>& values);

}  // namespace dynslam::segmentation
