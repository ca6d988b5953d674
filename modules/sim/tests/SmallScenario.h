#pragma once
// Scenario options for fast tests: a short run at a quarter of the default resolution (the
// intrinsics scaled with it, so the field of view is the scenarios' own).
#include <dynslam/sim/ScenarioOptions.h>

namespace dynslam::sim::testing {

inline ScenarioOptions smallScenario(const std::string& scene, double duration, double fps,
                                     uint64_t seed) {
  ScenarioOptions o;
  o.world.scene = scene;
  o.world.seed = seed;
  o.world.duration = duration;
  o.world.fps = fps;
  o.world.width = 320;
  o.world.height = 240;
  o.world.fx = o.world.fy = 262.5;
  o.world.cx = 159.5;
  o.world.cy = 119.5;
  return o;
}

}  // namespace dynslam::sim::testing
