#pragma once
// An appearance cue for the tracker (not in the method; KalmanBoxTrackerParams::reid_*):
// hue-saturation histograms of the object's upper and lower body. The method associates by depth
// IoU alone, which cannot tell apart two people who cross at similar depths, nor re-find a person
// after a hide long enough for the constant-velocity prediction to drift (people turn): on the
// simulator's indoor_people_high most identity breaks are exactly those. A colour histogram
// is the cheapest cue that separates people dressed differently (DeepSORT learns one from a
// CNN; that needs a second network on the CPU).
//
// Regions: the upper body (15-55 % of the box's height) and the lower body (55-95 %), the middle
// 70 % of the width, one histogram each (a shirt and trousers tell people apart better together
// than a torso alone). Only pixels whose depth lies within kAppearanceDepthBand of the object's
// depth count, when both are known: the box of a person partly behind another holds the
// occluder's clothes, and the wall's colours beside a walker; the band leaves both out. Per
// part: hue x saturation, 16 x 4 bins; pixels too dark or too grey for a stable hue (V < 40 or
// S < 40 of 255) go to 4 extra grey-level bins; L1-normalised to 0.5 per part.
//
// How well it separates people (bench-tracking prints it), and the torso-only form it replaced:
// docs/notes/perception.md, 2026-11-28 (appearance).
#include <dynslam/core/Frame.h>
#include <dynslam/tracking/KalmanBoxTracker.h>

#include <opencv2/core/mat.hpp>

namespace dynslam::tracking {

/// The descriptor (1 x kAppearanceBins CV_32F, sums to 1) of the object in `box` of `bgr`
/// (CV_8UC3), counting the pixels of `depth` (CV_32FC1, m, the size of `bgr`) within the band of
/// `objectDepth` when both are given; empty when neither part holds 50 pixels that count.
cv::Mat bodyHistogram(const cv::Mat& bgr, const cv::Rect2f& box, const cv::Mat& depth = {},
                      double objectDepth = 0);

/// What the tracker observes of frame.detections[detection]: its box, category and model, the
/// object depth (ObjectDepth.h) and, when `withAppearance`, its descriptor in frame.rgb with
/// frame.depth and that depth (the depth is measured once for both).
BoxObservation observeDetection(const core::Frame& frame, size_t detection, bool withAppearance);

/// Bhattacharyya distance of two descriptors, in [0, 1] (0 = identical); 1 when either is empty.
double appearanceDistance(const cv::Mat& a, const cv::Mat& b);

constexpr int kPartBins = 16 * 4 + 4;
constexpr int kAppearanceBins = 2 * kPartBins;
constexpr double kAppearanceDepthBand = 0.4;  // m

}  // namespace dynslam::tracking
