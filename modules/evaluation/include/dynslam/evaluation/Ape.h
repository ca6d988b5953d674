#pragma once
// Absolute pose error, evo.core.metrics.APE: per associated pose pair the error pose
// E_i = P_i^-1 * Q_i (P estimate, Q reference); for the translation part simply
// |p_est - p_ref|.
#include <dynslam/core/Trajectory.h>
#include <dynslam/evaluation/PoseRelation.h>

#include <vector>

namespace dynslam::evaluation {

/// One error per pose pair (ref[i], est[i]); throws EvaluationError when the lengths differ or
/// the trajectories are empty. Align `est` first if wanted (see Alignment.h).
std::vector<double> computeApe(const core::Trajectory& ref, const core::Trajectory& est,
                               PoseRelation relation);

}  // namespace dynslam::evaluation
