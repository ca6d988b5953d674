#include <dynslam/sim/DiffDriveMotion.h>
#include <dynslam/sim/ImuSynthesizer.h>

#include <gtest/gtest.h>

#include <cmath>

namespace dynslam::sim {
namespace {

TEST(DiffDriveMotion, ReachesItsSpeedsAtTheLimitsAndDrivesACircle) {
  DiffDriveLimits limits;  // 1 m/s^2, 3 rad/s^2
  DiffDriveMotion robot(1.0, 2.0, 0.0, 0.3, limits);
  robot.command(0.5, 0.5);
  const double dt = 0.005;
  robot.step(dt);
  EXPECT_NEAR(robot.speed(), 0.005, 1e-12);  // 1 m/s^2 for 5 ms
  EXPECT_NEAR(robot.turnRate(), 0.015, 1e-12);
  for (int i = 0; i < 200; ++i) robot.step(dt);  // 1 s: both reached
  EXPECT_NEAR(robot.speed(), 0.5, 1e-12);
  EXPECT_NEAR(robot.turnRate(), 0.5, 1e-12);
  // From here a circle of radius v / w = 1 m: a whole turn later it is back.
  const Eigen::Vector3d before = robot.sample().T_world_body.translation();
  const int steps = static_cast<int>(std::round(2 * M_PI / 0.5 / dt));
  for (int i = 0; i < steps; ++i) robot.step(dt);
  const auto s = robot.sample();
  EXPECT_NEAR((s.T_world_body.translation() - before).norm(), 0, 2e-3);
  EXPECT_NEAR(s.T_world_body.translation().z(), 0.3, 1e-12);
  EXPECT_NEAR(s.acceleration_world.norm(), 0.25, 1e-9);  // v * w, towards the centre
  EXPECT_NEAR(s.velocity_world.norm(), 0.5, 1e-12);
}

TEST(DiffDriveMotion, CommandsAreClampedToTheLimits) {
  DiffDriveLimits limits;
  limits.max_speed = 0.3;
  limits.max_turn_rate = 0.2;
  DiffDriveMotion robot(0, 0, 0, 0, limits);
  robot.command(5.0, -5.0);
  for (int i = 0; i < 400; ++i) robot.step(0.005);
  EXPECT_NEAR(robot.speed(), 0.3, 1e-12);
  EXPECT_NEAR(robot.turnRate(), -0.2, 1e-12);
  EXPECT_THROW(DiffDriveMotion(0, 0, 0, 0, DiffDriveLimits{0, 1, 1, 1}), std::invalid_argument);
}

/// The IMU's exact reports, integrated, give the motion back: what the estimator needs of a
/// closed-loop robot.
TEST(DiffDriveMotion, ItsImuIntegratesBackToItsPath) {
  DiffDriveMotion robot(0, 0, 0.3, 0.25, DiffDriveLimits{});
  ImuNoiseOptions o;
  o.noise = false;
  std::mt19937_64 rng(1);
  ImuNoiseProcess imu(o, rng);
  const double dt = 0.005;
  Eigen::Isometry3d T_body_imu = Eigen::Isometry3d::Identity();
  T_body_imu.translation() = Eigen::Vector3d(0.1, 0.0, 0.5);  // a lever arm
  auto state = imuKinematicsAt(robot.sample(), T_body_imu, o.gravity);
  Eigen::Vector3d p = state.T_world_imu.translation(), v = state.velocity_world;
  Eigen::Matrix3d R = state.T_world_imu.linear();
  for (int i = 0; i < 2000; ++i) {  // 10 s of changing commands
    const double t = i * dt;
    if (i % 100 == 0) robot.command(0.6 * std::sin(0.7 * t) + 0.2, 0.8 * std::cos(1.3 * t));
    const ImuMeasurement before =
        imu.measure(t, imuKinematicsAt(robot.sample(), T_body_imu, o.gravity));
    robot.step(dt);
    const ImuMeasurement after =
        imu.measure(t + dt, imuKinematicsAt(robot.sample(), T_body_imu, o.gravity));
    // Midpoint integration of the reported rates and specific forces.
    const Eigen::Vector3d w = 0.5 * (before.gyro + after.gyro);
    const Eigen::Matrix3d R1 =
        w.norm() > 0 ? Eigen::Matrix3d(R * Eigen::AngleAxisd(w.norm() * dt, w.normalized())) : R;
    const Eigen::Vector3d g(0, 0, -o.gravity);
    const Eigen::Vector3d a = 0.5 * (R * before.acc + R1 * after.acc) + g;
    p += v * dt + 0.5 * a * dt * dt;
    v += a * dt;
    R = R1;
  }
  const auto truth = imuKinematicsAt(robot.sample(), T_body_imu, o.gravity);
  EXPECT_LT((p - truth.T_world_imu.translation()).norm(), 0.01);
  EXPECT_LT((v - truth.velocity_world).norm(), 0.005);
  EXPECT_LT(Eigen::AngleAxisd(R.transpose() * truth.T_world_imu.linear()).angle(), 1e-3);
}

}  // namespace
}  // namespace dynslam::sim
