#pragma once
// The sensing side of mrpt::nav::CRobot2NavInterface served from the SLAM estimate: the robot's
// pose and world velocity, and the obstacles around it (static map points and every moving
// object's footprint swept along its predicted motion), so that MRPT's reactive navigator
// (CReactiveNavigationSystem3D) keeps out of where people are going. The motion commands stay
// the user's: compose the adapter into your CRobot2NavInterface (SlamRobotInterface.h does).
//
// The navigation frame is the robot's base at the SLAM system's first pose: x forward, y left,
// z up, origin on the floor (the robot stands on a level floor at its start). Obstacles are in
// the robot's frame with z the height above the floor, as CReactiveNavigationSystem3D slices
// them. Both calls read cached values (EstimateSource) and are safe from the navigator's thread.
#include <dynslam/nav/EstimateSource.h>
#include <dynslam/nav/NavigationOptions.h>

#include <mrpt/math/TPose2D.h>
#include <mrpt/math/TTwist2D.h>
#include <mrpt/system/datetime.h>

#include <Eigen/Geometry>

#include <cstddef>
#include <future>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

namespace mrpt::maps {
class CSimplePointsMap;
}

namespace dynslam::nav {

class NavigationAdapter {
 public:
  /// `source` must outlive the adapter.
  NavigationAdapter(const EstimateSource& source, const NavigationOptions& options);

  /// CRobot2NavInterface::getCurrentPoseAndSpeeds: the robot's pose and world velocity in the
  /// navigation frame at the latest posed frame; `odometry` is that pose again (there is no
  /// separate odometry). False while the system initializes or is lost (the navigator stops).
  bool getCurrentPoseAndSpeeds(mrpt::math::TPose2D& pose, mrpt::math::TTwist2D& velocity,
                               mrpt::system::TTimeStamp& timestamp, mrpt::math::TPose2D& odometry,
                               std::string& frame_id) const;
  /// CRobot2NavInterface::senseObstacles: robot frame, z above the floor, within
  /// obstacle_range_m. False whenever getCurrentPoseAndSpeeds is.
  bool senseObstacles(mrpt::maps::CSimplePointsMap& obstacles,
                      mrpt::system::TTimeStamp& timestamp) const;

  /// The navigation frame in the map (nullopt before the first pose).
  std::optional<Eigen::Isometry3d> mapToNavigation() const;
  const NavigationOptions& options() const { return options_; }

 private:
  /// The map in the navigation frame: the robot's base at the camera's first pose.
  Eigen::Isometry3d navigationFrame(const system::LocalizationUpdate& first) const;
  struct Robot {
    Eigen::Isometry3d T_nav_map;
    Eigen::Vector3d pose;  // x, y, yaw in the navigation frame
    mrpt::math::TTwist2D velocity;
    mrpt::system::TTimeStamp timestamp;
  };
  std::optional<Robot> robot(const CameraPoses& poses) const;
  /// The static map's points above the floor in the navigation frame, one per cell, within
  /// obstacle_range_m + kStaticCacheMarginM of where the robot was when they were gathered.
  struct StaticCache {
    std::shared_ptr<const mrpt::maps::CPointsMap> map;
    Eigen::Vector2d centre = Eigen::Vector2d::Zero();
    std::vector<Eigen::Vector3f> points;
  };
  static constexpr double kStaticCacheMarginM = 1.0;
  static StaticCache gather(std::shared_ptr<const mrpt::maps::CPointsMap> map,
                            const Eigen::Isometry3d& T_nav_map, const Eigen::Vector2d& robot,
                            const NavigationOptions& options);
  /// The points in hand; gathered again when the source hands out a new map or the robot has
  /// moved beyond the margin (on a thread of its own with gather_in_background).
  const std::vector<Eigen::Vector3f>& staticPoints(const Eigen::Isometry3d& T_nav_map,
                                                   const Eigen::Vector2d& robot) const;

  const EstimateSource& source_;
  NavigationOptions options_;
  Eigen::Isometry3d T_camera_base_;
  mutable std::mutex mutex_;  // the static cache (the navigator may call from several threads)
  mutable std::optional<StaticCache> cache_;
  mutable std::future<StaticCache> pending_;
};

}  // namespace dynslam::nav
