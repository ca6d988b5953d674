#pragma once
// A robot's pose on a level floor as x, y and yaw, and back: what a 2-D navigator reads of a 3-D
// pose whose z axis is (nearly) up.
#include <Eigen/Geometry>

#include <cmath>

namespace dynslam::nav {

/// x, y, yaw (rad) of `T`, its z axis taken as up.
inline Eigen::Vector3d planarOf(const Eigen::Isometry3d& T) {
  return {T.translation().x(), T.translation().y(), std::atan2(T.linear()(1, 0), T.linear()(0, 0))};
}

/// The pose at (x, y) on the floor turned by yaw (rad) about z.
inline Eigen::Isometry3d planarPose(double x, double y, double yaw) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  T.translation() = Eigen::Vector3d(x, y, 0);
  return T;
}

inline Eigen::Isometry3d planarPose(const Eigen::Vector3d& xyYaw) {
  return planarPose(xyYaw.x(), xyYaw.y(), xyYaw.z());
}

}  // namespace dynslam::nav
