#pragma once
// Drawing helpers for the procedural textures (internal to the sim module): a seeded random
// source with integer-based sampling (identical on every platform, unlike the std
// distributions) and a canvas that draws on a torus so the textures tile without seams.
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include <cstdint>
#include <random>
#include <string>
#include <vector>

namespace dynslam::sim::detail {

class SeededRandom {
 public:
  explicit SeededRandom(uint64_t seed) : engine_(seed) {}

  /// Uniform integer in [lo, hi]; lo when hi <= lo (a feature too big for a small texture).
  /// Modulo bias is below 2^-40 for our ranges.
  int uniformInt(int lo, int hi);
  /// Uniform in [0, 1) from the top 53 bits.
  double uniform01();
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform01(); }
  bool chance(double probability) { return uniform01() < probability; }
  /// `base` with each channel moved by up to +-amount (clamped to [0, 255]).
  cv::Scalar jitter(const cv::Scalar& base, int amount);
  /// `base` scaled by a brightness factor in [1 - amount, 1 + amount] (hue kept).
  cv::Scalar shade(const cv::Scalar& base, double amount);
  /// A saturated random colour (for prints, posters, logos).
  cv::Scalar vividColour();
  /// One of `palette`'s entries.
  cv::Scalar pick(const std::vector<cv::Scalar>& palette);

 private:
  std::mt19937_64 engine_;
};

/// A square CV_8UC3 canvas whose primitives wrap around both borders (each is drawn at the
/// nine offsets {-size, 0, size}^2 and OpenCV clips the copies), so the finished image tiles.
class WrapCanvas {
 public:
  WrapCanvas(int size, const cv::Scalar& background);

  int size() const { return size_; }
  void rect(const cv::Rect& r, const cv::Scalar& colour, int thickness = cv::FILLED);
  void line(cv::Point a, cv::Point b, const cv::Scalar& colour, int thickness = 1);
  void polyline(const std::vector<cv::Point>& points, const cv::Scalar& colour, int thickness);
  void circle(cv::Point centre, int radius, const cv::Scalar& colour, int thickness = cv::FILLED);
  void ellipse(cv::Point centre, cv::Size axes, double angle_deg, const cv::Scalar& colour,
               int thickness = cv::FILLED);
  void text(const std::string& text, cv::Point origin, double scale, const cv::Scalar& colour,
            int thickness);
  /// Blends `colour` into the rectangle with weight alpha in [0, 1] (woven stripes, stains).
  void blendRect(const cv::Rect& r, const cv::Scalar& colour, double alpha);

  /// Adds per-pixel grain in [-amplitude, amplitude] (material micro-texture), then a Gaussian
  /// blur of `blur_sigma` px computed on the torus, so edges are anti-aliased like a camera
  /// would see them and the borders still match. Returns the finished image.
  cv::Mat finish(SeededRandom& random, int grain_amplitude, double blur_sigma);

 private:
  template <typename Draw>
  void wrapped(Draw draw);

  int size_;
  cv::Mat image_;
};

}  // namespace dynslam::sim::detail
