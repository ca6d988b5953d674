#pragma once
// The object depth d a detection gives the tracker: the segmentation's d_t (method.md section
// 1) when the frame has a valid mask for it, else a fallback for pipelines without the
// segmentation stage: the median valid depth in the box's central half (the candidate box M of
// section 1: same centre, half the width and height), where the object itself is most likely
// seen. The median rather than the mean so that a few background or occluder pixels inside M
// do not pull it; it is still wrong when an occluder covers more than half of M, which is what
// the segmentation's two-cluster k-means is for.
#include <dynslam/core/Frame.h>

namespace dynslam::tracking {

/// Median of the valid (> 0, finite) depths of `depth` (CV_32FC1, m) inside the central half of
/// `box`, clipped to the image; 0 when there is none (or `depth` is empty).
double medianDepthInCentralHalf(const cv::Mat& depth, const cv::Rect2f& box);

/// d for frame.detections[detection]: the d_t of a valid frame.object_masks entry for it, else
/// medianDepthInCentralHalf(frame.depth, box); 0 (unknown) when neither gives one.
double measuredObjectDepth(const core::Frame& frame, size_t detection);

/// The d_alt of a valid frame.object_masks entry for frame.detections[detection]; 0 when none.
double alternativeObjectDepth(const core::Frame& frame, size_t detection);

}  // namespace dynslam::tracking
