#pragma once
// What a closed-loop run is judged by (nav.json and the printed line): goals reached and the
// time each took, collisions and contacts with people and static obstacles, the closest the
// robot came to a person, emergency stops, the adapter's call times and the pose error.
#include "nav_demo/ClosedLoop.h"

#include <iosfwd>
#include <string>

namespace dynslam::navdemo {

struct NavFigures {
  int goals_reached = 0;
  double mean_time_to_goal_s = 0;    ///< over the goals reached
  double position_error_rmse_m = 0;  ///< estimated against true base position, per frame
  double pose_call_median_us = 0, pose_call_max_us = 0;
  double obstacle_call_median_us = 0, obstacle_call_max_us = 0;
};
NavFigures figuresOf(const ClosedLoopResult& result);

/// Written whole or not at all.
void writeNavJson(const std::string& path, const NavScenario& scenario,
                  const sim::ScenarioOptions& world, const ClosedLoopResult& result);
void printSummary(std::ostream& out, const NavScenario& scenario, const ClosedLoopResult& result);

}  // namespace dynslam::navdemo
