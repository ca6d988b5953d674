#include "dynslam/sim/DiffDriveMotion.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace dynslam::sim {
namespace {

/// The change towards `target` over dt at most `rate` * dt.
double towards(double value, double target, double rate, double dt) {
  return std::clamp(target - value, -rate * dt, rate * dt);
}

}  // namespace

DiffDriveMotion::DiffDriveMotion(double x, double y, double yaw, double body_height,
                                 DiffDriveLimits limits)
    : limits_(limits), height_(body_height), x_(x), y_(y), yaw_(yaw) {
  if (!(limits.max_speed > 0 && limits.max_turn_rate > 0 && limits.max_acceleration > 0 &&
        limits.max_turn_accel > 0))
    throw std::invalid_argument("DiffDriveMotion: every limit must be above 0");
}

void DiffDriveMotion::command(double speed, double turn_rate) {
  v_cmd_ = std::clamp(speed, -limits_.max_speed, limits_.max_speed);
  w_cmd_ = std::clamp(turn_rate, -limits_.max_turn_rate, limits_.max_turn_rate);
}

void DiffDriveMotion::step(double dt) {
  if (!(dt > 0)) return;
  const double dv = towards(v_, v_cmd_, limits_.max_acceleration, dt);
  const double dw = towards(w_, w_cmd_, limits_.max_turn_accel, dt);
  accel_ = dv / dt;
  turn_accel_ = dw / dt;
  // Speeds linear in time over the step; the position is their integral along the heading
  // (Simpson's rule on 4 intervals: the heading is quadratic in time, far smoother than that).
  const auto heading = [&](double s) { return yaw_ + w_ * s + 0.5 * turn_accel_ * s * s; };
  const auto speedAt = [&](double s) { return v_ + accel_ * s; };
  double sx = 0, sy = 0;
  const int n = 4;
  for (int i = 0; i <= n; ++i) {
    const double s = dt * i / n;
    const double weight = (i == 0 || i == n) ? 1 : (i % 2 ? 4 : 2);
    sx += weight * speedAt(s) * std::cos(heading(s));
    sy += weight * speedAt(s) * std::sin(heading(s));
  }
  x_ += sx * dt / (3 * n);
  y_ += sy * dt / (3 * n);
  yaw_ = heading(dt);
  v_ += dv;
  w_ += dw;
  t_ += dt;
}

TrajectorySample DiffDriveMotion::sample() const {
  TrajectorySample s;
  s.t = t_;
  s.T_world_body.linear() = Eigen::AngleAxisd(yaw_, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  s.T_world_body.translation() = Eigen::Vector3d(x_, y_, height_);
  const Eigen::Vector2d forward(std::cos(yaw_), std::sin(yaw_)), left(-forward.y(), forward.x());
  s.velocity_world << v_ * forward, 0;
  // Along the heading the speed's change, across it the centripetal v * w.
  s.acceleration_world << accel_ * forward + v_ * w_ * left, 0;
  s.angular_velocity_body = Eigen::Vector3d(0, 0, w_);
  s.angular_acceleration_body = Eigen::Vector3d(0, 0, turn_accel_);
  s.yaw_pitch_roll = Eigen::Vector3d(yaw_, 0, 0);
  return s;
}

}  // namespace dynslam::sim
