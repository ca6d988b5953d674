#pragma once
// --gt FILE: the run's trajectory scored against a TUM ground truth, as
// `dynslam-eval ape GT trajectory.tum --align se3` (evo_ape -a) scores it.
#include <dynslam/core/Trajectory.h>
#include <dynslam/evaluation/Ape.h>

#include <cstddef>
#include <string>

namespace dynslam::runner {

/// pairs, max_pairs and the translation errors' statistics (metres).
using ApeScore = evaluation::ApeSe3Result;

/// Reads the ground truth up front, so a wrong path fails before the run rather than after it.
/// Throws core::TrajectoryFileError naming the file.
core::Trajectory readGroundTruth(const std::string& path);

/// APE of the translation part after SE(3) Umeyama alignment. Throws
/// evaluation::EvaluationError when no pose associates (it says so).
ApeScore scoreAgainstGroundTruth(const core::Trajectory& ground_truth,
                                 const core::Trajectory& estimate);

}  // namespace dynslam::runner
