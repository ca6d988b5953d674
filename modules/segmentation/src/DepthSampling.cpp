#include "dynslam/segmentation/DepthSampling.h"

#include <algorithm>
#include <cmath>

namespace dynslam::segmentation {

cv::Size gridShape(int count, double width, double height) {
  if (count <= 0) return {0, 0};
  if (width <= 0 || height <= 0) return {1, 1};
  const int cols =
      std::clamp(static_cast<int>(std::lround(std::sqrt(count * width / height))), 1, count);
  const int rows = std::max(1, static_cast<int>(std::lround(double(count) / cols)));
  return {cols, rows};
}

int sampleGrid(const cv::Mat& depth, const cv::Rect2d& region, int count, std::vector<float>& out) {
  const cv::Size grid = gridShape(count, region.width, region.height);
  if (grid.area() == 0) return 0;
  const double stepX = region.width / grid.width, stepY = region.height / grid.height;
  for (int j = 0; j < grid.height; ++j) {
    // Clamped so that rounding at the region's far edge can never leave the image.
    const int v =
        std::clamp(static_cast<int>(std::floor(region.y + (j + 0.5) * stepY)), 0, depth.rows - 1);
    const float* row = depth.ptr<float>(v);
    for (int i = 0; i < grid.width; ++i) {
      const int u =
          std::clamp(static_cast<int>(std::floor(region.x + (i + 0.5) * stepX)), 0, depth.cols - 1);
      const float z = row[u];
      if (z > 0 && std::isfinite(z)) out.push_back(z);
    }
  }
  return grid.area();
}

double threeSigmaMean(const std::vector<float>& values) {
  if (values.empty()) return 0;
  double sum = 0, sumSq = 0;
  for (float v : values) {
    sum += v;
    sumSq += double(v) * v;
  }
  const double n = static_cast<double>(values.size());
  const double mean = sum / n;
  const double sigma = std::sqrt(std::max(0.0, sumSq / n - mean * mean));
  double keptSum = 0;
  int kept = 0;
  for (float v : values)
    if (std::abs(v - mean) <= 3 * sigma) {
      keptSum += v;
      ++kept;
    }
  return kept ? keptSum / kept : mean;
}

}  // namespace dynslam::segmentation
