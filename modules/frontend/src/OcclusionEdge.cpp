#include "dynslam/frontend/OcclusionEdge.h"

#include <algorithm>
#include <cmath>

namespace dynslam::frontend {

bool behindOcclusionEdge(const cv::Mat& depth, const cv::Point2f& pixel,
                         const OcclusionEdgeParams& params, const cv::Mat& nearer) {
  const int r = params.radius_px;
  const int row = cvRound(pixel.y), col = cvRound(pixel.x);
  if (r <= 0 || depth.empty() || row < 0 || col < 0 || row >= depth.rows || col >= depth.cols)
    return false;
  const float z = depth.at<float>(row, col);
  if (!(std::isfinite(z) && z > 0)) return false;
  const float limit = z - float(std::max(params.min_gap_m, params.gap_ratio * z));
  for (int y = std::max(0, row - r); y <= std::min(depth.rows - 1, row + r); ++y) {
    const auto* d = depth.ptr<float>(y);
    const auto* m = nearer.empty() ? nullptr : nearer.ptr<uint8_t>(y);
    for (int x = std::max(0, col - r); x <= std::min(depth.cols - 1, col + r); ++x)
      if (d[x] > 0 && d[x] < limit && (!m || m[x])) return true;  // NaN fails both comparisons
  }
  return false;
}

bool nearDepthEdge(const cv::Mat& depth, const cv::Point2f& pixel,
                   const OcclusionEdgeParams& params) {
  const int r = params.radius_px;
  const int row = cvRound(pixel.y), col = cvRound(pixel.x);
  if (r <= 0 || depth.empty() || row < 0 || col < 0 || row >= depth.rows || col >= depth.cols)
    return false;
  const float z = depth.at<float>(row, col);
  if (!(std::isfinite(z) && z > 0)) return false;
  const float gap = float(std::max(params.min_gap_m, params.gap_ratio * z));
  for (int y = std::max(0, row - r); y <= std::min(depth.rows - 1, row + r); ++y) {
    const auto* d = depth.ptr<float>(y);
    for (int x = std::max(0, col - r); x <= std::min(depth.cols - 1, col + r); ++x)
      if (!(d[x] > 0) || !std::isfinite(d[x]) || std::abs(d[x] - z) > gap) return true;
  }
  return false;
}

}  // namespace dynslam::frontend
