#include "dynslam/frontend/OcclusionEdge.h"

#include <algorithm>
#include <cmath>

namespace dynslam::frontend {
namespace {

/// The pixel's own valid reading (0: none, outside the image, or radius <= 0), and its
/// row / column.
float ownReading(const cv::Mat& depth, const cv::Point2f& pixel, int radius, int& row, int& col) {
  row = cvRound(pixel.y);
  col = cvRound(pixel.x);
  if (radius <= 0 || depth.empty() || row < 0 || col < 0 || row >= depth.rows || col >= depth.cols)
    return 0;
  const float z = depth.at<float>(row, col);
  return std::isfinite(z) && z > 0 ? z : 0;
}

/// Whether `test(reading, y, x)` holds for a reading of the window round (row, col).
template <class Test>
bool anyInWindow(const cv::Mat& depth, int row, int col, int radius, Test test) {
  for (int y = std::max(0, row - radius); y <= std::min(depth.rows - 1, row + radius); ++y) {
    const auto* d = depth.ptr<float>(y);
    for (int x = std::max(0, col - radius); x <= std::min(depth.cols - 1, col + radius); ++x)
      if (test(d[x], y, x)) return true;
  }
  return false;
}

float gapAt(float z, const OcclusionEdgeParams& params) {
  return float(std::max(params.min_gap_m, params.gap_ratio * z));
}

}  // namespace

bool behindOcclusionEdge(const cv::Mat& depth, const cv::Point2f& pixel,
                         const OcclusionEdgeParams& params, const cv::Mat& nearer) {
  int row = 0, col = 0;
  const float z = ownReading(depth, pixel, params.radius_px, row, col);
  if (!(z > 0)) return false;
  const float limit = z - gapAt(z, params);
  return anyInWindow(depth, row, col, params.radius_px, [&](float d, int y, int x) {
    // NaN fails both comparisons.
    return d > 0 && d < limit && (nearer.empty() || nearer.at<uint8_t>(y, x) != 0);
  });
}

bool nearDepthEdge(const cv::Mat& depth, const cv::Point2f& pixel,
                   const OcclusionEdgeParams& params) {
  int row = 0, col = 0;
  const float z = ownReading(depth, pixel, params.radius_px, row, col);
  if (!(z > 0)) return false;
  const float gap = gapAt(z, params);
  return anyInWindow(depth, row, col, params.radius_px, [&](float d, int, int) {
    return !(d > 0) || !std::isfinite(d) || std::abs(d - z) > gap;
  });
}

}  // namespace dynslam::frontend
