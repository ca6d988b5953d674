#include "TextureCanvas.h"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>

namespace dynslam::sim::detail {

int SeededRandom::uniformInt(int lo, int hi) {
  if (hi <= lo) return lo;
  const uint64_t span = static_cast<uint64_t>(static_cast<int64_t>(hi) - lo) + 1;
  return static_cast<int>(lo + static_cast<int64_t>(engine_() % span));
}

double SeededRandom::uniform01() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }

cv::Scalar SeededRandom::jitter(const cv::Scalar& base, int amount) {
  cv::Scalar out;
  for (int c = 0; c < 3; ++c)
    out[c] = std::clamp(base[c] + uniformInt(-amount, amount), 0.0, 255.0);
  return out;
}

cv::Scalar SeededRandom::shade(const cv::Scalar& base, double amount) {
  const double factor = uniform(1.0 - amount, 1.0 + amount);
  cv::Scalar out;
  for (int c = 0; c < 3; ++c) out[c] = std::clamp(base[c] * factor, 0.0, 255.0);
  return out;
}

cv::Scalar SeededRandom::vividColour() {
  // One channel high, one low, one anywhere: saturated but varied hues.
  int channels[3] = {0, 1, 2};
  for (int i = 2; i > 0; --i) std::swap(channels[i], channels[uniformInt(0, i)]);
  cv::Scalar out;
  out[channels[0]] = uniformInt(180, 255);
  out[channels[1]] = uniformInt(0, 70);
  out[channels[2]] = uniformInt(0, 255);
  return out;
}

cv::Scalar SeededRandom::pick(const std::vector<cv::Scalar>& palette) {
  return palette[uniformInt(0, static_cast<int>(palette.size()) - 1)];
}

WrapCanvas::WrapCanvas(int size, const cv::Scalar& background)
    : size_(size), image_(size, size, CV_8UC3, background) {}

template <typename Draw>
void WrapCanvas::wrapped(Draw draw) {
  for (int dy = -size_; dy <= size_; dy += size_)
    for (int dx = -size_; dx <= size_; dx += size_) draw(cv::Point(dx, dy));
}

void WrapCanvas::rect(const cv::Rect& r, const cv::Scalar& colour, int thickness) {
  wrapped([&](cv::Point o) { cv::rectangle(image_, r + o, colour, thickness, cv::LINE_8); });
}

void WrapCanvas::line(cv::Point a, cv::Point b, const cv::Scalar& colour, int thickness) {
  wrapped([&](cv::Point o) { cv::line(image_, a + o, b + o, colour, thickness, cv::LINE_AA); });
}

void WrapCanvas::polyline(const std::vector<cv::Point>& points, const cv::Scalar& colour,
                          int thickness) {
  wrapped([&](cv::Point o) {
    std::vector<cv::Point> shifted(points);
    for (cv::Point& p : shifted) p += o;
    cv::polylines(image_, shifted, false, colour, thickness, cv::LINE_AA);
  });
}

void WrapCanvas::circle(cv::Point centre, int radius, const cv::Scalar& colour, int thickness) {
  wrapped(
      [&](cv::Point o) { cv::circle(image_, centre + o, radius, colour, thickness, cv::LINE_AA); });
}

void WrapCanvas::ellipse(cv::Point centre, cv::Size axes, double angle_deg,
                         const cv::Scalar& colour, int thickness) {
  wrapped([&](cv::Point o) {
    cv::ellipse(image_, centre + o, axes, angle_deg, 0, 360, colour, thickness, cv::LINE_AA);
  });
}

void WrapCanvas::text(const std::string& text, cv::Point origin, double scale,
                      const cv::Scalar& colour, int thickness) {
  wrapped([&](cv::Point o) {
    cv::putText(image_, text, origin + o, cv::FONT_HERSHEY_SIMPLEX, scale, colour, thickness,
                cv::LINE_AA);
  });
}

void WrapCanvas::blendRect(const cv::Rect& r, const cv::Scalar& colour, double alpha) {
  wrapped([&](cv::Point o) {
    const cv::Rect clipped = (r + o) & cv::Rect(0, 0, size_, size_);
    if (clipped.empty()) return;
    cv::Mat roi = image_(clipped);
    cv::addWeighted(roi, 1.0 - alpha, cv::Mat(roi.size(), roi.type(), colour), alpha, 0.0, roi);
  });
}

cv::Mat WrapCanvas::finish(SeededRandom& random, int grain_amplitude, double blur_sigma) {
  if (grain_amplitude > 0) {
    for (int y = 0; y < size_; ++y) {
      auto* row = image_.ptr<uchar>(y);
      for (int x = 0; x < size_; ++x) {
        // Same offset on the three channels: grain changes brightness, not hue.
        const int delta = random.uniformInt(-grain_amplitude, grain_amplitude);
        for (int c = 0; c < 3; ++c)
          row[3 * x + c] = cv::saturate_cast<uchar>(row[3 * x + c] + delta);
      }
    }
  }
  if (blur_sigma <= 0) return image_.clone();
  // GaussianBlur has no wrapping border mode: pad with wrapped copies, blur, crop.
  const int pad = 2 * static_cast<int>(std::ceil(3 * blur_sigma)) + 1;
  cv::Mat padded, blurred;
  cv::copyMakeBorder(image_, padded, pad, pad, pad, pad, cv::BORDER_WRAP);
  cv::GaussianBlur(padded, blurred, cv::Size(0, 0), blur_sigma, blur_sigma, cv::BORDER_REFLECT);
  return blurred(cv::Rect(pad, pad, size_, size_)).clone();
}

}  // namespace dynslam::sim::detail
