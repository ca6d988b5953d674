// makeOrbit / makeDrivePath: the curves go where their documentation says, look where it says,
// and reject motion the spline cannot represent.
#include <dynslam/sim/TrajectoryPaths.h>

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace dynslam::sim {
namespace {

constexpr double kPi = 3.14159265358979323846;

double angleBetween(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::atan2(a.cross(b).norm(), a.dot(b));
}

TEST(TrajectoryPaths, OrbitCirclesTheCentreAndLooksAtTheTarget) {
  const Eigen::Vector3d center(2.5, 3.0, 0.0), look_at(2.5, 3.0, 1.2);
  const double radius = 1.3, height = 1.4, period = 24.0, knot = 0.5;
  const SplineTrajectory orbit =
      makeOrbit(center, radius, height, period, 60.0, look_at, 0.0, knot);
  EXPECT_DOUBLE_EQ(orbit.startTime(), 0.0);
  EXPECT_GE(orbit.endTime(), 60.0);
  EXPECT_LT(orbit.endTime(), 60.0 + knot + 1e-9);

  double worst_knot_radius = 0, worst_radius = 0, worst_look = 0;
  for (double t = 0; t <= 60.0; t += knot / 8) {
    const TrajectorySample s = orbit.sample(t);
    const Eigen::Vector3d p = s.T_world_body.translation();
    const double r_error = std::abs((p - center).head<2>().norm() - radius);
    worst_radius = std::max(worst_radius, r_error);
    if (std::abs(std::remainder(t, knot)) < 1e-9)
      worst_knot_radius = std::max(worst_knot_radius, r_error);
    EXPECT_NEAR(p.z(), height, 1e-12);
    const Eigen::Vector3d forward = s.T_world_body.linear().col(0);
    worst_look = std::max(worst_look, angleBetween(forward, look_at - p));
    // Counter-clockwise at 2 pi / period.
    EXPECT_NEAR(s.angular_velocity_body.norm(), 2 * kPi / period, 1e-9);
  }
  EXPECT_LT(worst_knot_radius, 1e-12);     // pre-scaled: on the circle at every knot
  EXPECT_LT(worst_radius, 1e-4 * radius);  // and close between them (48 knots per turn)
  EXPECT_LT(worst_look, 1e-3);             // rad
  // Two and a half turns: the yaw is unwrapped, not folded into (-pi, pi].
  const double yaw_travel =
      orbit.sample(60.0).yaw_pitch_roll[0] - orbit.sample(0).yaw_pitch_roll[0];
  EXPECT_NEAR(yaw_travel, 2.5 * 2 * kPi, 1e-9);
}

TEST(TrajectoryPaths, OrbitBobsWithTheRequestedAmplitude) {
  const Eigen::Vector3d center(0, 0, 0), look_at(0, 0, 1.0);
  const double bob = 0.05, knot = 0.25;  // 1 Hz bob: 4 knots per bob period, the limit
  const SplineTrajectory orbit = makeOrbit(center, 1.5, 1.4, -10.0, 10.0, look_at, bob, knot, 1.0);
  double z_min = 1e9, z_max = -1e9;
  for (double t = 0; t <= 10.0; t += 0.25) {
    // Knots sit at the bob's quarter periods: its peaks and troughs.
    const double z = orbit.sample(t).T_world_body.translation().z();
    z_min = std::min(z_min, z);
    z_max = std::max(z_max, z);
  }
  EXPECT_NEAR(z_max - 1.4, bob, 1e-12);
  EXPECT_NEAR(1.4 - z_min, bob, 1e-12);
  // Negative period: clockwise.
  EXPECT_LT(orbit.sample(5.0).angular_velocity_body.dot(
                orbit.sample(5.0).T_world_body.linear().transpose() * Eigen::Vector3d::UnitZ()),
            0);
}

TEST(TrajectoryPaths, OrbitRejectsMotionTheSplineCannotRepresent) {
  const Eigen::Vector3d c(0, 0, 0), look(0, 0, 1);
  EXPECT_THROW(makeOrbit(c, 1.0, 1.4, 1.0, 5.0, look, 0.0, 0.5), std::invalid_argument);
  EXPECT_THROW(makeOrbit(c, 1.0, 1.4, 20.0, 5.0, look, 0.02, 0.5, 2.0), std::invalid_argument);
  EXPECT_THROW(makeOrbit(c, 0.0, 1.4, 20.0, 5.0, look, 0.0, 0.5), std::invalid_argument);
  EXPECT_THROW(makeOrbit(c, 1.0, 1.4, 0.0, 5.0, look, 0.0, 0.5), std::invalid_argument);
  EXPECT_THROW(makeOrbit(c, 1.0, 1.4, 20.0, 0.0, look, 0.0, 0.5), std::invalid_argument);
  EXPECT_THROW(makeOrbit(c, 1.0, 1.4, 20.0, 5.0, look, 0.0, 0.0), std::invalid_argument);
  // A bob of zero amplitude does not care about its frequency.
  EXPECT_NO_THROW(makeOrbit(c, 1.0, 1.4, 20.0, 5.0, look, 0.0, 0.5, 50.0));
}

TEST(TrajectoryPaths, DrivePathStartsAndEndsAtRestAndFollowsTheWaypoints) {
  const std::vector<Eigen::Vector2d> waypoints = {{0, 0}, {8, 0}, {8, 6}, {2, 6}};
  const double speed = 1.5, height = 0.3, knot = 0.5, ramp = 1.0;
  const SplineTrajectory drive = makeDrivePath(waypoints, speed, height, knot, ramp);
  const double length = 8 + 6 + 6, drive_time = length / speed + ramp;
  EXPECT_GE(drive.endTime(), knot + drive_time + knot - 1e-9);
  EXPECT_LE(drive.endTime(), knot + drive_time + 2 * knot + 1e-9);

  const TrajectorySample start = drive.sample(0), end = drive.sample(drive.endTime());
  EXPECT_NEAR((start.T_world_body.translation() - Eigen::Vector3d(0, 0, height)).norm(), 0, 1e-12);
  EXPECT_NEAR((end.T_world_body.translation() - Eigen::Vector3d(2, 6, height)).norm(), 0, 1e-12);
  EXPECT_NEAR(start.velocity_world.norm() + start.acceleration_world.norm(), 0, 1e-12);
  EXPECT_NEAR(end.velocity_world.norm() + end.acceleration_world.norm(), 0, 1e-12);
  EXPECT_NEAR(start.yaw_pitch_roll[0], 0, 1e-12);
  EXPECT_NEAR(end.yaw_pitch_roll[0], kPi, 1e-9);  // two left turns, unwrapped: +pi

  // Mid-segment of the first leg (well clear of the ramp and the corner): on the line at speed.
  const TrajectorySample cruise = drive.sample(knot + ramp + 2.0);
  EXPECT_NEAR(cruise.T_world_body.translation().y(), 0, 1e-12);
  EXPECT_NEAR(cruise.velocity_world.norm(), speed, 1e-9);

  // Flat ground; the nose points along the velocity (little side slip, even in the turns).
  double worst_slip = 0, peak_acc = 0;
  for (double t = 0; t <= drive.endTime(); t += 0.01) {
    const TrajectorySample s = drive.sample(t);
    EXPECT_NEAR(s.T_world_body.translation().z(), height, 1e-12);
    EXPECT_NEAR(s.yaw_pitch_roll[1], 0, 1e-15);
    EXPECT_NEAR(s.yaw_pitch_roll[2], 0, 1e-15);
    if (s.velocity_world.norm() > 0.3 * speed) {
      worst_slip =
          std::max(worst_slip, angleBetween(s.T_world_body.linear().col(0), s.velocity_world));
    }
    peak_acc = std::max(peak_acc, s.acceleration_world.norm());
  }
  // The heading of the rounded corner is not a cubic in t, so the yaw spline (interpolating the
  // curve's heading at the knots) lags it between knots: ~5 degrees at the peak of a 90-degree
  // corner turned over ~3 knots, 0 on the straights. Measured, with margin.
  EXPECT_LT(worst_slip, 7.0 * kPi / 180);
  EXPECT_LT(peak_acc, 2.0 * speed / knot);  // ~ v^2 / turn radius, radius ~ speed * knot
  RecordProperty("drive_worst_slip_deg", std::to_string(worst_slip * 180 / kPi));
}

TEST(TrajectoryPaths, DrivePathWithoutRampAndItsErrors) {
  const SplineTrajectory drive = makeDrivePath({{0, 0}, {0, 0}, {5, 5}}, 2.0, 0.0, 0.2);
  EXPECT_NEAR(drive.sample(0).yaw_pitch_roll[0], kPi / 4, 1e-12);  // duplicates are skipped
  const TrajectorySample cruise = drive.sample(1.5);
  EXPECT_NEAR(cruise.velocity_world.norm(), 2.0, 1e-9);
  EXPECT_THROW(makeDrivePath({{1, 1}}, 1.0, 0.0, 0.5), std::invalid_argument);
  EXPECT_THROW(makeDrivePath({{1, 1}, {1, 1}}, 1.0, 0.0, 0.5), std::invalid_argument);
  EXPECT_THROW(makeDrivePath({{0, 0}, {1, 0}}, 0.0, 0.0, 0.5), std::invalid_argument);
  EXPECT_THROW(makeDrivePath({{0, 0}, {1, 0}}, 1.0, 0.0, -0.5), std::invalid_argument);
  EXPECT_THROW(makeDrivePath({{0, 0}, {1, 0}}, 1.0, 0.0, 0.5, 2.0), std::invalid_argument);
}

TEST(TrajectoryPaths, UnwrapAnglesRemovesTwoPiJumps) {
  std::vector<double> angles = {3.0, -3.0, -2.5, 2.9, 0.1};
  unwrapAngles(angles);
  EXPECT_NEAR(angles[1], -3.0 + 2 * kPi, 1e-12);
  EXPECT_NEAR(angles[2], -2.5 + 2 * kPi, 1e-12);
  EXPECT_NEAR(angles[3], 2.9, 1e-12);
  EXPECT_NEAR(angles[4], 0.1, 1e-12);
}

}  // namespace
}  // namespace dynslam::sim
