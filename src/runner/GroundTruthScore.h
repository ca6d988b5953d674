#pragma once
// --gt FILE: the run's trajectory scored against a TUM ground truth, as
// `dynslam-eval ape GT trajectory.tum --align se3` (evo_ape -a) scores it.
#include <dynslam/core/Trajectory.h>

#include <cstddef>
#include <string>

namespace dynslam::runner {

struct ApeScore {
  std::size_t pairs = 0;      ///< poses associated by stamp (max. difference 0.01 s, evo's default)
  std::size_t max_pairs = 0;  ///< the most there could have been (the shorter trajectory)
  double rmse = 0, mean = 0, median = 0, std = 0, min = 0, max = 0, sse = 0;  ///< metres
};

/// Reads the ground truth up front, so a wrong path fails before the run rather than after it.
/// Throws core::TrajectoryFileError naming the file.
core::Trajectory readGroundTruth(const std::string& path);

/// APE of the translation part after SE(3) Umeyama alignment. Throws
/// evaluation::EvaluationError when no pose associates (it says so).
ApeScore scoreAgainstGroundTruth(const core::Trajectory& ground_truth,
                                 const core::Trajectory& estimate);

}  // namespace dynslam::runner
