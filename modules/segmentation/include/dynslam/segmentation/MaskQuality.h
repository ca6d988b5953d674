#pragma once
// Scores of a segmentation against per-pixel ground truth (the simulator's instance labels),
// shared by the segmentation tests and bench-segmentation.
#include <dynslam/core/Perception.h>

#include <opencv2/core/mat.hpp>

#include <cstdint>

namespace dynslam::segmentation {

/// Intersection over union of `mask` (placed at its roi) and the whole-image CV_8UC1 `truth`
/// (non-zero = object). An invalid or empty mask scores 0 (1 if the truth is empty too).
double maskIoU(const core::ObjectMask& mask, const cv::Mat& truth);

/// The object's true depth as the camera sees it: the median of the valid depths (CV_32FC1,
/// m) of the pixels labelled `id` in `label` (CV_16UC1); 0 when it has none. The median of
/// noisy depths is unbiased for a surface and ignores the odd pixel at a depth edge.
double visibleMedianDepth(const cv::Mat& depth, const cv::Mat& label, uint16_t id);

}  // namespace dynslam::segmentation
