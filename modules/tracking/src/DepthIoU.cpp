#include "dynslam/tracking/DepthIoU.h"

#include <dynslam/core/Perception.h>

namespace dynslam::tracking {

double boxIoU(const cv::Rect2f& a, const cv::Rect2f& b) {
  const double intersection = (a & b).area();
  const double unionArea = double(a.area()) + b.area() - intersection;
  return unionArea > 0 ? intersection / unionArea : 0.0;
}

double depthIoU(const cv::Rect2f& a, double depthA, const cv::Rect2f& b, double depthB) {
  const double iou = boxIoU(a, b);
  if (!(depthA > 0 && depthB > 0)) return iou;
  return iou * core::depthRatio(depthA, depthB);
}

}  // namespace dynslam::tracking
