#include "dynslam/sim/Compositor.h"

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <stdexcept>

namespace dynslam::sim {

cv::Mat compositeOverReal(const RenderOutput& rendered, const cv::Mat& real_rgb,
                          const cv::Mat& real_depth, RenderOutput& out) {
  const cv::Size size = real_depth.size();
  if (real_rgb.type() != CV_8UC3 || real_depth.type() != CV_32FC1 || real_rgb.size() != size)
    throw std::invalid_argument(
        "compositeOverReal: the real frame needs CV_8UC3 colour and "
        "CV_32FC1 depth of one size");
  if (rendered.rgb.size() != size || rendered.depth.size() != size ||
      rendered.label.size() != size || rendered.rgb.type() != CV_8UC3 ||
      rendered.depth.type() != CV_32FC1 || rendered.label.type() != CV_16UC1)
    throw std::invalid_argument(
        "compositeOverReal: the rendering differs from the real frame "
        "in size or type");
  cv::Mat mask(size, CV_8UC1);
  for (int y = 0; y < size.height; ++y) {
    const float* r = rendered.depth.ptr<float>(y);
    const float* d = real_depth.ptr<float>(y);
    uint8_t* m = mask.ptr<uint8_t>(y);
    for (int x = 0; x < size.width; ++x) m[x] = r[x] > 0 && (d[x] <= 0 || r[x] < d[x]) ? 255 : 0;
  }
  real_rgb.copyTo(out.rgb);
  real_depth.copyTo(out.depth);
  out.label.create(size, CV_16UC1);
  out.label.setTo(0);
  rendered.rgb.copyTo(out.rgb, mask);
  rendered.depth.copyTo(out.depth, mask);
  rendered.label.copyTo(out.label, mask);
  return mask;
}

void applyRgbdNoiseMasked(RenderOutput& frame, const cv::Mat& mask, const RgbdNoiseOptions& options,
                          std::mt19937_64& rng) {
  const cv::Rect box = cv::boundingRect(mask);
  if (box.empty()) {
    RenderOutput nothing;  // keep the rng's draws independent of what was inserted
    applyRgbdNoise(nothing, options, rng);
    return;
  }
  // Edge holes look at neighbours, so the noisy copy covers the mask plus a margin.
  const int margin = std::max(0, options.edge_hole_width) + 1;
  const cv::Rect roi =
      cv::Rect(box.x - margin, box.y - margin, box.width + 2 * margin, box.height + 2 * margin) &
      cv::Rect(0, 0, mask.cols, mask.rows);
  RenderOutput noisy;
  noisy.rgb = frame.rgb(roi).clone();
  noisy.depth = frame.depth(roi).clone();
  applyRgbdNoise(noisy, options, rng);
  const cv::Mat inside = mask(roi);
  cv::Mat rgb = frame.rgb(roi), depth = frame.depth(roi);
  noisy.rgb.copyTo(rgb, inside);
  noisy.depth.copyTo(depth, inside);
}

}  // namespace dynslam::sim
