#pragma once
// What a real RGB-D sensor does to a perfect rendering: colour noise, depth noise growing with
// z^2, no depth beyond the maximum range, holes along depth edges. Two depth models:
//   structured_light (Kinect-like): sigma(z) = depth_sigma_min + depth_sigma_z2 z^2, holes of
//     edge_hole_width px on the far side of every depth step;
//   stereo (RealSense D4xx-like, the depth imager on the left): sigma(z) = depth_sigma_min +
//     z^2 disparity_sigma / (f b), and besides the edge holes the band the right imager cannot
//     see: left of every near object, f b (1/z_near - 1/z_far) px of the background.
#include <dynslam/sim/Rasterizer.h>

#include <random>

namespace dynslam::sim {

enum class DepthModel { StructuredLight, Stereo };

struct RgbdNoiseOptions {
  double colour_sigma = 3.0;       ///< grey levels, per channel
  double depth_sigma_z2 = 0.0015;  ///< m^-1: sigma(z) = depth_sigma_z2 * z^2 (+ depth_sigma_min)
  double depth_sigma_min = 0.001;  ///< m
  double max_range = 6.0;          ///< m; farther depth becomes 0 (invalid)
  double min_range = 0.3;          ///< m; nearer depth becomes 0 (invalid)
  double edge_jump = 0.10;         ///< m; neighbours differing more make a hole
  int edge_hole_width = 1;         ///< pixels removed on the far side of such an edge
  DepthModel depth_model = DepthModel::StructuredLight;
  double stereo_baseline = 0.05;  ///< m (D435: 50 mm)
  double disparity_sigma = 0.08;  ///< px, the stereo matcher's subpixel noise
  double focal_px = 525;          ///< px; the camera's fx (ScenarioOptions sets it)
};

/// Applies the noise model in place (rgb and depth; labels are untouched: they are the truth).
/// Range cuts and edge holes are decided on the noise-free depth, then the surviving pixels
/// get z + sigma(z) n with n ~ N(0, 1); colour gets independent N(0, colour_sigma^2) per
/// channel, rounded and saturated. The normals come from fixed tables of normal quantiles
/// (65536 for depth, 4096 for colour) indexed by a generator seeded from `rng` (two draws per
/// call), so the same rng state gives the same images. An empty rgb or depth image is left alone;
/// throws std::invalid_argument for an image that is not CV_8UC3 / CV_32FC1.
void applyRgbdNoise(RenderOutput& frame, const RgbdNoiseOptions& options, std::mt19937_64& rng);

}  // namespace dynslam::sim
