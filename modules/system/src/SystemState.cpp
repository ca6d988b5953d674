#include "SystemState.h"

#include <dynslam/core/Frame.h>
#include <dynslam/system/PoseConversion.h>

#include <mrpt/poses/CPose3D.h>

namespace dynslam::system {
namespace {

mrpt::math::TPoint3D toTPoint3D(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }

/// The velocity between two stamped poses' origins (0 when their stamps coincide).
Eigen::Vector3d velocityBetween(double t0, const Eigen::Isometry3d& T0, double t1,
                                const Eigen::Isometry3d& T1) {
  return t1 > t0 ? Eigen::Vector3d((T1.translation() - T0.translation()) / (t1 - t0))
                 : Eigen::Vector3d::Zero();
}

}  // namespace

void SystemState::update(const core::Frame& frame) {
  std::lock_guard<std::mutex> lock(mutex_);
  ++frames_;
  const bool restarted = frame.keyframe && frame.keyframe->restarted;
  if (frame.T_world_camera) {
    previousCamera_ = camera_;
    camera_ = Posed{frame.t, *frame.T_world_camera};
    LocalizationUpdate u;
    u.timestamp = mrpt::Clock::fromDouble(frame.t);
    u.pose = toTPose3D(*frame.T_world_camera);
    pose_ = u;
  }
  if (frame.T_world_camera && !restarted)
    status_ = TrackingStatus::Tracking;
  else if (pose_)
    status_ = TrackingStatus::LostRestarting;
  updateObjects(frame);
}

void SystemState::updateObjects(const core::Frame& frame) {
  if (frame.object_states) {
    objects_.clear();  // the stage keeps its own states, coasting ones too
    for (const auto& state : *frame.object_states) {
      MovingObject& o = objects_[state.id].out;
      o.id = state.id;
      o.category = state.category;
      o.pose = mrpt::math::TPose3D(state.centre.x(), state.centre.y(), state.centre.z(), 0, 0, 0);
      o.velocity = toTPoint3D(state.velocity);
      o.extent = {state.extent.x(), state.extent.z(), state.extent.y()};  // width, height, depth
      mrpt::math::CMatrixDouble66 cov;
      for (int r = 0; r < 6; ++r)
        for (int c = 0; c < 6; ++c) cov(r, c) = state.covariance(r, c);
      o.cov = cov;
      o.moving = state.moving;
      o.measured = state.measured;
      o.last_seen = mrpt::Clock::fromDouble(state.last_measured);
    }
    return;
  }
  for (const auto& posed : frame.object_poses) {
    Object& o = objects_[posed.object_id];
    const bool seenBefore = o.out.id == posed.object_id;
    o.out.id = posed.object_id;
    o.out.pose = toTPose3D(posed.T_world_object);
    o.out.velocity =
        toTPoint3D(seenBefore ? velocityBetween(o.last.t, o.last.T, frame.t, posed.T_world_object)
                              : Eigen::Vector3d::Zero());
    o.out.last_seen = mrpt::Clock::fromDouble(frame.t);
    o.last = Posed{frame.t, posed.T_world_object};
    for (const auto& track : frame.tracks)
      if (track.id == posed.object_id) {
        o.out.category = track.category;
        const double fx = frame.intrinsics.fx, fy = frame.intrinsics.fy;
        if (fx > 0 && fy > 0 && track.depth > 0) {
          const double w = track.box.width * track.depth / fx;
          o.out.extent = {w, track.box.height * track.depth / fy, w};
        }
      }
  }
  for (auto it = objects_.begin(); it != objects_.end();)
    it = frame.t - it->second.last.t > kObjectMemoryS ? objects_.erase(it) : std::next(it);
}

std::optional<LocalizationUpdate> SystemState::latestPose() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return pose_;
}

std::optional<Eigen::Vector3d> SystemState::latestVelocity() const {
  std::lock_guard<std::mutex> lock(mutex_);
  if (!camera_ || !previousCamera_) return std::nullopt;
  return velocityBetween(previousCamera_->t, previousCamera_->T, camera_->t, camera_->T);
}

std::vector<MovingObject> SystemState::movingObjects() const {
  std::lock_guard<std::mutex> lock(mutex_);
  std::vector<MovingObject> out;
  for (const auto& [id, o] : objects_) out.push_back(o.out);
  return out;
}

TrackingStatus SystemState::status() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return status_;
}

std::size_t SystemState::frames() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return frames_;
}

}  // namespace dynslam::system
