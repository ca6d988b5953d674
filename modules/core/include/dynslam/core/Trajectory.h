#pragma once
// A trajectory as the evaluator and the writers see it: stamped rigid poses.
#include <Eigen/Geometry>

#include <vector>

namespace dynslam::core {

/// Pose of a body in the world frame (world <- body) at time t (seconds, Unix epoch or
/// sequence-relative as the source gives it).
struct StampedPose {
  double t = 0.0;
  Eigen::Isometry3d T_world_body = Eigen::Isometry3d::Identity();
};

using Trajectory = std::vector<StampedPose>;

}  // namespace dynslam::core
