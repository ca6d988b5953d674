// The RGB-D noise model: depth sigma growing with z^2, range cuts, holes on the far side of
// depth edges, colour noise, determinism. Also times the renderer plus noise on a room scene.
#include <dynslam/sim/SensorNoise.h>
#include <dynslam/testing/SyntheticRoom.h>

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <iostream>

namespace dynslam::sim {
namespace {

RenderOutput constantFrame(float depth, int width = 640, int height = 480) {
  RenderOutput frame;
  frame.rgb = cv::Mat(height, width, CV_8UC3, cv::Scalar(128, 128, 128));
  frame.depth = cv::Mat(height, width, CV_32FC1, cv::Scalar(depth));
  frame.label = cv::Mat(height, width, CV_16UC1, cv::Scalar(5));
  return frame;
}

RgbdNoiseOptions noEdgeHoles() {
  RgbdNoiseOptions options;
  options.edge_hole_width = 0;
  return options;
}

TEST(SensorNoise, DepthSigmaFollowsTheModelAt1And4Metres) {
  const RgbdNoiseOptions options = noEdgeHoles();
  std::mt19937_64 rng(11);
  for (double z : {1.0, 4.0}) {
    RenderOutput frame = constantFrame(static_cast<float>(z));
    applyRgbdNoise(frame, options, rng);
    cv::Scalar mean, stddev;
    cv::meanStdDev(frame.depth, mean, stddev);
    const double expected = options.depth_sigma_min + options.depth_sigma_z2 * z * z;
    std::cout << "z " << z << " m: sigma " << stddev[0] << " m (model " << expected << ")\n";
    EXPECT_NEAR(stddev[0], expected, 0.1 * expected) << z;
    EXPECT_NEAR(mean[0], z, 0.01 * expected) << z;
    EXPECT_EQ(cv::countNonZero(frame.depth), frame.depth.cols * frame.depth.rows);
  }
}

TEST(SensorNoise, ColourSigmaPerChannelAndLabelsUntouched) {
  RenderOutput frame = constantFrame(2.0f);
  std::mt19937_64 rng(3);
  applyRgbdNoise(frame, {}, rng);
  cv::Scalar mean, stddev;
  cv::meanStdDev(frame.rgb, mean, stddev);
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(stddev[c], 3.0, 0.3) << c;
    EXPECT_NEAR(mean[c], 128.0, 0.1) << c;
  }
  // Independent channels: B and G of one pixel are uncorrelated.
  std::vector<cv::Mat> channels;
  cv::split(frame.rgb, channels);
  cv::Mat b, g;
  channels[0].convertTo(b, CV_64F, 1, -128);
  channels[1].convertTo(g, CV_64F, 1, -128);
  EXPECT_LT(std::abs(b.dot(g) / (b.total() * 9.0)), 0.02);
  EXPECT_EQ(cv::countNonZero(frame.label != 5), 0);
}

TEST(SensorNoise, DepthOutsideTheRangeBecomesInvalid) {
  std::mt19937_64 rng(5);
  for (float z : {7.0f, 0.2f, 0.0f}) {
    RenderOutput frame = constantFrame(z);
    applyRgbdNoise(frame, {}, rng);
    EXPECT_EQ(cv::countNonZero(frame.depth), 0) << z;
  }
  for (float z : {5.9f, 0.35f}) {
    RenderOutput frame = constantFrame(z);
    applyRgbdNoise(frame, {}, rng);
    EXPECT_EQ(cv::countNonZero(frame.depth), 640 * 480) << z;
  }
}

TEST(SensorNoise, HolesOnTheFarSideOfStepEdges) {
  for (int width : {1, 3}) {
    RgbdNoiseOptions options;
    options.edge_hole_width = width;
    // Near left half (1 m) against a far right half (3 m), and a near top band over a far
    // bottom band in the left half.
    RenderOutput frame = constantFrame(1.0f);
    frame.depth.colRange(320, 640).setTo(3.0f);
    frame.depth(cv::Rect(0, 300, 320, 180)).setTo(2.0f);
    std::mt19937_64 rng(9);
    applyRgbdNoise(frame, options, rng);
    const cv::Mat& d = frame.depth;
    for (int y = 0; y < 480; y += 7) {
      for (int i = 0; i < width; ++i) EXPECT_EQ(d.at<float>(y, 320 + i), 0.0f) << width;
      EXPECT_GT(d.at<float>(y, 320 + width), 2.5f) << width;
      if (y < 300 - 1) {
        EXPECT_GT(d.at<float>(y, 319), 0.5f) << width;  // near side kept
      }
    }
    for (int x = 0; x < 319; x += 5) {
      for (int i = 0; i < width; ++i) EXPECT_EQ(d.at<float>(300 + i, x), 0.0f) << width;
      EXPECT_GT(d.at<float>(300 + width, x), 1.5f) << width;
      EXPECT_GT(d.at<float>(299, x), 0.5f) << width;
    }
  }
}

// The stereo model (RealSense D4xx-like): sigma from the disparity noise, f = 380 px and b = 5 cm
// give 0.0042 z^2; a person at 1 m before a wall at 3 m hides f b (1 - 1/3) = 12.7 -> 13 px of the
// wall left of it from the right imager; nothing right of it beyond the ordinary edge hole.
TEST(SensorNoise, StereoDepthNoiseAndTheOcclusionBandLeftOfNearObjects) {
  RgbdNoiseOptions options;
  options.depth_model = DepthModel::Stereo;
  options.focal_px = 380;
  options.edge_hole_width = 1;
  std::mt19937_64 rng(21);
  RenderOutput flat = constantFrame(3.0f);
  applyRgbdNoise(flat, options, rng);
  cv::Scalar mean, stddev;
  cv::meanStdDev(flat.depth, mean, stddev);
  const double expected = options.depth_sigma_min + 9.0 * 0.08 / (380 * 0.05);
  std::cout << "stereo, z 3 m: sigma " << stddev[0] << " m (model " << expected << ")\n";
  EXPECT_NEAR(stddev[0], expected, 0.1 * expected);

  RenderOutput frame = constantFrame(3.0f);
  frame.depth.colRange(300, 400).setTo(1.0f);  // a near object in front of the wall
  applyRgbdNoise(frame, options, rng);
  for (int y = 0; y < 480; y += 11) {
    for (int x = 300 - 13; x < 300; ++x) EXPECT_EQ(frame.depth.at<float>(y, x), 0.0f) << x;
    EXPECT_GT(frame.depth.at<float>(y, 300 - 14), 2.5f);
    EXPECT_GT(frame.depth.at<float>(y, 300), 0.5f);  // the object itself
    EXPECT_EQ(frame.depth.at<float>(y, 400), 0.0f);  // the ordinary 1 px edge hole
    EXPECT_GT(frame.depth.at<float>(y, 401), 2.5f);
  }
}

TEST(SensorNoise, SmoothSlopesKeepTheirPixels) {
  // 2 mm per pixel: a floor seen at a grazing angle; no pair differs by edge_jump.
  RenderOutput frame = constantFrame(1.0f);
  for (int x = 0; x < 640; ++x) frame.depth.col(x).setTo(1.0f + 0.002f * x);
  std::mt19937_64 rng(1);
  applyRgbdNoise(frame, {}, rng);
  EXPECT_EQ(cv::countNonZero(frame.depth), 640 * 480);
}

TEST(SensorNoise, SameSeedSameImages) {
  const auto noisy = [](uint64_t seed) {
    RenderOutput frame = constantFrame(2.0f);
    frame.depth.colRange(0, 100).setTo(4.0f);
    std::mt19937_64 rng(seed);
    applyRgbdNoise(frame, {}, rng);
    return frame;
  };
  const RenderOutput a = noisy(21), b = noisy(21), c = noisy(22);
  EXPECT_EQ(cv::norm(a.rgb, b.rgb, cv::NORM_INF), 0);
  EXPECT_EQ(cv::norm(a.depth, b.depth, cv::NORM_INF), 0);
  EXPECT_GT(cv::norm(a.rgb, c.rgb, cv::NORM_INF), 0);
  EXPECT_GT(cv::norm(a.depth, c.depth, cv::NORM_INF), 0);
}

TEST(SensorNoise, RejectsWrongImageTypes) {
  RenderOutput frame = constantFrame(1.0f);
  frame.depth.convertTo(frame.depth, CV_64F);
  std::mt19937_64 rng(1);
  EXPECT_THROW(applyRgbdNoise(frame, {}, rng), std::invalid_argument);
}

}  // namespace
}  // namespace dynslam::sim
