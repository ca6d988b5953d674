#pragma once
// A smooth 6-DoF trajectory: a uniform cubic B-spline over control positions and control
// yaw/pitch/roll (ZYX Euler angles of the body in the world), evaluated with analytic first and
// second derivatives so the synthetic IMU is exactly consistent with the poses. World: z up
// (gravity along -z); body: x forward, y left, z up.
//
// Orientation: R_world_body = Rz(yaw) * Ry(pitch) * Rx(roll). With these axes a positive pitch
// tilts the nose (body x) down and a positive roll tilts body y (left) up.
//
// Smoothness: position and the Euler angles are C2 (acceleration is continuous and piecewise
// linear in t), so the specific force is continuous and the angular velocity is C1.
#include <Eigen/Geometry>

#include <cstddef>
#include <vector>

namespace dynslam::sim {

struct TrajectorySample {
  double t = 0;
  Eigen::Isometry3d T_world_body = Eigen::Isometry3d::Identity();
  Eigen::Vector3d velocity_world = Eigen::Vector3d::Zero();         ///< m/s
  Eigen::Vector3d acceleration_world = Eigen::Vector3d::Zero();     ///< m/s^2, without gravity
  Eigen::Vector3d angular_velocity_body = Eigen::Vector3d::Zero();  ///< rad/s, body frame
  /// d/dt of angular_velocity_body (rad/s^2). The body-frame derivative equals the world
  /// angular acceleration expressed in the body frame, because omega x omega = 0.
  Eigen::Vector3d angular_acceleration_body = Eigen::Vector3d::Zero();
  Eigen::Vector3d yaw_pitch_roll = Eigen::Vector3d::Zero();  ///< rad, unwrapped as the controls
};

class SplineTrajectory {
 public:
  /// Time mapping: control point i (0-based) sits at time t0 + (i - 1) * knot_interval, and the
  /// curve is defined on [t0, t0 + (n - 3) * knot_interval]. For t in segment
  /// k = floor((t - t0) / knot_interval) (k = n - 4 at the very end) with
  /// u = (t - t0) / knot_interval - k in [0, 1], the value is
  ///   B0(u) c[k] + B1(u) c[k+1] + B2(u) c[k+2] + B3(u) c[k+3]
  /// with the uniform cubic B-spline basis. The curve approximates (does not pass through) the
  /// controls: at t0 + j * knot_interval it equals (c[j] + 4 c[j+1] + c[j+2]) / 6, and controls
  /// that are affine in their times (c[i] = a + b * t_i) are reproduced exactly.
  ///
  /// Throws std::invalid_argument when n < 4, the sizes differ, knot_interval is not a positive
  /// finite number, a control is not finite, or consecutive control angles jump by more than pi
  /// (almost always a wrapped yaw: unwrap it, or use a shorter knot interval).
  SplineTrajectory(std::vector<Eigen::Vector3d> positions,
                   std::vector<Eigen::Vector3d> yaw_pitch_roll, double knot_interval,
                   double t0 = 0.0);

  /// Pose and analytic derivatives at t. Throws std::out_of_range when t lies outside
  /// [startTime(), endTime()] by more than a rounding tolerance (1e-9 knot intervals plus 1e-14
  /// of |t|); times within it are clamped. Extrapolating would silently produce motion the
  /// caller did not design, so a bad time range is an error, not a clamp.
  TrajectorySample sample(double t) const;
  double startTime() const;
  double endTime() const;
  double knotInterval() const { return dt_; }
  std::size_t controlPointCount() const { return positions_.size(); }

 private:
  std::vector<Eigen::Vector3d> positions_, ypr_;
  double dt_, t0_;
};

/// R_world_body for ZYX Euler angles (yaw, pitch, roll): Rz(yaw) * Ry(pitch) * Rx(roll).
Eigen::Matrix3d rotationFromYawPitchRoll(const Eigen::Vector3d& yaw_pitch_roll);

/// E(ypr) with omega_body = E * d(yaw, pitch, roll)/dt, for the ZYX convention above:
///   [ -sin(p)         0        1 ]
///   [  sin(r) cos(p)  cos(r)   0 ]
///   [  cos(r) cos(p) -sin(r)   0 ]
Eigen::Matrix3d eulerRatesToBodyRates(const Eigen::Vector3d& yaw_pitch_roll);

/// The sampling rule every synthesizer shares: t0 + k / rate_hz for k = 0, 1, ... while the time
/// is <= t1, up to rounding (1e-9 samples plus a few ulps of |t|), so t1 = t0 + N / rate_hz
/// yields N + 1 samples even after rounding, also with Unix-epoch times. The last time may then
/// exceed t1 by that rounding, which SplineTrajectory::sample accepts. Throws std::invalid_argument
/// when rate_hz <= 0, t1 < t0 or either is not finite.
std::vector<double> uniformSampleTimes(double t0, double t1, double rate_hz);

}  // namespace dynslam::sim
