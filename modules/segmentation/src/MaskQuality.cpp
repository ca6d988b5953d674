#include "dynslam/segmentation/MaskQuality.h"

#include <dynslam/core/Median.h>
#include <opencv2/core.hpp>

#include <algorithm>
#include <vector>

namespace dynslam::segmentation {

double maskIoU(const core::ObjectMask& mask, const cv::Mat& truth) {
  const int truthArea = cv::countNonZero(truth);
  if (!mask.valid || mask.mask.empty()) return truthArea == 0 ? 1.0 : 0.0;
  const int maskArea = cv::countNonZero(mask.mask);
  cv::Mat both;
  cv::bitwise_and(mask.mask, truth(mask.roi), both);
  const int inter = cv::countNonZero(both);
  const int uni = maskArea + truthArea - inter;
  return uni == 0 ? 1.0 : double(inter) / uni;
}

double visibleMedianDepth(const cv::Mat& depth, const cv::Mat& label, uint16_t id) {
  std::vector<float> z;
  for (int v = 0; v < label.rows; ++v) {
    const auto* l = label.ptr<uint16_t>(v);
    const auto* d = depth.ptr<float>(v);
    for (int u = 0; u < label.cols; ++u)
      if (l[u] == id && d[u] > 0) z.push_back(d[u]);
  }
  return core::upperMedianInPlace(z);
}

}  // namespace dynslam::segmentation
