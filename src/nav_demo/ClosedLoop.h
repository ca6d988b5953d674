#pragma once
// One closed-loop navigation run (issue 54 item 2): the simulator renders RGB-D and synthesizes
// the IMU from where a differential-drive robot really is; the SLAM system (or, for the
// reference, the simulator's truth) feeds the navigation adapter; MRPT's
// CReactiveNavigationSystem3D drives the robot through the goals in turn while the scenario's
// people walk their paths (they do not avoid the robot). Time is the simulator's: IMU samples at
// the scenario's rate, frames at its fps, navigation steps at [NavDemo] control_rate_hz, each
// frame processed before the simulation goes on, so a run repeats exactly.
#include "nav_demo/NavDemoOptions.h"

#include <dynslam/core/Trajectory.h>
#include <dynslam/sim/ScenarioOptions.h>

#include <Eigen/Core>

#include <functional>
#include <string>
#include <vector>

namespace dynslam::navdemo {

struct GoalResult {
  Eigen::Vector2d xy = Eigen::Vector2d::Zero();  ///< world frame
  bool reached = false;  ///< the robot's true position came within goal_tolerance_m in time
  /// From being given to the true position first within the tolerance (reached), else to the
  /// goal's end (the navigator stopped at it by its estimate, or the time limit).
  double time_s = 0;
  double final_distance_m = 0;  ///< true distance when the goal ended
};

/// One contact as it began.
struct Contact {
  double t = 0;                                     ///< s since the start
  int id = 0;                                       ///< the person's id, 0 for a static obstacle
  double robot_speed = 0;                           ///< m/s
  double distance_m = 0;                            ///< the outlines' distance at that instant
  Eigen::Vector2d robot = Eigen::Vector2d::Zero();  ///< world x, y
};

struct ClosedLoopResult {
  std::vector<GoalResult> goals;
  /// Contacts: the robot's outline within collision_distance_m of a body or a static obstacle;
  /// counted once per contact (entering it), apart by whether the robot was moving.
  int collisions_people = 0, contacts_people_robot_still = 0;
  int collisions_static = 0, contacts_static_robot_still = 0;
  double min_distance_people_m = 1e9;  ///< the robot's outline to a body's, m
  double min_distance_static_m = 1e9;
  std::vector<Contact> contacts;
  int emergency_stops = 0;     ///< while navigating with a pose
  int stops_without_pose = 0;  ///< the navigator stopped the robot for lack of a pose
  double duration_s = 0;
  std::size_t frames = 0;
  core::Trajectory true_base, estimated_base;  ///< the robot's base, world frame, per frame
  std::vector<double> pose_calls_us, obstacle_calls_us;  ///< the adapter's calls, wall time
};

struct ClosedLoopSettings {
  std::string out_dir;                      ///< people.csv, top.avi, ptg_cache/
  std::vector<std::string> slam_overrides;  ///< "Section.key=value" for the SLAM ini
  bool video = true;
  /// Called after every navigation step with the simulated time and the goal index.
  std::function<void(double t, std::size_t goal)> progress;
};

ClosedLoopResult runClosedLoop(const NavScenario& scenario, const sim::ScenarioOptions& world,
                               const ClosedLoopSettings& settings);

}  // namespace dynslam::navdemo
