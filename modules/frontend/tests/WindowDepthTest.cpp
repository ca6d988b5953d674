// Contract of windowDepth: the median of the window's readings on the pixel's own surface has
// about a quarter of one reading's noise also where that noise is decimetres (9 m away), and a
// surface a metre behind does not leak into it.
#include <dynslam/frontend/WindowDepth.h>

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace dynslam::frontend {
namespace {

constexpr double kSigmaZ2 = 0.0015;  // the D455-like model of the simulator and the inis

/// A 640x480 depth image: `left` m for x < 320, `right` m beyond, each reading with Gaussian
/// noise of sigma kSigmaZ2 z^2.
cv::Mat noisyDepth(double left, double right, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> n(0, 1);
  cv::Mat d(480, 640, CV_32FC1);
  for (int y = 0; y < d.rows; ++y)
    for (int x = 0; x < d.cols; ++x) {
      const double z = x < 320 ? left : right;
      d.at<float>(y, x) = float(z + kSigmaZ2 * z * z * n(rng));
    }
  return d;
}

/// RMS error of windowDepth (5x5) against `truth` over a grid of pixels in the left half.
double rmsError(const cv::Mat& depth, double truth, double sigmaZ2) {
  std::vector<double> buf;
  double sum = 0;
  int n = 0;
  for (int y = 10; y < 470; y += 7)
    for (int x = 10; x < 300; x += 7) {
      const double e = windowDepth(depth, cv::Point2f(float(x), float(y)), 2, sigmaZ2, buf) - truth;
      sum += e * e;
      ++n;
    }
  return std::sqrt(sum / n);
}

TEST(WindowDepth, AFarSurfacesWindowMedianHasAQuarterOfOneReadingsNoise) {
  const double z = 9.0, sigma = kSigmaZ2 * z * z;  // 12 cm per reading
  const cv::Mat depth = noisyDepth(z, z, 1);
  const double rms = rmsError(depth, z, kSigmaZ2);
  EXPECT_LT(rms, 0.3 * sigma) << "rms " << rms << " m against one reading's " << sigma;
  // Without the noise term (the band of 2 % = 1.5 sigma around the pixel's own noisy reading)
  // the median keeps much of that reading's error.
  EXPECT_GT(rmsError(depth, z, 0.0), 1.5 * rms);
}

TEST(WindowDepth, ASurfaceAMetreBehindDoesNotLeakIn) {
  std::vector<double> buf;
  // 2 m against 3 m (sigma 6 / 14 mm) and 9 m against 10 m (sigma 12 / 15 cm), 1 px either side
  // of the edge: a fifth of the window lies on the other surface, and those 5 readings kept
  // would move the median by about 0.3 sigma; the mean error over 230 rows stays within 0.1.
  for (const auto& [near, far] : {std::pair{2.0, 3.0}, std::pair{9.0, 10.0}}) {
    const cv::Mat depth = noisyDepth(near, far, 2);
    double nearSum = 0, farSum = 0;
    int n = 0;
    for (int y = 10; y < 470; y += 2, ++n) {
      nearSum += windowDepth(depth, cv::Point2f(318.f, float(y)), 2, kSigmaZ2, buf) - near;
      farSum += windowDepth(depth, cv::Point2f(321.f, float(y)), 2, kSigmaZ2, buf) - far;
    }
    EXPECT_LT(std::abs(nearSum / n), 0.1 * kSigmaZ2 * near * near) << near << " m, beside " << far;
    EXPECT_LT(std::abs(farSum / n), 0.1 * kSigmaZ2 * far * far) << far << " m, beside " << near;
  }
}

TEST(WindowDepth, APixelWithoutAReadingTakesTheWindowsMainSurfaceAndNoReadingGivesZero) {
  std::vector<double> buf;
  cv::Mat depth(20, 20, CV_32FC1, cv::Scalar(4.0f));
  depth.at<float>(10, 10) = 0;  // the pixel itself has no reading
  depth.at<float>(9, 9) = 7.0f;  // one reading of another surface in its window
  EXPECT_FLOAT_EQ(windowDepth(depth, cv::Point2f(10, 10), 2, kSigmaZ2, buf), 4.0f);
  EXPECT_FLOAT_EQ(windowDepth(cv::Mat(20, 20, CV_32FC1, cv::Scalar(0.0f)), cv::Point2f(10, 10), 2,
                              kSigmaZ2, buf),
                  0.0f);
}

}  // namespace
}  // namespace dynslam::frontend
