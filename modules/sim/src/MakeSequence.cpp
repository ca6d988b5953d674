#include "dynslam/sim/MakeSequence.h"

#include "dynslam/sim/Augmenter.h"
#include "dynslam/sim/Simulator.h"

namespace dynslam::sim {

std::unique_ptr<Sequence> makeSequence(const ScenarioOptions& options) {
  if (options.world.scene == "augment") return std::make_unique<Augmenter>(options);
  return std::make_unique<Simulator>(options);
}

}  // namespace dynslam::sim
