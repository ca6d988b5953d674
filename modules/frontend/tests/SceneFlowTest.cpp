// Contracts of the scene flow (method.md Eq. 11) and of the camera motion it removes: the flow
// of a static point under the camera's motion is zero, that of a moving point is its own
// displacement; the gyro rotation, turned into camera axes by the extrinsics, is the camera's.
#include <dynslam/frontend/CameraMotion.h>
#include <dynslam/frontend/FarPointMotion.h>
#include <dynslam/frontend/SceneFlow.h>

#include <gtest/gtest.h>

#include <random>

namespace dynslam::frontend {
namespace {

Eigen::Isometry3d pose(const Eigen::Vector3d& axis, double angle, const Eigen::Vector3d& t) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
  T.translation() = t;
  return T;
}

TEST(SceneFlow, StaticPointHasNoFlowAndAMovingPointItsOwnMotion) {
  const Eigen::Isometry3d T_w_c0 = pose({0, 1, 0.2}, 0.1, {0.5, 0.1, -0.3});
  const Eigen::Isometry3d T_w_c1 = pose({0.1, 1, 0.1}, 0.14, {0.53, 0.11, -0.28});
  const Eigen::Isometry3d T_c1_c0 = T_w_c1.inverse() * T_w_c0;
  const Eigen::Vector3d X(1.0, -0.4, 4.0);  // world
  const Eigen::Vector3d P0 = T_w_c0.inverse() * X, P1 = T_w_c1.inverse() * X;
  EXPECT_LT(sceneFlow(P0, P1, T_c1_c0).norm(), 1e-12);

  const Eigen::Vector3d move(0.04, 0.0, -0.02);  // the point walks 4.5 cm in the world
  const Eigen::Vector3d P1moved = T_w_c1.inverse() * (X + move);
  const Eigen::Vector3d F = sceneFlow(P0, P1moved, T_c1_c0);
  EXPECT_LT((F - T_w_c1.linear().transpose() * move).norm(), 1e-12);
  EXPECT_NEAR(F.norm(), move.norm(), 1e-12);
}

// A point beyond the depth range (no depth): static at any depth >= minDepth it stays on the
// segment its ray sweeps under the camera's motion (residual 0, also far away); moving 0.3 m
// 20 m away it leaves the segment, and the bound minDepth / f * residual stays below the true
// 0.3 m; a static point nearer than minDepth (not what the bound assumes) is off the segment.
TEST(FarPointMotion, StaticFarPointsStayOnTheirSegmentMovingOnesLeaveIt) {
  const core::CameraIntrinsics k{500, 500, 320, 240, 640, 480};
  const Eigen::Isometry3d T_w_c0 = pose({0, 1, 0}, 0.05, {0.0, 0.0, 0.0});
  const Eigen::Isometry3d T_w_c1 = pose({0, 1, 0}, 0.08, {0.2, 0.0, 0.4});
  const Eigen::Isometry3d T_c1_c0 = T_w_c1.inverse() * T_w_c0;
  const auto pixel = [&](const Eigen::Isometry3d& T_w_c, const Eigen::Vector3d& X) {
    const Eigen::Vector3d P = T_w_c.inverse() * X;
    return cv::Point2f(float(k.fx * P.x() / P.z() + k.cx), float(k.fy * P.y() / P.z() + k.cy));
  };
  const double minDepth = 10;
  for (const double z : {10.5, 20.0, 80.0}) {
    const Eigen::Vector3d X = T_w_c0 * Eigen::Vector3d(1.5, -0.5, z);
    EXPECT_LT(farPointResidualPx(pixel(T_w_c0, X), pixel(T_w_c1, X), T_c1_c0, k, minDepth), 0.01)
        << "static at " << z << " m";
  }
  // 0.3 m up (across the segment: the camera moved in x and z) shows almost whole through the
  // bound, 0.3 * 10 / 20 m; 0.3 m sideways lies partly along the segment and shows in part.
  const Eigen::Vector3d X = T_w_c0 * Eigen::Vector3d(1.5, -0.5, 20.0);
  for (const auto& [move, least] : {std::pair{Eigen::Vector3d(0, -0.3, 0), 0.9 * 0.15},
                                    std::pair{Eigen::Vector3d(0.3, 0, 0), 0.05}}) {
    const Eigen::Vector3d walked = X + T_w_c0.linear() * move;
    const double bound =
        farPointMinDisplacement(pixel(T_w_c0, X), pixel(T_w_c1, walked), T_c1_c0, k, minDepth);
    EXPECT_LT(bound, 0.3);
    EXPECT_GT(bound, least) << move.transpose();
  }
  const Eigen::Vector3d near = T_w_c0 * Eigen::Vector3d(1.5, -0.5, 3.0);
  EXPECT_GT(farPointResidualPx(pixel(T_w_c0, near), pixel(T_w_c1, near), T_c1_c0, k, minDepth), 5)
      << "a static point 3 m away moves like no point beyond 10 m";
}

TEST(SceneFlow, BackProjectionInvertsThePinhole) {
  core::CameraIntrinsics k{500, 510, 320, 240, 640, 480};
  const Eigen::Vector3d P = backProject({420.f, 140.f}, 2.0, k);
  EXPECT_NEAR(k.fx * P.x() / P.z() + k.cx, 420, 1e-9);
  EXPECT_NEAR(k.fy * P.y() / P.z() + k.cy, 140, 1e-9);
  EXPECT_EQ(P.z(), 2.0);
}

TEST(CameraMotion, GyroRotationInCameraAxes) {
  // Body x forward, y left, z up; camera optical axes (x right, y down, z forward); the IMU
  // mounted turned 90 deg about the body's z.
  Eigen::Isometry3d T_body_camera = Eigen::Isometry3d::Identity();
  T_body_camera.linear() << 0, 0, 1, -1, 0, 0, 0, -1, 0;
  const Eigen::Isometry3d T_body_imu = pose({0, 0, 1}, M_PI / 2, {0.02, 0, 0.01});
  // The body yaws left at 0.6 rad/s for 1/30 s: the IMU measures it about its own z as well.
  const Eigen::Vector3d w_body(0, 0, 0.6);
  const Eigen::Vector3d w_imu = T_body_imu.linear().transpose() * w_body;
  std::vector<core::ImuSample> imu;
  for (int i = 1; i <= 7; ++i) {
    core::ImuSample s;
    s.t = 10.0 + i / 200.0;
    s.gyro = w_imu;
    s.has_gyro = true;
    imu.push_back(s);
  }
  const double t0 = 10.0, t1 = 10.0 + 7 / 200.0;
  const auto R = gyroCameraRotation(imu, t0, t1, T_body_imu, T_body_camera);
  ASSERT_TRUE(R);
  // Camera poses at t0 and t1 in a world = body at t0.
  const Eigen::Isometry3d T_w_c0 = T_body_camera;
  const Eigen::Isometry3d T_w_c1 = pose({0, 0, 1}, 0.6 * (t1 - t0), {0, 0, 0}) * T_body_camera;
  const Eigen::Matrix3d expected = (T_w_c1.inverse() * T_w_c0).linear();
  EXPECT_LT((*R - expected).norm(), 1e-9);
  // A yaw to the left turns static points to the right in the image (+x of the camera).
  const Eigen::Vector3d ahead(0, 0, 3);
  EXPECT_GT((*R * ahead).x(), 0);
  EXPECT_FALSE(gyroCameraRotation({}, t0, t1, T_body_imu, T_body_camera));
}

TEST(CameraMotion, BackgroundRegistrationRecoversTheMotionAmongMovers) {
  std::mt19937 gen(11);
  std::uniform_real_distribution<double> u(-2, 2);
  const Eigen::Isometry3d T = pose({0.2, 1, 0}, 0.03, {0.02, -0.01, 0.05});  // C1 <- C0
  std::vector<Eigen::Vector3d> p, q;
  for (int i = 0; i < 80; ++i) {
    p.emplace_back(u(gen), u(gen) / 2, 4 + u(gen) / 2);
    q.push_back(T * p.back());
    if (i % 10 == 0) q.back() += Eigen::Vector3d(0.25, 0, 0.1);  // a walker in the background
  }
  // With the gyro's rotation only the translation is registered; without, all six degrees.
  CameraMotionEstimator withGyro;
  const auto g = withGyro.estimate(p, q, T.linear(), std::nullopt, std::nullopt);
  EXPECT_EQ(g.source, CameraMotionSource::ImuRotationRegistration);
  EXPECT_EQ(g.inliers, 72);
  EXPECT_LT((g.motion.isometry().matrix() - T.matrix()).norm(), 1e-9);
  CameraMotionEstimator estimator;
  const auto e = estimator.estimate(p, q, std::nullopt, std::nullopt, std::nullopt);
  EXPECT_EQ(e.source, CameraMotionSource::Registration);
  EXPECT_EQ(e.inliers, 72);
  EXPECT_LT((e.motion.isometry().matrix() - T.matrix()).norm(), 1e-9);
  // A gyro rotation that does not hold (wrong extrinsics: 20 deg off) loses to the registration.
  CameraMotionEstimator wrongGyro;
  const Eigen::Matrix3d bad = Eigen::AngleAxisd(0.35, Eigen::Vector3d::UnitX()) * T.linear();
  const auto w = wrongGyro.estimate(p, q, bad, std::nullopt, std::nullopt);
  EXPECT_EQ(w.source, CameraMotionSource::Registration);
  EXPECT_LT((w.motion.isometry().matrix() - T.matrix()).norm(), 1e-9);
  // Poses of an earlier stage win.
  const Eigen::Isometry3d T_w_c0 = pose({1, 0, 0}, 0.2, {1, 2, 3});
  const Eigen::Isometry3d T_w_c1 = T_w_c0 * T.inverse();
  const auto fromPoses = estimator.estimate({}, {}, std::nullopt, T_w_c0, T_w_c1);
  EXPECT_EQ(fromPoses.source, CameraMotionSource::Poses);
  EXPECT_LT((fromPoses.motion.isometry().matrix() - T.matrix()).norm(), 1e-9);
  // No background at all: the previous motion (constant velocity).
  const auto blind = estimator.estimate({}, {}, std::nullopt, std::nullopt, std::nullopt);
  EXPECT_EQ(blind.source, CameraMotionSource::ConstantVelocity);
  EXPECT_LT((blind.motion.isometry().matrix() - T.matrix()).norm(), 1e-9);
}

// Without background pairs the gyro's rotation takes the median of the recent registered
// translations, not the last one: the last registration before a person fills the view is the
// one made on the fewest pairs.
TEST(CameraMotion, TheConstantVelocityTranslationIsTheMedianOfTheRecentOnes) {
  std::mt19937 gen(3);
  std::uniform_real_distribution<double> u(-2, 2);
  const Eigen::Vector3d t(0.015, 0.003, 0.0);  // m per frame
  CameraMotionEstimator estimator;
  const auto registerWith = [&](const Eigen::Vector3d& translation) {
    std::vector<Eigen::Vector3d> p, q;
    for (int i = 0; i < 40; ++i) {
      p.emplace_back(u(gen), u(gen) / 2, 4 + u(gen) / 2);
      q.push_back(p.back() + translation);
    }
    return estimator.estimate(p, q, Eigen::Matrix3d::Identity(), std::nullopt, std::nullopt);
  };
  for (int k = 0; k < 9; ++k) registerWith(t);
  const Eigen::Vector3d off = t + Eigen::Vector3d(0, 0, -0.025);  // 2.5 cm off in depth
  ASSERT_LT((registerWith(off).motion.t - off).norm(), 1e-9);
  const auto blind =
      estimator.estimate({}, {}, Eigen::Matrix3d::Identity(), std::nullopt, std::nullopt);
  EXPECT_EQ(blind.source, CameraMotionSource::ImuRotationConstantVelocity);
  EXPECT_LT((blind.motion.t - t).norm(), 1e-9)
      << "the median, not the last (" << off.transpose() << ")";
}

}  // namespace
}  // namespace dynslam::frontend
