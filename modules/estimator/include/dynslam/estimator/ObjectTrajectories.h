#pragma once
// World trajectories of the tracked objects from the front-end's rigid point sets (issue 6
// item 9) and the estimated camera poses. A set's motion maps its points from the previous
// camera frame to this one, q = R p + t; in the world that is
//   M = T_world_camera(k) [R | t] T_world_camera(k-1)^-1,
// and the object's pose moves as L_k = M L_(k-1). A new object starts at its set's virtual
// centroid with the world's axes. An object whose set is not seen for a frame keeps its last
// pose and continues when the set comes back in the next frame; after a longer gap (the camera
// pose of the frame before is needed) it starts again from the new centroid.
//
// Where the sliding window estimates an object (r_O, r_om: its L at a keyframe), that estimate
// replaces the composed pose and the frames after it compose from there. The window takes a new
// object's first pose from predict(), so both follow the same object frame.
//
// What is written (Frame::object_poses, objects/ID.tum) is that orientation placed at the set's
// virtual centroid in this frame: the composed origin drifts from the set as rotation errors
// compound, and jumps where the window recentres an object's frame (measured:
// docs/notes/estimator.md, 2026-11-28 (virtual centroid)).
#include <dynslam/core/Frame.h>

#include <map>
#include <utility>
#include <vector>

namespace dynslam::estimator {

class ObjectTrajectories {
 public:
  /// Updates the objects seen in `frame` (its rigid_sets, its T_world_camera, which must be set)
  /// and writes their poses into frame.object_poses; objects in `estimated` (id, T_world_object)
  /// take that pose.
  void update(core::Frame& frame,
              const std::vector<std::pair<int, Eigen::Isometry3d>>& estimated = {});

  /// The poses update() would give the objects of `frame` with the camera at `T_world_camera`
  /// and no estimate: the first pose guess of an object new to the window.
  std::map<int, Eigen::Isometry3d> predict(const core::Frame& frame,
                                           const Eigen::Isometry3d& T_world_camera) const;

 private:
  struct Followed {
    Eigen::Isometry3d T_world_object = Eigen::Isometry3d::Identity();
    std::size_t last_frame = 0;
  };
  /// The pose of `set`'s object in `frame` seen from `T_world_camera`: composed from its last
  /// pose when it continues, else at the set's centroid.
  Eigen::Isometry3d follow(const core::RigidSet& set, const core::Frame& frame,
                           const Eigen::Isometry3d& T_world_camera) const;

  std::map<int, Followed> objects_;
  std::optional<Eigen::Isometry3d> previous_camera_;
  std::size_t previous_frame_ = 0;
};

}  // namespace dynslam::estimator
