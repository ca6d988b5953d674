// synthesizeImu: exact measurements (gravity, lever arm, extrinsic rotation) against finite
// differences of the IMU pose, the noise and bias statistics, determinism and the error cases.
// The integration test (IMU samples reproduce the trajectory) is in ImuIntegrationTest.cpp.
#include <dynslam/sim/ImuSynthesizer.h>
#include <dynslam/sim/TrajectoryPaths.h>

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace dynslam::sim {
namespace {

SplineTrajectory stationary(const Eigen::Vector3d& position, const Eigen::Vector3d& ypr,
                            double duration) {
  const auto n = static_cast<std::size_t>(std::ceil(duration / 0.5)) + 3;
  return SplineTrajectory(std::vector<Eigen::Vector3d>(n, position),
                          std::vector<Eigen::Vector3d>(n, ypr), 0.5);
}

Eigen::Isometry3d extrinsic(const Eigen::Vector3d& rotation_vector, const Eigen::Vector3d& r) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  if (rotation_vector.norm() > 0) {
    T.linear() = Eigen::AngleAxisd(rotation_vector.norm(), rotation_vector.normalized()).matrix();
  }
  T.translation() = r;
  return T;
}

ImuNoiseOptions exactOptions() {
  ImuNoiseOptions o;
  o.noise = false;
  return o;
}

TEST(ImuSynthesizer, StationaryLevelImuMeasuresGravityAndItsBiases) {
  ImuNoiseOptions options = exactOptions();
  options.gyro_bias0 = Eigen::Vector3d(0.01, -0.02, 0.03);
  options.acc_bias0 = Eigen::Vector3d(0.1, 0.2, -0.3);
  std::mt19937_64 rng(1);
  const auto samples = synthesizeImu(stationary({1, 2, 3}, {0.7, 0, 0}, 2.0), 0.0, 2.0, options,
                                     Eigen::Isometry3d::Identity(), rng);
  ASSERT_EQ(samples.size(), 401u);
  for (const ImuMeasurement& m : samples) {
    EXPECT_NEAR((m.gyro - options.gyro_bias0).norm(), 0, 1e-15);
    EXPECT_NEAR((m.acc - options.acc_bias0 - Eigen::Vector3d(0, 0, 9.81)).norm(), 0, 1e-14);
    EXPECT_EQ(m.gyro_bias, options.gyro_bias0);
    EXPECT_EQ(m.acc_bias, options.acc_bias0);
  }
  EXPECT_EQ(rng(), std::mt19937_64(1)());  // noise = false draws nothing
}

TEST(ImuSynthesizer, RotatedImuSeesGravityInItsOwnFrame) {
  const Eigen::Vector3d ypr(0.3, -0.2, 0.4);
  const Eigen::Isometry3d T_body_imu = extrinsic({0.5, -1.0, 2.0}, {0.05, 0.02, -0.01});
  std::mt19937_64 rng(1);
  const auto samples =
      synthesizeImu(stationary({0, 0, 0}, ypr, 1.0), 0.0, 1.0, exactOptions(), T_body_imu, rng);
  const Eigen::Matrix3d R_world_imu = rotationFromYawPitchRoll(ypr) * T_body_imu.linear();
  for (const ImuMeasurement& m : samples) {
    EXPECT_NEAR((m.acc - R_world_imu.transpose() * Eigen::Vector3d(0, 0, 9.81)).norm(), 0, 1e-13);
    EXPECT_NEAR(m.gyro.norm(), 0, 1e-15);
  }
}

TEST(ImuSynthesizer, OffsetImuOnASpinningBodyFeelsTheCentripetalAcceleration) {
  // Yaw controls affine in time give an exactly constant yaw rate w about the body z axis.
  const double w = 2.0, r = 0.1;
  std::vector<Eigen::Vector3d> positions(8, Eigen::Vector3d::Zero()), ypr;
  for (int i = 0; i < 8; ++i) ypr.emplace_back(w * (i - 1) * 0.25, 0, 0);
  const SplineTrajectory spin(positions, ypr, 0.25);
  std::mt19937_64 rng(1);
  const auto samples = synthesizeImu(spin, 0.0, spin.endTime(), exactOptions(),
                                     extrinsic({0, 0, 0}, {r, 0, 0}), rng);
  for (const ImuMeasurement& m : samples) {
    EXPECT_NEAR((m.gyro - Eigen::Vector3d(0, 0, w)).norm(), 0, 1e-12);
    EXPECT_NEAR((m.acc - Eigen::Vector3d(-w * w * r, 0, 9.81)).norm(), 0, 1e-12);
  }
}

TEST(ImuSynthesizer, ExactKinematicsMatchFiniteDifferencesOfTheImuPose) {
  // Independent of the lever-arm formula: difference the IMU frame's own pose T_wb(t) * T_bi.
  const SplineTrajectory orbit =
      makeOrbit({0, 0, 0}, 1.5, 1.4, 8.0, 6.0, {0.3, 0.2, 1.0}, 0.05, 0.25, 1.0);
  const Eigen::Isometry3d T_body_imu = extrinsic({0.3, 0.9, -0.4}, {0.06, 0.0, 0.08});
  const auto imuPose = [&](double t) { return orbit.sample(t).T_world_body * T_body_imu; };
  const double h = 1e-4;
  double worst_v = 0, worst_w = 0, worst_f = 0;
  for (double t = 0.013; t < 5.9; t += 0.05) {
    const ImuKinematics k = imuKinematicsAt(orbit.sample(t), T_body_imu, 9.81);
    const Eigen::Isometry3d before = imuPose(t - h), now = imuPose(t), after = imuPose(t + h);
    EXPECT_NEAR((k.T_world_imu.matrix() - now.matrix()).norm(), 0, 1e-14);
    const Eigen::Vector3d v = (after.translation() - before.translation()) / (2 * h);
    const Eigen::Vector3d a =
        (after.translation() - 2 * now.translation() + before.translation()) / (h * h);
    const Eigen::AngleAxisd delta(before.linear().transpose() * after.linear());
    const Eigen::Vector3d w = delta.angle() * delta.axis() / (2 * h);
    const Eigen::Vector3d f = now.linear().transpose() * (a - Eigen::Vector3d(0, 0, -9.81));
    worst_v = std::max(worst_v, (k.velocity_world - v).norm());
    worst_w = std::max(worst_w, (k.angular_velocity - w).norm());
    worst_f = std::max(worst_f, (k.specific_force - f).norm());
  }
  EXPECT_LT(worst_v, 1e-7);
  EXPECT_LT(worst_w, 1e-7);
  EXPECT_LT(worst_f, 1e-5);  // second difference: rounding ~ 1e-16 * |p| / h^2
}

TEST(ImuSynthesizer, WhiteNoiseStdMatchesTheDiscretisedDensity) {
  ImuNoiseOptions options;  // the D455 defaults, noise on
  const SplineTrajectory still = stationary({0, 0, 1}, {0.2, 0.1, -0.1}, 20.0);
  const Eigen::Isometry3d T_body_imu = extrinsic({0.1, 0.2, 0.3}, {0.1, 0, 0});
  std::mt19937_64 rng(2024);
  const auto noisy = synthesizeImu(still, 0.0, 20.0, options, T_body_imu, rng);
  const ImuKinematics exact = imuKinematicsAt(still.sample(0), T_body_imu, options.gravity);
  ASSERT_EQ(noisy.size(), 4001u);
  Eigen::Array3d gyro_sum = Eigen::Array3d::Zero(), gyro_sq = gyro_sum, acc_sum = gyro_sum,
                 acc_sq = gyro_sum;
  for (const ImuMeasurement& m : noisy) {
    // The reported true bias lets us isolate the white noise exactly.
    const Eigen::Array3d g = (m.gyro - m.gyro_bias - exact.angular_velocity).array();
    const Eigen::Array3d a = (m.acc - m.acc_bias - exact.specific_force).array();
    gyro_sum += g;
    gyro_sq += g * g;
    acc_sum += a;
    acc_sq += a * a;
  }
  const double n = static_cast<double>(noisy.size());
  const Eigen::Array3d gyro_std = (gyro_sq / n - (gyro_sum / n).square()).sqrt();
  const Eigen::Array3d acc_std = (acc_sq / n - (acc_sum / n).square()).sqrt();
  const double gyro_expected = options.gyro_noise_density * std::sqrt(options.rate_hz);
  const double acc_expected = options.acc_noise_density * std::sqrt(options.rate_hz);
  for (int axis = 0; axis < 3; ++axis) {
    EXPECT_NEAR(gyro_std[axis] / gyro_expected, 1.0, 0.1) << axis;
    EXPECT_NEAR(acc_std[axis] / acc_expected, 1.0, 0.1) << axis;
  }
}

TEST(ImuSynthesizer, BiasesRandomWalkWithSqrtTimeGrowth) {
  ImuNoiseOptions options;
  options.gyro_bias0 = Eigen::Vector3d(0.001, 0.002, 0.003);
  options.acc_bias0 = Eigen::Vector3d(-0.05, 0.0, 0.05);
  const SplineTrajectory still = stationary({0, 0, 0}, {0, 0, 0}, 2.0);
  const int seeds = 300;
  const std::size_t checkpoints[2] = {50, 400};  // 0.25 s and 2 s at 200 Hz
  double gyro_sq[2] = {0, 0}, acc_sq[2] = {0, 0};
  for (int seed = 0; seed < seeds; ++seed) {
    std::mt19937_64 rng(1000 + seed);
    const auto samples =
        synthesizeImu(still, 0.0, 2.0, options, Eigen::Isometry3d::Identity(), rng);
    ASSERT_EQ(samples[0].gyro_bias, options.gyro_bias0);  // the walk starts at bias0
    for (int c = 0; c < 2; ++c) {
      gyro_sq[c] += (samples[checkpoints[c]].gyro_bias - options.gyro_bias0).squaredNorm();
      acc_sq[c] += (samples[checkpoints[c]].acc_bias - options.acc_bias0).squaredNorm();
    }
  }
  for (int c = 0; c < 2; ++c) {
    // Zero-mean increments: the RMS over seeds and axes estimates the std, rw * sqrt(t).
    const double elapsed = static_cast<double>(checkpoints[c]) / options.rate_hz;
    const double gyro_std = std::sqrt(gyro_sq[c] / (3.0 * seeds));
    const double acc_std = std::sqrt(acc_sq[c] / (3.0 * seeds));
    EXPECT_NEAR(gyro_std / (options.gyro_bias_random_walk * std::sqrt(elapsed)), 1.0, 0.1) << c;
    EXPECT_NEAR(acc_std / (options.acc_bias_random_walk * std::sqrt(elapsed)), 1.0, 0.1) << c;
  }
}

TEST(ImuSynthesizer, SameSeedSameSamplesOtherSeedOtherSamples) {
  const SplineTrajectory orbit = makeOrbit({0, 0, 0}, 1.0, 1.4, 10.0, 3.0, {0, 0, 1}, 0.02, 0.25);
  const Eigen::Isometry3d T_body_imu = extrinsic({0.1, 0, 0}, {0, 0.1, 0});
  std::mt19937_64 a(77), b(77), c(78);
  const auto first = synthesizeImu(orbit, 0.5, 2.5, ImuNoiseOptions(), T_body_imu, a);
  const auto again = synthesizeImu(orbit, 0.5, 2.5, ImuNoiseOptions(), T_body_imu, b);
  const auto other = synthesizeImu(orbit, 0.5, 2.5, ImuNoiseOptions(), T_body_imu, c);
  ASSERT_EQ(first.size(), again.size());
  ASSERT_EQ(first.size(), 401u);
  EXPECT_DOUBLE_EQ(first.front().t, 0.5);
  EXPECT_DOUBLE_EQ(first.back().t, 2.5);
  for (std::size_t i = 0; i < first.size(); ++i) {
    EXPECT_EQ(first[i].t, again[i].t);
    EXPECT_EQ(first[i].gyro, again[i].gyro);
    EXPECT_EQ(first[i].acc, again[i].acc);
    EXPECT_EQ(first[i].acc_bias, again[i].acc_bias);
  }
  EXPECT_NE(first[10].gyro, other[10].gyro);
}

TEST(ImuSynthesizer, RejectsBadRangesAndOptions) {
  const SplineTrajectory still = stationary({0, 0, 0}, {0, 0, 0}, 2.0);
  const Eigen::Isometry3d I = Eigen::Isometry3d::Identity();
  std::mt19937_64 rng(1);
  EXPECT_THROW(synthesizeImu(still, 0.0, 5.0, ImuNoiseOptions(), I, rng), std::out_of_range);
  EXPECT_THROW(synthesizeImu(still, -0.1, 1.0, ImuNoiseOptions(), I, rng), std::out_of_range);
  EXPECT_THROW(synthesizeImu(still, 1.0, 0.5, ImuNoiseOptions(), I, rng), std::invalid_argument);
  ImuNoiseOptions bad;
  bad.rate_hz = 0;
  EXPECT_THROW(synthesizeImu(still, 0.0, 1.0, bad, I, rng), std::invalid_argument);
  bad = ImuNoiseOptions();
  bad.acc_noise_density = -1;
  EXPECT_THROW(synthesizeImu(still, 0.0, 1.0, bad, I, rng), std::invalid_argument);
}

}  // namespace
}  // namespace dynslam::sim
