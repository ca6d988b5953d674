#pragma once
// Box overlap with depth (method.md section 2): rho = IoU(A, B) * min(d_A, d_B) / max(d_A, d_B),
// so two boxes that overlap in the image but lie at different depths (a person passing in front
// of another) score low.
#include <opencv2/core/types.hpp>

namespace dynslam::tracking {

/// Intersection over union of two boxes; 0 when either is empty.
double boxIoU(const cv::Rect2f& a, const cv::Rect2f& b);

/// IoU(a, b) * min(depthA, depthB) / max(depthA, depthB). A depth <= 0 means "unknown": the
/// depth factor is then 1 (plain IoU), so boxes without depth can still be tracked.
double depthIoU(const cv::Rect2f& a, double depthA, const cv::Rect2f& b, double depthB);

}  // namespace dynslam::tracking
