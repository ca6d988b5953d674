#pragma once
// The paths a scenario's people follow, generated from its options and seed (the camera's
// come from TrajectoryPaths.h).
#include <dynslam/sim/Agent.h>
#include <dynslam/sim/Person.h>
#include <dynslam/sim/ScenarioOptions.h>

#include <random>
#include <string>
#include <vector>

namespace dynslam::sim {

/// Floor paths of the walkers and spots of the people standing, inside the disc the camera
/// circles (so nobody walks through the camera). "high" interaction: lines through the centre
/// that cross each other and pass close in front of the camera; "low": parallel lanes.
/// Parses "x,y x,y | x,y" (groups of floor points separated by '|', points by white space)
/// into one point list per group. Empty text: no groups. Throws std::invalid_argument quoting
/// the piece that is not a point (or an empty group).
std::vector<std::vector<Eigen::Vector2d>> parseWaypointList(const std::string& text);

/// Appends the people of [People] waypoints and the cars of [Cars] waypoints to `agents`, with
/// ids after the last one there (people walk their points back and forth, cars round a loop).
void addListedAgents(const ScenarioOptions& options, std::vector<Agent>& agents,
                     TextureLibrary& textures, std::mt19937_64& rng);

std::vector<FloorPath> makePeoplePaths(const PeopleOptions& people, double region_radius,
                                       std::mt19937_64& rng);

}  // namespace dynslam::sim
