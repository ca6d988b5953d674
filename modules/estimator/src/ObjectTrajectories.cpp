#include "dynslam/estimator/ObjectTrajectories.h"

#include "dynslam/estimator/StateBlocks.h"

namespace dynslam::estimator {

Eigen::Isometry3d ObjectTrajectories::follow(const core::RigidSet& set, const core::Frame& frame,
                                             const Eigen::Isometry3d& T_wc) const {
  const auto it = objects_.find(set.object_id);
  const bool continues = it != objects_.end() && previous_camera_ &&
                         frame.index == previous_frame_ + 1 &&
                         it->second.last_frame + 1 == frame.index;
  if (!continues) {
    Eigen::Isometry3d L = Eigen::Isometry3d::Identity();
    L.translation() = T_wc * set.virtual_centroid;
    return L;
  }
  Eigen::Isometry3d motion = Eigen::Isometry3d::Identity();
  motion.linear() = set.R;
  motion.translation() = set.t;
  const Eigen::Isometry3d M = T_wc * motion * previous_camera_->inverse();
  return nearestRigid(M * it->second.T_world_object);
}

void ObjectTrajectories::update(core::Frame& frame,
                                const std::vector<std::pair<int, Eigen::Isometry3d>>& estimated) {
  frame.object_poses.clear();
  if (!frame.T_world_camera) return;
  const Eigen::Isometry3d& T_wc = *frame.T_world_camera;
  const std::map<int, Eigen::Isometry3d> fromWindow(estimated.begin(), estimated.end());
  std::map<int, Followed> updated;
  for (const auto& set : frame.rigid_sets) {
    if (set.object_id < 0) continue;
    const auto window = fromWindow.find(set.object_id);
    Followed f;
    f.T_world_object = window != fromWindow.end() ? window->second : follow(set, frame, T_wc);
    f.last_frame = frame.index;
    updated[set.object_id] = f;
    // Written: the followed orientation at the set's (virtual) centroid as seen in this frame.
    // The followed origin drifts from the set as rotation errors compound (and jumps where the
    // window recentres an object's frame); the centroid is this frame's measurement.
    Eigen::Isometry3d written = f.T_world_object;
    written.translation() = T_wc * set.virtual_centroid;
    frame.object_poses.push_back({set.object_id, written});
  }
  // After all sets are followed: each composes from the previous frame's poses. Only this
  // frame's objects are kept (follow() continues an object from the frame before only), so a
  // long run does not keep one entry per object it ever saw.
  objects_ = std::move(updated);
  previous_camera_ = T_wc;
  previous_frame_ = frame.index;
}

std::map<int, Eigen::Isometry3d> ObjectTrajectories::predict(
    const core::Frame& frame, const Eigen::Isometry3d& T_world_camera) const {
  std::map<int, Eigen::Isometry3d> out;
  for (const auto& set : frame.rigid_sets)
    if (set.object_id >= 0) out[set.object_id] = follow(set, frame, T_world_camera);
  return out;
}

}  // namespace dynslam::estimator
