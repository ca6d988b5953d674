#pragma once
// Where a camera sits on a body whose axes are x forward, y left, z up (a robot's base, the
// simulator's IMU body): its optical frame (x right, y down, z along the view) as a pose in the
// body. The simulator's camera and the navigation adapter's robot both describe a mount this way.
#include <Eigen/Geometry>

#include <cmath>

namespace dynslam::core {

/// The optical frame at `position` (m, in the body), looking along the body's x turned by yaw
/// (about z, to the left), then pitch (about y, down) and roll (about x), degrees.
inline Eigen::Isometry3d opticalFrameOnBody(const Eigen::Vector3d& position, double yaw_deg,
                                            double pitch_deg, double roll_deg) {
  Eigen::Matrix3d axes;  // optical z = body x, optical x = -body y, optical y = -body z
  axes << 0, 0, 1, -1, 0, 0, 0, -1, 0;
  const double d = M_PI / 180;
  const Eigen::Matrix3d mount = (Eigen::AngleAxisd(yaw_deg * d, Eigen::Vector3d::UnitZ()) *
                                 Eigen::AngleAxisd(pitch_deg * d, Eigen::Vector3d::UnitY()) *
                                 Eigen::AngleAxisd(roll_deg * d, Eigen::Vector3d::UnitX()))
                                    .toRotationMatrix();
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = mount * axes;
  T.translation() = position;
  return T;
}

}  // namespace dynslam::core
