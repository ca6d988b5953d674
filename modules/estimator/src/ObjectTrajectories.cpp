#include "dynslam/estimator/ObjectTrajectories.h"

#include "dynslam/estimator/StateBlocks.h"

namespace dynslam::estimator {

void ObjectTrajectories::update(core::Frame& frame) {
  frame.object_poses.clear();
  if (!frame.T_world_camera) return;
  const Eigen::Isometry3d& T_wc = *frame.T_world_camera;
  const bool consecutive = previous_camera_ && frame.index == previous_frame_ + 1;
  for (const auto& set : frame.rigid_sets) {
    if (set.object_id < 0) continue;
    auto it = objects_.find(set.object_id);
    const bool continues = it != objects_.end() && consecutive &&
                           it->second.last_frame + 1 == frame.index;
    if (!continues) {
      Followed f;
      f.T_world_object.translation() = T_wc * set.virtual_centroid;
      it = objects_.insert_or_assign(set.object_id, f).first;
    } else {
      Eigen::Isometry3d motion = Eigen::Isometry3d::Identity();
      motion.linear() = set.R;
      motion.translation() = set.t;
      const Eigen::Isometry3d M = T_wc * motion * previous_camera_->inverse();
      it->second.T_world_object = nearestRigid(M * it->second.T_world_object);
    }
    it->second.last_frame = frame.index;
    frame.object_poses.push_back({set.object_id, it->second.T_world_object});
  }
  previous_camera_ = T_wc;
  previous_frame_ = frame.index;
}

}  // namespace dynslam::estimator
