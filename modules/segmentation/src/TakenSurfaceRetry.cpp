#include "ClusterChoice.h"
#include "dynslam/segmentation/DepthSampling.h"

#include <dynslam/core/Perception.h>

#include <opencv2/core.hpp>

namespace dynslam::segmentation {
namespace {

// retry_taken_surface: a mask keeping less than this share of its pixels after the overlap step,
// with another overlapping mask on the same body (d_t within kSameSurface of its own, or nearer
// by less than e / 2: the flank of the body in front, whose d_t is its front), lost its surface
// to it. The flank: a hidden person's mask often holds the side of the person in front, 0.1-0.2
// m behind its front. Measured: docs/notes/perception.md, 2026-11-28 (retry_taken_surface).
constexpr double kTakenFraction = 0.2;
constexpr double kSameSurface = 0.9;

}  // namespace

bool takenSurface(const std::vector<core::ObjectMask>& masks, size_t i, int before, double e) {
  const int now = cv::countNonZero(masks[i].mask);
  if (now == 0) return true;
  if (now >= kTakenFraction * before) return false;
  for (size_t j = 0; j < masks.size(); ++j) {
    if (j == i || !masks[j].valid || (masks[j].roi & masks[i].roi).area() <= 0) continue;
    const double di = masks[i].d_t, dj = masks[j].d_t;
    if (core::depthRatio(dj, di) >= kSameSurface || (dj < di && di - dj < e / 2)) return true;
  }
  return false;
}

bool clustersBehind(const cv::Mat& depth, const cv::Rect& roi, double surface, double e, int m,
                    double maxDepth, TwoMeansResult& out) {
  std::vector<float> behind;
  forEachGridPoint(depth, cv::Rect2d(roi), m, [&](cv::Point, float z) {
    if (z > surface + e / 2 && z <= maxDepth) behind.push_back(z);
  });
  if (behind.size() < 4) return false;
  const TwoMeansResult rest = twoMeans(behind);
  out.two_clusters = true;
  out.near_mean = surface;
  out.near_count = 0;
  out.far_count = int(behind.size());
  out.far_mean = twoSurfaces(rest, e) ? rest.near_mean : meanOfAll(rest);
  return true;
}

void DepthThresholdSegmenter::retryTakenSurfaces(const cv::Mat& depth,
                                                 const std::vector<core::Detection>& detections,
                                                 const std::vector<BoxClusters>& boxes,
                                                 const std::vector<ClusterChoice>& chosen,
                                                 std::vector<core::ObjectMask>& masks) const {
  std::vector<int> cut(masks.size(), 0);  // each mask's pixels before the overlap step
  for (size_t i = 0; i < masks.size(); ++i)
    if (masks[i].valid && !masks[i].mask.empty()) cut[i] = cv::countNonZero(masks[i].mask);
  resolveOverlaps(masks, depth);
  // A mask whose surface the overlap step gave to another object was cut on that object's
  // surface: two detections are not one surface, so it is cut again on what its box shows
  // behind that surface, and the overlaps are resolved again.
  bool retried = false;
  for (size_t i = 0; i < masks.size(); ++i) {
    const double e = boxes[i].e;
    if (!masks[i].valid || !takenSurface(masks, i, cut[i], e)) continue;
    const TwoMeansResult& c = chosen[i].clusters;
    const double surface = chosen[i].nearIsObject ? c.near_mean : c.far_mean;
    TwoMeansResult behind;
    if (clustersBehind(depth, boxes[i].roi, surface, e, params_.m, boxes[i].maxDepth, behind)) {
      masks[i] = segmentWith(depth, detections[i], int(i), behind, false, boxes[i].maxDepth);
      retried = true;
    } else if (cv::countNonZero(masks[i].mask) == 0 && twoSurfaces(c, e)) {
      // nothing behind: the other cluster
      masks[i] =
          segmentWith(depth, detections[i], int(i), c, !chosen[i].nearIsObject, boxes[i].maxDepth);
      retried = true;
    }
  }
  if (retried) resolveOverlaps(masks, depth);
}

}  // namespace dynslam::segmentation
