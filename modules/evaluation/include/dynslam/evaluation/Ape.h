#pragma once
// Absolute pose error, evo.core.metrics.APE: per associated pose pair the error pose
// E_i = P_i^-1 * Q_i (P estimate, Q reference); for the translation part simply
// |p_est - p_ref|.
#include <dynslam/core/Trajectory.h>
#include <dynslam/evaluation/PoseRelation.h>
#include <dynslam/evaluation/Statistics.h>

#include <vector>

namespace dynslam::evaluation {

/// One error per pose pair (ref[i], est[i]); throws EvaluationError when the lengths differ or
/// the trajectories are empty. Align `est` first if wanted (see Alignment.h).
std::vector<double> computeApe(const core::Trajectory& ref, const core::Trajectory& est,
                               PoseRelation relation);

/// `evo_ape tum REF EST -a` in one call (what the runner's --gt and dynslam-sweep score with):
/// poses associated by stamp within t_max_diff, EST aligned to REF by SE(3) Umeyama, the
/// translation errors' statistics. Throws EvaluationError when no pose associates.
struct ApeSe3Result {
  ErrorStatistics statistics;
  std::size_t pairs = 0;      ///< poses associated
  std::size_t max_pairs = 0;  ///< the most there could have been (the shorter trajectory)
};
ApeSe3Result evoApeSe3(const core::Trajectory& ref, const core::Trajectory& est,
                       double t_max_diff = 0.01);

}  // namespace dynslam::evaluation
