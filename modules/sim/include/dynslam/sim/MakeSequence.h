#pragma once
// The sequence a scenario ini asks for: the fully synthetic Simulator, or ([Scenario] scene =
// augment) the Augmenter's real RGB-D sequence with rendered movers. Programs that take any
// params/sim/*.ini (dynslam-sim, bench-segmentation) build their frames through this one choice.
#include <dynslam/sim/ScenarioOptions.h>
#include <dynslam/sim/SimFrame.h>

#include <memory>

namespace dynslam::sim {

/// Throws what the chosen constructor throws (a scene that cannot be built, a missing rawlog).
std::unique_ptr<Sequence> makeSequence(const ScenarioOptions& options);

}  // namespace dynslam::sim
