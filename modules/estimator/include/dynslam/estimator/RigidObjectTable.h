#pragma once
// The dynamic rigid objects of the sliding window (method.md section 5, r_O and r_om): per object
// (a car, or the rigid point set on a walking person) one pose L_n = T_world_object per keyframe
// in which it is seen with at least kMinFeatures rigid features, and one object-frame position
// m_obj per feature (RigidObjectReprojectionFactor.h explains why m_obj and not the paper's
// m_{n-1}), with its observations.
//
// Initial values come from the measured depths: a new object's first L is the caller's guess (the
// object trajectory followed so far, so the window and the written trajectory share one object
// frame) or else the centroid of its measured points with the world's axes; a later L is the
// Kabsch/Umeyama fit of the known m_obj onto their measured world points, or, with fewer than
// three of those, the previous L moved by the last keyframe interval's motion. A new feature's
// m_obj is its measured point brought into the object frame (features without depth join once
// they have one). A known point measured farther than max_point_offset from where the fit puts
// it has broken away from the object (the rigid set on a walking person is rigid from frame to
// frame, not over a whole window): its observations are dropped and it starts again there.
#include <dynslam/estimator/LandmarkTable.h>
#include <dynslam/estimator/factors/PinholeProjection.h>

#include <Eigen/Geometry>

#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <vector>

namespace dynslam::estimator {

struct RigidObjectPoint {
  double m_obj[3] = {0, 0, 0};  ///< the estimator's block: position in the object frame
  std::map<std::int64_t, LandmarkObservation> observations;  ///< by keyframe id
};

struct RigidObject {
  std::map<std::int64_t, std::array<double, 7>> poses;  ///< L by keyframe id (pose blocks)
  std::map<std::int64_t, RigidObjectPoint> points;      ///< by feature id
};

/// One keyframe's view of one object: its features' pixels and depths.
struct RigidObjectFeature {
  std::int64_t id = -1;
  Eigen::Vector2d pixel = Eigen::Vector2d::Zero();
  double depth = 0;  ///< m; 0 = none
};

class RigidObjectTable {
 public:
  static constexpr int kMinFeatures = 3;

  explicit RigidObjectTable(double max_point_offset = 0.05) : max_point_offset_(max_point_offset) {}

  /// Records object `object_id` seen in keyframe `keyframe` (ids increase with time) by a camera
  /// at `T_world_camera` (the keyframe's initial guess). Returns false, and records nothing,
  /// when it is seen with fewer than kMinFeatures features, or is new with fewer than
  /// kMinFeatures depths.
  bool observe(int object_id, std::int64_t keyframe,
               const std::vector<RigidObjectFeature>& features,
               const Eigen::Isometry3d& T_world_camera, const PinholeCamera& camera,
               const std::optional<Eigen::Isometry3d>& first_pose_guess);

  /// Moves each object frame seen in `keyframe` (a gauge freedom) so that its origin is the
  /// centroid of the points seen there, the axes kept: every L and m_obj change, no world point.
  void recentre(std::int64_t keyframe);

  /// Drops keyframe `keyframe`'s poses and observations (it left the window), then the points
  /// with no observation left and the objects with no pose left.
  void removeKeyframe(std::int64_t keyframe);

  std::map<int, RigidObject>& all() { return objects_; }
  const std::map<int, RigidObject>& all() const { return objects_; }

 private:
  /// A known object's pose in this keyframe from its points' measured world positions
  /// (`measured`, by feature), the points that broke away dropped.
  Eigen::Isometry3d fitPose(RigidObject& object, const std::vector<RigidObjectFeature>& features,
                            const std::vector<Eigen::Vector3d>& measured);

  double max_point_offset_;  ///< m
  std::map<int, RigidObject> objects_;
};

}  // namespace dynslam::estimator
