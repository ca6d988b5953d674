// The gyro's flow prediction: the infinite homography K R K^-1 of a pure camera rotation.
#include <dynslam/frontend/FlowPrediction.h>

#include <gtest/gtest.h>

#include <cmath>

using dynslam::frontend::predictByRotation;

TEST(FlowPrediction, PanningRightMovesTheImageLeftByFocalTimesTangent) {
  const dynslam::core::CameraIntrinsics K{500, 480, 320, 240, 640, 480};
  const double angle = 0.05;  // rad: the camera turns right (about its y axis, down)
  // q = R p maps a static point from the previous camera frame to this one: the camera turning
  // right by `angle` turns the world left by it.
  const Eigen::Matrix3d R = Eigen::AngleAxisd(-angle, Eigen::Vector3d::UnitY()).toRotationMatrix();
  const auto out = predictByRotation({{320, 240}, {420, 140}}, K, R);
  ASSERT_EQ(out.size(), 2u);
  EXPECT_NEAR(out[0].x, 320 - 500 * std::tan(angle), 1e-3);
  EXPECT_NEAR(out[0].y, 240, 1e-3);
  // Off-centre: the exact ray rotation, not a shift.
  const Eigen::Vector3d ray((420 - 320) / 500.0, (140 - 240) / 480.0, 1);
  const Eigen::Vector3d q = R * ray;
  EXPECT_NEAR(out[1].x, 500 * q.x() / q.z() + 320, 1e-3);
  EXPECT_NEAR(out[1].y, 480 * q.y() / q.z() + 240, 1e-3);
}

TEST(FlowPrediction, IdentityKeepsPixelsAndABackwardRayKeepsItsPixel) {
  const dynslam::core::CameraIntrinsics K{500, 500, 320, 240, 640, 480};
  auto out = predictByRotation({{10, 20}}, K, Eigen::Matrix3d::Identity());
  EXPECT_NEAR(out[0].x, 10, 1e-4);
  EXPECT_NEAR(out[0].y, 20, 1e-4);
  // Turned half round: the ray points behind the camera; no prediction is possible.
  out = predictByRotation({{10, 20}}, K,
                          Eigen::AngleAxisd(M_PI, Eigen::Vector3d::UnitY()).toRotationMatrix());
  EXPECT_EQ(out[0], cv::Point2f(10, 20));
}
