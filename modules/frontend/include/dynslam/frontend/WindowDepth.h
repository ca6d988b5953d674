#pragma once
// A feature's depth as the median of the readings around its pixel that lie on its own surface
// (DynamicClassifierParams::depth_window): with independent per-pixel noise, the median of the
// 25 readings of a 5x5 window has about a quarter of one reading's noise.
#include <opencv2/core/mat.hpp>
#include <opencv2/core/types.hpp>

#include <vector>

namespace dynslam::frontend {

/// The median depth (m) of the valid readings of `depth` (CV_32FC1, 0 = none) within `half` px
/// of `pixel` that lie on the surface of the pixel's own reading (of the window's median when
/// the pixel has none): within the largest of 5 cm, 2 % and 3 sigma of the difference of two
/// readings, sigma = sigmaZ2 z^2 (the depth noise model; 0: no noise term). 0 when no reading
/// is valid. `buf` is scratch space.
///
/// The noise term matters beyond about 5 m: with 2 % alone the band centred on the pixel's own
/// noisy reading keeps mostly the window's readings on that side of the surface, and the median
/// keeps about half of that reading's error instead of a quarter. Measured:
/// docs/notes/frontend.md, 2026-11-28 (front-end settings' history).
float windowDepth(const cv::Mat& depth, const cv::Point2f& pixel, int half, double sigmaZ2,
                  std::vector<double>& buf);

}  // namespace dynslam::frontend
