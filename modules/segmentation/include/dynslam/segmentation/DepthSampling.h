#pragma once
// The depth samples the segmentation works from (method.md section 1, steps 2 and 5): an even
// grid of points over a region of the depth image, and the three-sigma-filtered mean.
#include <opencv2/core/mat.hpp>
#include <opencv2/core/types.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace dynslam::segmentation {

/// Number of grid columns and rows for about `count` points evenly spaced over a region of
/// `width` x `height` pixels: the spacing is the same along both axes (a tall person box gets
/// more rows than columns), so cols * rows is `count` up to rounding (64 over a 1:2.5 box:
/// 5 x 13).
cv::Size gridShape(int count, double width, double height);

/// Calls `visit(cv::Point, float depth)` at the valid (> 0, finite) depths of `depth` (CV_32FC1,
/// metres) at the centres of the cells of a gridShape(count, ...) grid over `region` (pixel x
/// spanning [x, x + 1); points past the image's edge are clamped onto it); returns how many
/// points the grid had.
template <typename Visit>
int forEachGridPoint(const cv::Mat& depth, const cv::Rect2d& region, int count, Visit visit) {
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
      if (z > 0 && std::isfinite(z)) visit(cv::Point(u, v), z);
    }
  }
  return grid.area();
}

/// Samples the depth image (CV_32FC1, metres, 0 = invalid) at the centres of the cells of a
/// gridShape(count, ...) grid over `region` (pixel coordinates, pixel x spanning [x, x + 1);
/// it must lie inside the image). Appends the valid (> 0, finite) depths to `out` and
/// returns how many points the grid had.
int sampleGrid(const cv::Mat& depth, const cv::Rect2d& region, int count, std::vector<float>& out);

/// Mean of `values` after dropping those farther than three standard deviations (population)
/// from the mean of all of them; one pass. 0 for an empty input.
double threeSigmaMean(const std::vector<float>& values);

}  // namespace dynslam::segmentation
