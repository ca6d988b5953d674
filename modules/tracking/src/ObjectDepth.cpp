#include "dynslam/tracking/ObjectDepth.h"

#include <dynslam/core/Median.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace dynslam::tracking {

double medianDepthInCentralHalf(const cv::Mat& depth, const cv::Rect2f& box) {
  if (depth.empty() || depth.type() != CV_32FC1) return 0.0;
  const cv::Rect2f half(box.x + 0.25f * box.width, box.y + 0.25f * box.height, 0.5f * box.width,
                        0.5f * box.height);
  const cv::Rect roi =
      cv::Rect(cvFloor(half.x), cvFloor(half.y), cvCeil(half.width), cvCeil(half.height)) &
      cv::Rect(0, 0, depth.cols, depth.rows);
  std::vector<float> valid;
  valid.reserve(roi.area());
  for (int y = roi.y; y < roi.y + roi.height; ++y) {
    const float* row = depth.ptr<float>(y);
    for (int x = roi.x; x < roi.x + roi.width; ++x)
      if (row[x] > 0 && std::isfinite(row[x])) valid.push_back(row[x]);
  }
  return core::upperMedianInPlace(valid);
}

namespace {

// The valid mask the segmentation made for frame.detections[detection]; nullptr when none.
const core::ObjectMask* validMaskOf(const core::Frame& frame, size_t detection) {
  for (const auto& mask : frame.object_masks)
    if (mask.detection == int(detection) && mask.valid) return &mask;
  return nullptr;
}

}  // namespace

double measuredObjectDepth(const core::Frame& frame, size_t detection) {
  if (const auto* mask = validMaskOf(frame, detection); mask && mask->d_t > 0) return mask->d_t;
  if (detection >= frame.detections.size()) return 0.0;
  return medianDepthInCentralHalf(frame.depth, frame.detections[detection].box);
}

double alternativeObjectDepth(const core::Frame& frame, size_t detection) {
  const auto* mask = validMaskOf(frame, detection);
  return mask ? mask->d_alt : 0.0;
}

}  // namespace dynslam::tracking
