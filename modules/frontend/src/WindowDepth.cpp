#include "dynslam/frontend/WindowDepth.h"

#include <dynslam/core/Median.h>

#include <algorithm>
#include <cmath>

namespace dynslam::frontend {

float windowDepth(const cv::Mat& depth, const cv::Point2f& pixel, int half, double sigmaZ2,
                  std::vector<double>& buf) {
  const int x0 = cvRound(pixel.x), y0 = cvRound(pixel.y);
  buf.clear();
  for (int y = std::max(0, y0 - half); y <= std::min(depth.rows - 1, y0 + half); ++y) {
    const float* row = depth.ptr<float>(y);
    for (int x = std::max(0, x0 - half); x <= std::min(depth.cols - 1, x0 + half); ++x)
      if (row[x] > 0) buf.push_back(row[x]);
  }
  if (buf.empty()) return 0;
  // The surface of the feature's own pixel when it has a reading, else the window's main one.
  const float centre = (x0 >= 0 && y0 >= 0 && x0 < depth.cols && y0 < depth.rows)
                           ? depth.at<float>(y0, x0)
                           : 0.f;
  const double m0 = centre > 0 ? double(centre) : core::upperMedianInPlace(buf);
  const double band = std::max({0.05, 0.02 * m0, 3 * std::sqrt(2.0) * sigmaZ2 * m0 * m0});
  buf.erase(std::remove_if(buf.begin(), buf.end(), [&](double z) { return std::abs(z - m0) > band; }),
            buf.end());
  return float(core::upperMedianInPlace(buf));
}

}  // namespace dynslam::frontend
