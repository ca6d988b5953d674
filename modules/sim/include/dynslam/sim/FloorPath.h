#pragma once
// Where an agent is on the ground plane (world z = 0, z up) at time t: a polyline followed at
// constant speed, either back and forth (people pacing) or round a closed loop (cars circling
// a block), or a single point (standing / parked).
#include <Eigen/Core>

#include <vector>

namespace dynslam::sim {

class FloorPath {
 public:
  enum class Mode { BackAndForth, Loop };

  /// `start_offset_m`: arc length already travelled at t = 0. `turn_length`: the heading at s
  /// follows the chord from s - turn_length to s + turn_length, so corners and reversals turn
  /// over about that distance instead of instantly (a step for a person, a car's length for a
  /// car). Throws std::invalid_argument for no waypoints or a non-positive turn length.
  FloorPath(std::vector<Eigen::Vector2d> waypoints, double speed, double start_offset_m = 0.0,
            Mode mode = Mode::BackAndForth, double turn_length = 0.4);

  /// Position on the floor and heading (rad, about z) at time t.
  void at(double t, Eigen::Vector2d& xy, double& heading) const;
  /// Distance travelled by time t (drives a person's gait phase, a car's wheel angle).
  double distance(double t) const { return speed_ * t; }
  bool standing() const { return length() <= 0 || speed_ <= 0; }
  /// Length of one pass (BackAndForth) or of the closed loop (Loop).
  double length() const { return cumulative_.back(); }

 private:
  Eigen::Vector2d pointAt(double s) const;  // s: arc length travelled
  std::vector<Eigen::Vector2d> waypoints_;  // Loop: the first point is repeated at the end
  std::vector<double> cumulative_;          // arc length at each waypoint
  double speed_, offset_, turn_length_;
  Mode mode_;
};

}  // namespace dynslam::sim
