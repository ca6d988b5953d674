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
  return forEachGridPoint(depth, region, count, [&](cv::Point, float z) { out.push_back(z); });
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
