#include "GroundTruthScore.h"

#include <dynslam/core/TrajectoryFile.h>

namespace dynslam::runner {

core::Trajectory readGroundTruth(const std::string& path) { return core::readTum(path); }

ApeScore scoreAgainstGroundTruth(const core::Trajectory& ground_truth,
                                 const core::Trajectory& estimate) {
  return evaluation::evoApeSe3(ground_truth, estimate);
}

}  // namespace dynslam::runner
