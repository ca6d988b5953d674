#pragma once
// A navigation scenario of dynslam-nav-demo (params/nav/NAME.ini): [NavDemo] which simulated
// world, SLAM configuration and navigator to use and the goals to reach; [Robot] the simulated
// differential-drive robot; [Navigation] the adapter (nav::NavigationOptions, also where the
// camera sits on the robot).
#include <dynslam/core/Options.h>
#include <dynslam/nav/NavigationOptions.h>
#include <dynslam/sim/DiffDriveMotion.h>

#include <Eigen/Core>

#include <string>
#include <vector>

namespace dynslam::core {
class IniConfig;
}

namespace dynslam::navdemo {

struct NavDemoOptions : core::Options {
  static constexpr const char* kSection = "NavDemo";
  std::string scenario;          ///< a dynslam-sim scenario ini (its scene and people)
  std::string slam_config;       ///< the dynslam ini the System runs
  std::string navigator_config;  ///< CReactiveNavigationSystem3D's ini
  /// Where the robot starts, the scenario's world frame: "x y yaw_deg".
  std::string start = "0 0 0";
  /// The goals in order, the world frame: "x y; x y; ...".
  std::string goals;
  double goal_tolerance_m = 0.3;
  double goal_time_limit_s = 40;
  double control_rate_hz = 10;
  double wait_s = 1.0;  ///< standing still at the start before the first goal
  /// estimated (the SLAM system's pose and objects) | ground_truth (the simulator's)
  std::string obstacles = "estimated";
  double person_radius_m = 0.25;  ///< a body's radius for contacts and the minimum distance
  double collision_distance_m = 0.2;
  double moving_speed_m_s = 0.05;  ///< the robot counts as moving above this
  /// The static map the navigator gets keeps voxels seen in at least this many of the frames
  /// the map took (every 10th): people's pixels a missed detection let in come from one.
  int map_min_frames = 3;

  void describe(core::OptionVisitor& v) override;
};

struct RobotOptions : core::Options {
  static constexpr const char* kSection = "Robot";
  sim::DiffDriveLimits limits;
  double radius_m = 0.3;  ///< the base's outline for contacts (the navigator has its own shape)
  double imu_x = 0, imu_y = 0, imu_z = 0.3;  ///< the IMU on the base, m
  void describe(core::OptionVisitor& v) override;
};

struct NavScenario {
  NavDemoOptions demo;
  RobotOptions robot;
  nav::NavigationOptions navigation;
  Eigen::Vector3d start = Eigen::Vector3d::Zero();  ///< x, y, yaw (rad)
  std::vector<Eigen::Vector2d> goals;
};

/// Reads and checks a navigation scenario (unknown sections and keys name themselves); the
/// paths it names are resolved against the ini's folder.
NavScenario loadNavScenario(const core::IniConfig& ini);

}  // namespace dynslam::navdemo
