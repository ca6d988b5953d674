#pragma once
// One PNG per swept key: APE RMSE against the key's values, one line per combination of the
// other keys (each point the median over the rawlogs); past 8 such lines only their median is
// drawn, with the min-max band around it.
#include "sweep/SweepResults.h"

#include <string>
#include <vector>

namespace dynslam::sweep {

/// Writes OUT/plot_<Section.key>.png for every swept key and returns the paths; keys with no
/// scored job get no plot. Throws std::runtime_error when a file cannot be written.
std::vector<std::string> writeSweepPlots(const SweepSpec& spec,
                                         const std::vector<JobResult>& results);

}  // namespace dynslam::sweep
