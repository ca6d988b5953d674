#pragma once
// The paths a scenario's people follow, generated from its options and seed (the camera's
// come from TrajectoryPaths.h).
#include <dynslam/sim/Person.h>
#include <dynslam/sim/ScenarioOptions.h>

#include <random>
#include <vector>

namespace dynslam::sim {

/// Floor paths of the walkers and spots of the people standing, inside the disc the camera
/// circles (so nobody walks through the camera). "high" interaction: lines through the centre
/// that cross each other and pass close in front of the camera; "low": parallel lanes.
std::vector<FloorPath> makePeoplePaths(const PeopleOptions& people, double region_radius,
                                       std::mt19937_64& rng);

}  // namespace dynslam::sim
