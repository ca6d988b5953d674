#pragma once
// An EstimateSource the tests set by hand, with helpers that place the robot and objects in the
// navigation frame (the robot's base at the first pose) through a map frame of any orientation.
#include <dynslam/core/CameraMount.h>
#include <dynslam/nav/EstimateSource.h>
#include <dynslam/nav/PlanarPose.h>

#include <dynslam/system/PoseConversion.h>
#include <mrpt/maps/CSimplePointsMap.h>

#include <Eigen/Geometry>

#include <cmath>

namespace dynslam::nav::testing {

using system::toTPose3D;

using nav::planarPose;

class FakeEstimateSource : public EstimateSource {
 public:
  /// The map frame's pose in the navigation frame (what the SLAM system chose as its world)
  /// and the camera on the robot, as the adapter's options give it.
  FakeEstimateSource(const Eigen::Isometry3d& T_nav_map, const Eigen::Isometry3d& T_base_camera)
      : T_nav_map_(T_nav_map), T_base_camera_(T_base_camera) {}

  system::TrackingStatus status_ = system::TrackingStatus::Tracking;
  CameraPoses poses_;
  std::vector<system::MovingObject> objects_;
  std::shared_ptr<const mrpt::maps::CPointsMap> map_;

  /// Appends a camera pose for the robot's base at `T_nav_base` (the first one fixes the frame).
  void robotAt(double t, const Eigen::Isometry3d& T_nav_base) {
    system::LocalizationUpdate u;
    u.timestamp = mrpt::Clock::fromDouble(t);
    u.pose = toTPose3D(T_nav_map_.inverse() * T_nav_base * T_base_camera_);
    poses_.add(u);
  }
  /// A person centred at `centre` (navigation frame) moving at `velocity`.
  void personAt(const Eigen::Vector3d& centre, const Eigen::Vector3d& velocity) {
    system::MovingObject o;
    o.id = static_cast<int>(objects_.size());
    o.category = "person";
    const Eigen::Vector3d c = T_nav_map_.inverse() * centre;
    const Eigen::Vector3d v = T_nav_map_.linear().transpose() * velocity;
    o.pose = mrpt::math::TPose3D(c.x(), c.y(), c.z(), 0, 0, 0);
    o.velocity = {v.x(), v.y(), v.z()};
    o.extent = {0.5, 1.8, 0.3};  // width, height, depth
    objects_.push_back(o);
  }
  /// A static map holding `points` given in the navigation frame.
  void mapOf(const std::vector<Eigen::Vector3d>& points) {
    auto map = std::make_shared<mrpt::maps::CSimplePointsMap>();
    for (const auto& p : points) {
      const Eigen::Vector3d m = T_nav_map_.inverse() * p;
      map->insertPoint(m.x(), m.y(), m.z());
    }
    map_ = map;
  }

  system::TrackingStatus status() const override { return status_; }
  CameraPoses cameraPoses() const override { return poses_; }
  std::vector<system::MovingObject> movingObjects() const override { return objects_; }
  std::shared_ptr<const mrpt::maps::CPointsMap> staticMap() const override { return map_; }

 private:
  Eigen::Isometry3d T_nav_map_, T_base_camera_;
};

}  // namespace dynslam::nav::testing
