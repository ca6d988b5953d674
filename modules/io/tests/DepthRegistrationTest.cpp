#include <dynslam/io/DepthRegistration.h>
#include <dynslam/io/ObservationConversion.h>
#include <dynslam/testing/SyntheticObservations.h>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>

using namespace dynslam;

namespace {
core::CameraIntrinsics camera(int w, int h, double f) {
  core::CameraIntrinsics k;
  k.fx = k.fy = f;
  k.cx = (w - 1) / 2.0;
  k.cy = (h - 1) / 2.0;
  k.width = w;
  k.height = h;
  return k;
}
}  // namespace

TEST(DepthRegistration, IdentityKeepsTheImage) {
  const auto k = camera(40, 30, 50);
  cv::Mat d(30, 40, CV_32FC1, cv::Scalar(2.0f));
  d.at<float>(5, 7) = 0;  // a hole stays a hole
  const cv::Mat r = io::registerDepth(d, k, k, Eigen::Isometry3d::Identity());
  EXPECT_EQ(cv::norm(r, d, cv::NORM_INF), 0.0);
}

TEST(DepthRegistration, SidewaysShiftMovesPixelsByFocalTimesBaselineOverDepth) {
  const auto k = camera(40, 30, 50);
  cv::Mat d(30, 40, CV_32FC1, cv::Scalar(0.0f));
  d.at<float>(15, 20) = 2.0f;
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.translation() = Eigen::Vector3d(0.2, 0, 0.5);  // target camera 0.2 m left, 0.5 m back
  const cv::Mat r = io::registerDepth(d, k, k, T);
  // x = 0.2 * ... : point (u=20 -> x = (20-19.5)/50*2 = 0.02) maps to x' = 0.22, z' = 2.5
  // u' = 50 * 0.22 / 2.5 + 19.5 = 23.9 -> 24; v' = 50 * (0.5/50*2) / 2.5 + 14.5 = 14.9 -> 15
  EXPECT_FLOAT_EQ(r.at<float>(15, 24), 2.5f);
  EXPECT_EQ(cv::countNonZero(r), 1);
}

TEST(DepthRegistration, NearestPointWinsWhereTwoLand) {
  const auto k = camera(40, 30, 50);
  cv::Mat d(30, 40, CV_32FC1, cv::Scalar(0.0f));
  d.at<float>(15, 20) = 2.0f;
  d.at<float>(15, 21) = 1.0f;
  // A camera with a tenth of the focal length maps both neighbours onto one pixel.
  const auto small = camera(10, 8, 5);
  const cv::Mat r = io::registerDepth(d, k, small, Eigen::Isometry3d::Identity());
  double mn = 0, mx = 0;
  cv::minMaxLoc(r, &mn, &mx);
  EXPECT_FLOAT_EQ(static_cast<float>(mx), 1.0f);
  EXPECT_EQ(cv::countNonZero(r), 1);
}

TEST(DepthRegistration, RangesBecomeDepthsAlongTheAxis) {
  const auto k = camera(3, 1, 1);  // cx = 1: pixel 0 and 2 are 45 degrees off-axis
  cv::Mat r(1, 3, CV_32FC1, cv::Scalar(std::sqrt(2.0f)));
  io::rangesToDepths(r, k);
  EXPECT_NEAR(r.at<float>(0, 0), 1.0f, 1e-6);
  EXPECT_NEAR(r.at<float>(0, 1), std::sqrt(2.0f), 1e-6);
}

// A colour camera with other intrinsics at the depth camera's place (7-Scenes: depth f 585 px,
// colour f 525 px; MRPT's doDepthAndIntensityCamerasCoincide() compares the poses only): the
// depth comes out registered to the colour image, a point at depth pixel u landing at colour
// pixel cx + (u - cx) * 450 / 500.
TEST(DepthRegistration, AColourCameraWithOtherIntrinsicsAtTheSamePlaceGetsRegisteredDepth) {
  auto obs = dynslam::testing::makeScan(1.0, 64, 48);
  for (int v = 0; v < 48; ++v)
    for (int u = 0; u < 64; ++u) obs->rangeImage(v, u) = 0;
  obs->rangeImage(24, 52) = 2000;  // 20 px right of the principal point (32, 24)
  obs->cameraParamsIntensity.setIntrinsicParamsFromValues(450, 450, 32, 24);
  ASSERT_TRUE(obs->doDepthAndIntensityCamerasCoincide());
  core::Frame frame;
  io::fillFrameFromRgbd(*obs, frame);
  EXPECT_DOUBLE_EQ(frame.intrinsics.fx, 450.0);
  ASSERT_EQ(cv::countNonZero(frame.depth), 1);
  EXPECT_FLOAT_EQ(frame.depth.at<float>(24, 50), 2.0f) << "32 + 20 * 450 / 500 = 50";
}

// Cameras at the same place with other intrinsics take a shortcut (each column and row maps
// once): the same image as the general warp, here forced by a 1e-9 m offset.
TEST(DepthRegistration, AnIntrinsicsOnlyChangeMapsLikeTheGeneralWarp) {
  auto from = camera(64, 48, 58.5), to = camera(64, 48, 52.5);
  cv::Mat d(48, 64, CV_32FC1);
  cv::randu(d, 0.5, 4.0);
  d(cv::Rect(10, 10, 5, 5)).setTo(0);  // holes stay holes
  Eigen::Isometry3d nudge = Eigen::Isometry3d::Identity();
  nudge.translation() = Eigen::Vector3d(1e-9, 0, 0);
  const cv::Mat fast = io::registerDepth(d, from, to, Eigen::Isometry3d::Identity());
  const cv::Mat general = io::registerDepth(d, from, to, nudge);
  EXPECT_EQ(cv::norm(fast, general, cv::NORM_INF), 0.0);
  EXPECT_GT(cv::countNonZero(fast), 48 * 64 / 2);
}
