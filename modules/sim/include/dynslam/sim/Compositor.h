#pragma once
// Rendered movers inserted into a real RGB-D frame with occlusion against the real depth.
#include <dynslam/sim/Rasterizer.h>
#include <dynslam/sim/SensorNoise.h>

#include <opencv2/core/mat.hpp>

#include <random>

namespace dynslam::sim {

/// `out` = the real frame, except where `rendered` has a surface (depth > 0) nearer than the
/// real depth or the real depth is invalid (0): there the rendered colour, depth and label win.
/// Every other pixel keeps the real colour and depth exactly, with label 0. Returns the mask of
/// the pixels that won (CV_8UC1, 255). Throws std::invalid_argument when the sizes or types
/// differ (rgb CV_8UC3, depth CV_32FC1, label CV_16UC1).
cv::Mat compositeOverReal(const RenderOutput& rendered, const cv::Mat& real_rgb,
                          const cv::Mat& real_depth, RenderOutput& out);

/// applyRgbdNoise for the masked pixels only: the real pixels already carry the real sensor's
/// noise. Edge holes are decided on the whole depth image, so a real object in front of an
/// inserted one leaves a hole on the inserted side; the other pixels stay byte-equal. Draws
/// from `rng` exactly as applyRgbdNoise does, mask or no mask.
void applyRgbdNoiseMasked(RenderOutput& frame, const cv::Mat& mask, const RgbdNoiseOptions& options,
                          std::mt19937_64& rng);

}  // namespace dynslam::sim
