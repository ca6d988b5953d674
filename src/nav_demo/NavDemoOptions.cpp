#include "nav_demo/NavDemoOptions.h"

#include <dynslam/core/Config.h>

#include <cmath>
#include <sstream>

namespace dynslam::navdemo {
namespace {

/// "a b c; d e f" -> rows of `width` numbers; ConfigError naming the key otherwise.
std::vector<std::vector<double>> numberRows(const std::string& text, std::size_t width,
                                            const std::string& key, const std::string& source) {
  std::vector<std::vector<double>> rows;
  std::istringstream all(text);
  for (std::string row; std::getline(all, row, ';');) {
    if (row.find_first_not_of(" \t") == std::string::npos) continue;
    std::istringstream in(row);
    std::vector<double> values;
    for (double v; in >> v;) values.push_back(v);
    if (!in.eof() || values.size() != width ||
        !std::all_of(values.begin(), values.end(), [](double v) { return std::isfinite(v); }))
      throw core::ConfigError("[NavDemo] " + key + " in " + source + ": '" + row + "' is not " +
                              std::to_string(width) + " numbers");
    rows.push_back(values);
  }
  return rows;
}

}  // namespace

void NavDemoOptions::describe(core::OptionVisitor& v) {
  using core::Range;
  v.path("scenario", scenario,
         "the dynslam-sim scenario ini whose scene and people are used "
         "(its camera path is not: the robot carries the camera)");
  v.path("slam_config", slam_config, "the dynslam ini the SLAM system runs");
  v.path("navigator_config", navigator_config,
         "MRPT's CReactiveNavigationSystem3D ini (params/nav/reactive3d.ini)");
  v.key("start", start, "x y yaw_deg: the robot's start in the scenario's world frame");
  v.key("goals", goals, "x y; x y; ...: the goals in order, world frame");
  v.key("goal_tolerance_m", goal_tolerance_m, Range::above(0), "m; a goal this close is reached");
  v.key("goal_time_limit_s", goal_time_limit_s, Range::above(0),
        "s; a goal not reached this long after it was given is missed and the next one given");
  v.key("control_rate_hz", control_rate_hz, Range::above(0),
        "navigation steps per simulated second");
  v.key("wait_s", wait_s, Range::atLeast(0), "s standing still at the start");
  v.word("obstacles", obstacles, {"estimated", "ground_truth"},
         "estimated: the navigator senses through the SLAM system's pose, static map and object "
         "states; ground_truth: through the simulator's (the reference)");
  v.key("person_radius_m", person_radius_m, Range::above(0),
        "m; a person's body for contacts and the minimum distance");
  v.key("collision_distance_m", collision_distance_m, Range::atLeast(0),
        "m; the robot's outline closer than this to a body or a static obstacle is a contact");
  v.key("map_min_frames", map_min_frames, Range::atLeast(1),
        "the static map the navigator senses keeps points seen in at least this many of the "
        "frames the map took (one in ten): a person's pixels a missed detection let in are "
        "seen once (System's map_update_min_frames)");
  v.key("moving_speed_m_s", moving_speed_m_s, Range::atLeast(0),
        "m/s; a contact while the robot is faster counts as a collision");
}

void RobotOptions::describe(core::OptionVisitor& v) {
  using core::Range;
  v.key("max_speed", limits.max_speed, Range::above(0), "m/s");
  v.key("max_turn_rate", limits.max_turn_rate, Range::above(0), "rad/s");
  v.key("max_acceleration", limits.max_acceleration, Range::above(0), "m/s^2");
  v.key("max_turn_accel", limits.max_turn_accel, Range::above(0), "rad/s^2");
  v.key("radius_m", radius_m, Range::above(0), "m; the base's outline for contacts");
  v.key("imu_x", imu_x, Range::any(), "m; the IMU on the base (x forward, z up from the floor)");
  v.key("imu_y", imu_y, Range::any(), "m");
  v.key("imu_z", imu_z, Range::any(), "m");
}

NavScenario loadNavScenario(const core::IniConfig& ini) {
  core::rejectUnknownSections(
      ini, {NavDemoOptions::kSection, RobotOptions::kSection, nav::NavigationOptions::kSection});
  NavScenario s;
  core::loadOptionsStrict(s.demo, ini, NavDemoOptions::kSection);
  core::loadOptionsStrict(s.robot, ini, RobotOptions::kSection);
  core::loadOptionsStrict(s.navigation, ini, nav::NavigationOptions::kSection);
  for (const auto& [key, value] :
       {std::pair{"scenario", s.demo.scenario}, std::pair{"slam_config", s.demo.slam_config},
        std::pair{"navigator_config", s.demo.navigator_config}})
    if (value.empty())
      throw core::ConfigError(std::string("[NavDemo] ") + key + " in " + ini.source() +
                              " is not set");
  const auto start = numberRows(s.demo.start, 3, "start", ini.source());
  if (start.size() != 1)
    throw core::ConfigError("[NavDemo] start in " + ini.source() + " must be one 'x y yaw_deg'");
  s.start = Eigen::Vector3d(start[0][0], start[0][1], start[0][2] * M_PI / 180);
  for (const auto& g : numberRows(s.demo.goals, 2, "goals", ini.source()))
    s.goals.emplace_back(g[0], g[1]);
  if (s.goals.empty())
    throw core::ConfigError("[NavDemo] goals in " + ini.source() + " lists no goal");
  return s;
}

}  // namespace dynslam::navdemo
