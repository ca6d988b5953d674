// SplineTrajectory: the documented time mapping, analytic derivatives against central
// differences, continuity at knots, the Euler convention and the error cases.
#include <dynslam/sim/SplineTrajectory.h>

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>
#include <string>

namespace dynslam::sim {
namespace {

constexpr double kPi = 3.14159265358979323846;

/// Runs `f`, expects it to throw E, and returns the message (so tests can check it is helpful).
template <typename E, typename F>
std::string messageOf(F&& f) {
  try {
    f();
  } catch (const E& e) {
    return e.what();
  } catch (const std::exception& e) {
    ADD_FAILURE() << "threw the wrong type: " << e.what();
    return "";
  }
  ADD_FAILURE() << "did not throw";
  return "";
}

struct Controls {
  std::vector<Eigen::Vector3d> positions, ypr;
};

/// Random but reproducible controls with large enough angles to exercise the Euler matrix
/// (pitch up to ~70 degrees, roll up to ~60 degrees).
Controls randomControls(unsigned seed, std::size_t n) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  Controls c;
  double yaw = 0;
  for (std::size_t i = 0; i < n; ++i) {
    Eigen::Vector3d p, a;
    for (int axis = 0; axis < 3; ++axis) p[axis] = 3.0 * uniform(rng);
    yaw += uniform(rng);
    a << yaw, 1.2 * uniform(rng), 0;
    a[2] = uniform(rng);
    c.positions.push_back(p);
    c.ypr.push_back(a);
  }
  return c;
}

SplineTrajectory randomTrajectory(unsigned seed, std::size_t n, double knot, double t0) {
  const Controls c = randomControls(seed, n);
  return SplineTrajectory(c.positions, c.ypr, knot, t0);
}

/// log(R) as a rotation vector.
Eigen::Vector3d logMap(const Eigen::Matrix3d& R) {
  const Eigen::AngleAxisd aa(R);
  return aa.angle() * aa.axis();
}

TEST(SplineTrajectory, TimeMappingReproducesAffineControlsExactly) {
  // Controls that are affine in their documented times t_i = t0 + (i - 1) * dt must come back
  // as the same affine function of t: this pins down the time mapping.
  const double t0 = 2.5, dt = 0.4;
  const Eigen::Vector3d p0(1, -2, 0.5), p_rate(0.3, 0.1, -0.2);
  const Eigen::Vector3d a0(0.2, -0.1, 0.05), a_rate(0.5, 0.05, -0.02);
  std::vector<Eigen::Vector3d> positions, ypr;
  for (int i = 0; i < 9; ++i) {
    const double t_i = t0 + (i - 1) * dt;
    positions.push_back(p0 + p_rate * t_i);
    ypr.push_back(a0 + a_rate * t_i);
  }
  const SplineTrajectory trajectory(positions, ypr, dt, t0);
  EXPECT_DOUBLE_EQ(trajectory.startTime(), t0);
  EXPECT_DOUBLE_EQ(trajectory.endTime(), t0 + 6 * dt);
  EXPECT_EQ(trajectory.controlPointCount(), 9u);
  EXPECT_DOUBLE_EQ(trajectory.knotInterval(), dt);
  for (double t = t0; t <= trajectory.endTime(); t += 0.037) {
    const TrajectorySample s = trajectory.sample(t);
    EXPECT_NEAR((s.T_world_body.translation() - (p0 + p_rate * t)).norm(), 0, 1e-12) << t;
    EXPECT_NEAR((s.velocity_world - p_rate).norm(), 0, 1e-12) << t;
    EXPECT_NEAR(s.acceleration_world.norm(), 0, 1e-11) << t;
    EXPECT_NEAR((s.yaw_pitch_roll - (a0 + a_rate * t)).norm(), 0, 1e-12) << t;
  }
}

TEST(SplineTrajectory, ValueAtKnotIsTheOneFourOneAverage) {
  const SplineTrajectory trajectory = randomTrajectory(7, 8, 0.3, -1.0);
  const std::vector<Eigen::Vector3d> c = randomControls(7, 8).positions;
  for (int j = 0; j <= 5; ++j) {
    const Eigen::Vector3d expected = (c[j] + 4 * c[j + 1] + c[j + 2]) / 6.0;
    const double t = -1.0 + j * 0.3;
    EXPECT_NEAR((trajectory.sample(t).T_world_body.translation() - expected).norm(), 0, 1e-12);
  }
}

TEST(SplineTrajectory, AnalyticDerivativesMatchCentralDifferences) {
  const SplineTrajectory trajectory = randomTrajectory(42, 12, 0.5, 1.0);
  const double h = 1e-5;
  std::mt19937_64 rng(1);
  // Stay h away from the knots, where the third derivative (not checked) jumps.
  std::uniform_real_distribution<double> segment_u(0.01, 0.99);
  double worst_v = 0, worst_a = 0, worst_w = 0, worst_alpha = 0;
  for (int k = 0; k < 9; ++k) {
    for (int trial = 0; trial < 20; ++trial) {
      const double t = 1.0 + (k + segment_u(rng)) * 0.5;
      const TrajectorySample s = trajectory.sample(t);
      const TrajectorySample before = trajectory.sample(t - h), after = trajectory.sample(t + h);
      const Eigen::Vector3d v_numeric =
          (after.T_world_body.translation() - before.T_world_body.translation()) / (2 * h);
      const Eigen::Vector3d a_numeric = (after.velocity_world - before.velocity_world) / (2 * h);
      // Body-frame rate: R(t-h)^T R(t+h) = Exp(2 h omega_body) + O(h^3).
      const Eigen::Vector3d w_numeric =
          logMap(before.T_world_body.linear().transpose() * after.T_world_body.linear()) / (2 * h);
      const Eigen::Vector3d alpha_numeric =
          (after.angular_velocity_body - before.angular_velocity_body) / (2 * h);
      worst_v = std::max(worst_v, (s.velocity_world - v_numeric).norm());
      worst_a = std::max(worst_a, (s.acceleration_world - a_numeric).norm());
      worst_w = std::max(worst_w, (s.angular_velocity_body - w_numeric).norm());
      worst_alpha = std::max(worst_alpha, (s.angular_acceleration_body - alpha_numeric).norm());
    }
  }
  // Truncation O(h^2 * third derivative) ~ 1e-9 and rounding ~ 1e-16 * |value| / h ~ 1e-10:
  // second derivatives are differenced from the analytic first ones, so the same bound holds.
  EXPECT_LT(worst_v, 1e-7);
  EXPECT_LT(worst_a, 1e-7);
  EXPECT_LT(worst_w, 1e-7);
  EXPECT_LT(worst_alpha, 1e-6);
}

TEST(SplineTrajectory, PoseVelocityAndAccelerationAreContinuousAtKnots) {
  const SplineTrajectory trajectory = randomTrajectory(3, 10, 0.25, 0.0);
  // Both sides of each knot, 2e-12 s apart: the natural change is ~1e-9 of the derivatives
  // (|acceleration| ~ 100 m/s^2 here), a discontinuity would be O(1).
  const double eps = 1e-12;
  for (int j = 1; j < 7; ++j) {
    const double t = j * 0.25;
    const TrajectorySample a = trajectory.sample(t - eps), b = trajectory.sample(t + eps);
    EXPECT_NEAR((a.T_world_body.translation() - b.T_world_body.translation()).norm(), 0, 1e-8);
    EXPECT_NEAR((a.velocity_world - b.velocity_world).norm(), 0, 1e-8);
    EXPECT_NEAR((a.acceleration_world - b.acceleration_world).norm(), 0, 1e-8);
    EXPECT_NEAR((a.angular_velocity_body - b.angular_velocity_body).norm(), 0, 1e-8);
    EXPECT_NEAR((a.angular_acceleration_body - b.angular_acceleration_body).norm(), 0, 1e-8);
  }
}

TEST(SplineTrajectory, EulerConventionIsZyxWithBodyXForward) {
  const Eigen::Vector3d x = Eigen::Vector3d::UnitX(), y = Eigen::Vector3d::UnitY();
  // Yaw +90 degrees: forward points to world +y.
  EXPECT_NEAR((rotationFromYawPitchRoll({kPi / 2, 0, 0}) * x - y).norm(), 0, 1e-15);
  // Pitch +30 degrees: the nose goes down.
  const Eigen::Vector3d nose = rotationFromYawPitchRoll({0, kPi / 6, 0}) * x;
  EXPECT_NEAR(nose.z(), -0.5, 1e-15);
  // Roll +30 degrees: the left side goes up.
  EXPECT_NEAR((rotationFromYawPitchRoll({0, 0, kPi / 6}) * y).z(), 0.5, 1e-15);
  // The composition order: Rz * Ry * Rx.
  const Eigen::Vector3d ypr(0.3, -0.4, 0.5);
  const Eigen::Matrix3d expected = (Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitZ()) *
                                    Eigen::AngleAxisd(-0.4, Eigen::Vector3d::UnitY()) *
                                    Eigen::AngleAxisd(0.5, Eigen::Vector3d::UnitX()))
                                       .toRotationMatrix();
  EXPECT_NEAR((rotationFromYawPitchRoll(ypr) - expected).norm(), 0, 1e-15);
  // A pure yaw rate is a body z rate only when level; with roll it leaks into body y.
  const Eigen::Vector3d w = eulerRatesToBodyRates({0, 0, kPi / 2}) * Eigen::Vector3d(1, 0, 0);
  EXPECT_NEAR((w - Eigen::Vector3d(0, 1, 0)).norm(), 0, 1e-15);
}

