#pragma once
// A differential-drive robot's exact motion on a level floor, for a robot driven in closed loop:
// the commanded linear and angular speeds are reached at bounded accelerations, and every state
// is a TrajectorySample with the exact accelerations, so that ImuNoiseProcess reports what the
// motion really was. We integrate it ourselves rather than take MRPT's CVehicleSimul_DiffDriven,
// which gives poses and velocities but not the accelerations an IMU measures.
#include <dynslam/sim/SplineTrajectory.h>

namespace dynslam::sim {

struct DiffDriveLimits {
  double max_speed = 0.8;         ///< m/s, forward or back
  double max_turn_rate = 1.05;    ///< rad/s
  double max_acceleration = 1.0;  ///< m/s^2
  double max_turn_accel = 3.0;    ///< rad/s^2
};

class DiffDriveMotion {
 public:
  /// At rest at (x, y) facing yaw (rad); the body frame is the base's (x forward, z up) at
  /// `body_height` above the floor.
  DiffDriveMotion(double x, double y, double yaw, double body_height, DiffDriveLimits limits);

  /// The speeds to reach (clamped to the limits); held until the next command.
  void command(double speed, double turn_rate);
  /// Advances by dt (s): each speed moves towards its command at its acceleration limit.
  void step(double dt);

  double t() const { return t_; }
  double speed() const { return v_; }
  double turnRate() const { return w_; }
  /// The body's pose, velocities and accelerations now (those of the step just made).
  TrajectorySample sample() const;

 private:
  DiffDriveLimits limits_;
  double height_;
  double t_ = 0, x_, y_, yaw_, v_ = 0, w_ = 0;
  double v_cmd_ = 0, w_cmd_ = 0;
  double accel_ = 0, turn_accel_ = 0;  // during the last step
};

}  // namespace dynslam::sim
