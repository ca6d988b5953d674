#pragma once
// Feature-tracker tests on simulator frames without a rawlog in between: each rendered frame
// becomes the core::Frame io's SensorSync would give (colour, depth, intrinsics, extrinsics,
// the IMU samples of its interval), with the simulator's truth (poses, labels) beside it.
#include <dynslam/core/Frame.h>
#include <dynslam/sim/Simulator.h>

#include <string>
#include <vector>

namespace dynslam::frontend::testing {

/// A scenario of params/sim/ with "section.key=value" overrides (e.g. "Scenario.duration=1").
sim::ScenarioOptions scenario(const std::string& name, const std::vector<std::string>& overrides);

struct SimulatedFrame {
  core::Frame frame;
  sim::SimFrame truth;
};

/// Frame `index` of `sim` as the pipeline sees it, plus its ground truth.
SimulatedFrame simulatedFrame(const sim::Simulator& sim, size_t index);

/// The ground-truth object masks of `truth` (one ObjectMask per visible object, from the
/// label image), as a perfect segmentation stage would write them.
std::vector<core::ObjectMask> truthMasks(const sim::SimFrame& truth);

}  // namespace dynslam::frontend::testing
