#pragma once
// A trajectory as the evaluator and the writers see it: stamped rigid poses.
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <vector>

namespace dynslam::core {

/// Pose of a body in the world frame (world <- body) at time t (seconds, Unix epoch or
/// sequence-relative as the source gives it).
struct StampedPose {
  double t = 0.0;
  Eigen::Isometry3d T_world_body = Eigen::Isometry3d::Identity();
};

using Trajectory = std::vector<StampedPose>;

/// The pose of `trajectory` (sorted by t) stamped nearest `t` within `tolerance` seconds, the
/// earlier one on a tie; nullptr when none is that close.
inline const StampedPose* poseNear(const Trajectory& trajectory, double t, double tolerance) {
  const auto it = std::lower_bound(trajectory.begin(), trajectory.end(), t,
                                   [](const StampedPose& p, double s) { return p.t < s; });
  const StampedPose* best = nullptr;
  double best_gap = tolerance;
  for (auto c : {it, it == trajectory.begin() ? it : it - 1})
    if (c != trajectory.end() && std::abs(c->t - t) <= best_gap) {
      best = &*c;
      best_gap = std::abs(c->t - t);
    }
  return best;
}

}  // namespace dynslam::core
