#pragma once
// An appearance cue for the tracker (not in the method; KalmanBoxTrackerParams::appearance_*):
// a hue-saturation histogram of the object's torso. The method associates by depth IoU alone,
// which cannot tell apart two people who cross at similar depths, nor re-find a person after a
// hide long enough for the constant-velocity prediction to drift (people turn): on the
// simulator's indoor_people_high most identity breaks are exactly those. A colour histogram
// is the cheapest cue that separates people dressed differently (DeepSORT learns one from a
// CNN; that needs a second network on the CPU).
//
// Region: the box's torso (middle half of the width, 20-60 % of the height: no floor, little
// background, no legs that swing and no head that turns). Not restricted to the segmentation's
// mask: on indoor_people_high a person's descriptor one detector frame apart differed by 0.83
// or more in 10 % of frames with the mask (wrong or tiny masks), 0.21 without. Hue x saturation, 16
// x 4 bins, pixels too dark or too grey for a stable hue (V < 40 or S < 40 of 255) go to 4 extra
// grey-level bins, L1-normalised.
#include <dynslam/core/Frame.h>

#include <opencv2/core/mat.hpp>

namespace dynslam::tracking {

/// The descriptor (1 x kAppearanceBins CV_32F, sums to 1) of `box`'s torso in `bgr` (CV_8UC3);
/// empty when the region holds fewer than 50 pixels.
cv::Mat torsoHistogram(const cv::Mat& bgr, const cv::Rect2f& box);

/// The descriptor of frame.detections[detection] in frame.rgb.
cv::Mat observationAppearance(const core::Frame& frame, size_t detection);

/// Bhattacharyya distance of two descriptors, in [0, 1] (0 = identical); 1 when either is empty.
double appearanceDistance(const cv::Mat& a, const cv::Mat& b);

constexpr int kAppearanceBins = 16 * 4 + 4;

}  // namespace dynslam::tracking
