#include "nav_demo/NavReport.h"

#include <dynslam/core/AtomicFile.h>
#include <dynslam/core/JsonWriter.h>
#include <dynslam/core/Median.h>
#include <dynslam/core/Trajectory.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ostream>

namespace dynslam::navdemo {
namespace {

double maxOf(const std::vector<double>& v) {
  return v.empty() ? 0.0 : *std::max_element(v.begin(), v.end());
}

}  // namespace

NavFigures figuresOf(const ClosedLoopResult& r) {
  NavFigures f;
  double total = 0;
  for (const auto& g : r.goals)
    if (g.reached) ++f.goals_reached, total += g.time_s;
  f.mean_time_to_goal_s = f.goals_reached ? total / f.goals_reached : 0.0;
  double sum = 0;
  std::size_t n = 0;
  for (const auto& e : r.estimated_base)
    if (const auto* truth = core::poseNear(r.true_base, e.t, 1e-3)) {
      sum += (e.T_world_body.translation() - truth->T_world_body.translation())
                 .head<2>()
                 .squaredNorm();
      ++n;
    }
  f.position_error_rmse_m = n ? std::sqrt(sum / n) : 0.0;
  f.pose_call_median_us = core::upperMedian(r.pose_calls_us);
  f.pose_call_max_us = maxOf(r.pose_calls_us);
  f.obstacle_call_median_us = core::upperMedian(r.obstacle_calls_us);
  f.obstacle_call_max_us = maxOf(r.obstacle_calls_us);
  return f;
}

void writeNavJson(const std::string& path, const NavScenario& s, const sim::ScenarioOptions& world,
                  const ClosedLoopResult& r) {
  const NavFigures f = figuresOf(r);
  core::AtomicTextFile file(path);
  core::JsonWriter j(file.stream());
  j.beginObject()
      .member("obstacles", s.demo.obstacles)
      .member("obstacle_horizon_s", s.navigation.obstacle_horizon_s)
      .member("seed", static_cast<long long>(world.world.seed))
      .member("goals_total", r.goals.size())
      .member("goals_reached", f.goals_reached)
      .member("mean_time_to_goal_s", f.mean_time_to_goal_s);
  j.key("goals").beginArray();
  for (const auto& g : r.goals)
    j.beginObject()
        .member("x", g.xy.x())
        .member("y", g.xy.y())
        .member("reached", g.reached)
        .member("time_s", g.time_s)
        .member("final_distance_m", g.final_distance_m)
        .endObject();
  j.endArray()
      .member("collisions_people", r.collisions_people)
      .member("contacts_people_robot_still", r.contacts_people_robot_still)
      .member("collisions_static", r.collisions_static)
      .member("contacts_static_robot_still", r.contacts_static_robot_still)
      .member("min_distance_people_m", r.min_distance_people_m)
      .member("min_distance_static_m", r.min_distance_static_m)
      .member("emergency_stops", r.emergency_stops)
      .member("stops_without_pose", r.stops_without_pose)
      .member("duration_s", r.duration_s)
      .member("frames", r.frames)
      .member("position_error_rmse_m", f.position_error_rmse_m)
      .member("adapter_pose_call_median_us", f.pose_call_median_us)
      .member("adapter_pose_call_max_us", f.pose_call_max_us)
      .member("adapter_obstacle_call_median_us", f.obstacle_call_median_us)
      .member("adapter_obstacle_call_max_us", f.obstacle_call_max_us)
      .endObject();
  file.stream() << "\n";
  file.commit();
}

void printSummary(std::ostream& out, const NavScenario& s, const ClosedLoopResult& r) {
  const NavFigures f = figuresOf(r);
  char line[512];
  std::snprintf(line, sizeof line,
                "obstacles %s (horizon %.1f s): goals %d/%zu, mean time to goal %.1f s; "
                "collisions with people %d (contacts while still %d), static %d; min distance "
                "to people %.2f m; emergency stops %d; position error %.3f m; %zu frames, "
                "%.1f s\n",
                s.demo.obstacles.c_str(), s.navigation.obstacle_horizon_s, f.goals_reached,
                r.goals.size(), f.mean_time_to_goal_s, r.collisions_people,
                r.contacts_people_robot_still, r.collisions_static, r.min_distance_people_m,
                r.emergency_stops, f.position_error_rmse_m, r.frames, r.duration_s);
  out << line;
}

}  // namespace dynslam::navdemo
