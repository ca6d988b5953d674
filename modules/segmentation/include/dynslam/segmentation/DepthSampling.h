#pragma once
// The depth samples the segmentation works from (method.md section 1, steps 2 and 5): an even
// grid of points over a region of the depth image, and the three-sigma-filtered mean.
#include <opencv2/core/mat.hpp>
#include <opencv2/core/types.hpp>

#include <vector>

namespace dynslam::segmentation {

/// Number of grid columns and rows for about `count` points evenly spaced over a region of
/// `width` x `height` pixels: the spacing is the same along both axes (a tall person box gets
/// more rows than columns), so cols * rows is `count` up to rounding (64 over a 1:2.5 box:
/// 5 x 13).
cv::Size gridShape(int count, double width, double height);

/// Samples the depth image (CV_32FC1, metres, 0 = invalid) at the centres of the cells of a
/// gridShape(count, ...) grid over `region` (pixel coordinates, pixel x spanning [x, x + 1);
/// it must lie inside the image). Appends the valid (> 0, finite) depths to `out` and
/// returns how many points the grid had.
int sampleGrid(const cv::Mat& depth, const cv::Rect2d& region, int count, std::vector<float>& out);

/// Mean of `values` after dropping those farther than three standard deviations (population)
/// from the mean of all of them; one pass. 0 for an empty input.
double threeSigmaMean(const std::vector<float>& values);

}  // namespace dynslam::segmentation