TEST(SplineTrajectory, RejectsBadControlsWithClearMessages) {
  const std::vector<Eigen::Vector3d> three(3, Eigen::Vector3d::Zero()),
      four(4, Eigen::Vector3d::Zero()), five(5, Eigen::Vector3d::Zero());
  EXPECT_NE(messageOf<std::invalid_argument>([&] {
              SplineTrajectory(three, three, 0.1);
            }).find("at least 4 control points"),
            std::string::npos);
  EXPECT_NE(messageOf<std::invalid_argument>([&] {
              SplineTrajectory(four, five, 0.1);
            }).find("must match"),
            std::string::npos);
  EXPECT_NE(messageOf<std::invalid_argument>([&] {
              SplineTrajectory(four, four, 0.0);
            }).find("knot_interval"),
            std::string::npos);
  EXPECT_NE(messageOf<std::invalid_argument>([&] {
              SplineTrajectory(four, four, -1.0);
            }).find("knot_interval"),
            std::string::npos);
  EXPECT_NE(messageOf<std::invalid_argument>([&] {
              SplineTrajectory(four, four, NAN);
            }).find("knot_interval"),
            std::string::npos);
  std::vector<Eigen::Vector3d> wrapped(4, Eigen::Vector3d::Zero());
  wrapped[2][0] = 3.1;
  wrapped[3][0] = -3.1;  // a wrapped yaw: a 6.2 rad jump
  EXPECT_NE(messageOf<std::invalid_argument>([&] {
              SplineTrajectory(four, wrapped, 0.1);
            }).find("unwrap"),
            std::string::npos);
  std::vector<Eigen::Vector3d> not_finite = four;
  not_finite[1].x() = NAN;
  EXPECT_NE(messageOf<std::invalid_argument>([&] {
              SplineTrajectory(not_finite, four, 0.1);
            }).find("not finite"),
            std::string::npos);
}

TEST(SplineTrajectory, TimesOutsideTheRangeThrowButRoundingIsClamped) {
  const SplineTrajectory trajectory = randomTrajectory(5, 6, 0.1, 10.0);
  EXPECT_NE(messageOf<std::out_of_range>([&] { trajectory.sample(9.99); }).find("outside"),
            std::string::npos);
  EXPECT_THROW(trajectory.sample(trajectory.endTime() + 1e-6), std::out_of_range);
  EXPECT_THROW(trajectory.sample(NAN), std::out_of_range);
  // 10 + 3 * 0.1 is not exactly representable; times a few ulps off still evaluate.
  const double end = trajectory.endTime();
  const TrajectorySample at_end = trajectory.sample(std::nextafter(end, 1e9));
  EXPECT_NEAR(
      (at_end.T_world_body.translation() - trajectory.sample(end).T_world_body.translation())
          .norm(),
      0, 1e-15);
  EXPECT_NO_THROW(trajectory.sample(std::nextafter(10.0, 0.0)));
}

TEST(SplineTrajectory, EpochTimestampsSampleOnTheirGrid) {
  // Rawlog stamps are seconds since the Unix epoch (~1.7e9, an ulp of 2.4e-7 s): a grid built by
  // uniformSampleTimes over the whole range must evaluate, including its rounded last sample.
  const double t0 = 1.7e9 + 0.123;
  const SplineTrajectory trajectory = randomTrajectory(9, 14, 0.1, t0);  // 1.1 s long
  const std::vector<double> times =
      uniformSampleTimes(trajectory.startTime(), trajectory.endTime(), 30.0);
  // endTime() - startTime() comes out 1.1 - 9.5e-8 s here (rounded to an ulp of 1.7e9), so
  // 33 frame periods hold only thanks to the rounding slack.
  EXPECT_EQ(times.size(), 34u);
  for (const double t : times) EXPECT_NO_THROW(trajectory.sample(t)) << t - t0;
}

TEST(SplineTrajectory, UniformSampleTimesFollowTheSharedRule) {
  const std::vector<double> times = uniformSampleTimes(0.0, 10.0, 200.0);
  ASSERT_EQ(times.size(), 2001u);
  EXPECT_DOUBLE_EQ(times.front(), 0.0);
  EXPECT_DOUBLE_EQ(times.back(), 10.0);
  EXPECT_DOUBLE_EQ(times[37], 37 / 200.0);
  const std::vector<double> partial = uniformSampleTimes(0.1, 0.35, 10.0);
  ASSERT_EQ(partial.size(), 3u);
  EXPECT_DOUBLE_EQ(partial[2], 0.1 + 0.2);
  // 0.3 / 0.1 is 2.9999999999999996 in doubles: the tolerance keeps the last sample.
  EXPECT_EQ(uniformSampleTimes(0.0, 0.3, 10.0).size(), 4u);
  EXPECT_EQ(uniformSampleTimes(1.0, 1.0, 30.0).size(), 1u);
  EXPECT_THROW(uniformSampleTimes(0.0, 1.0, 0.0), std::invalid_argument);
  EXPECT_THROW(uniformSampleTimes(0.0, 1.0, -5.0), std::invalid_argument);
  EXPECT_THROW(uniformSampleTimes(1.0, 0.0, 10.0), std::invalid_argument);
}

}  // namespace
}  // namespace dynslam::sim
