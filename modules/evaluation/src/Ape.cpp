#include "dynslam/evaluation/Ape.h"

#include "dynslam/evaluation/Alignment.h"
#include "dynslam/evaluation/Association.h"
#include "dynslam/evaluation/EvaluationError.h"

namespace dynslam::evaluation {

std::vector<double> computeApe(const core::Trajectory& ref, const core::Trajectory& est,
                               PoseRelation relation) {
  if (ref.size() != est.size())
    throw EvaluationError("APE needs trajectories with the same number of poses (" +
                          std::to_string(ref.size()) + " vs " + std::to_string(est.size()) + ")");
  if (ref.empty()) throw EvaluationError("APE of empty trajectories");

  std::vector<double> errors;
  errors.reserve(ref.size());
  for (std::size_t i = 0; i < ref.size(); ++i) {
    if (relation == PoseRelation::TranslationPart) {
      // evo takes the position difference directly (no full error pose needed).
      errors.push_back(
          (est[i].T_world_body.translation() - ref[i].T_world_body.translation()).norm());
    } else {
      // E = P^-1 * Q: the reference pose seen from the estimated one.
      errors.push_back(poseError(
          relativePose(est[i].T_world_body.matrix(), ref[i].T_world_body.matrix()), relation));
    }
  }
  return errors;
}

ApeSe3Result evoApeSe3(const core::Trajectory& ref, const core::Trajectory& est,
                       double t_max_diff) {
  AssociatedTrajectories pairs = associateByTime(ref, est, t_max_diff);
  alignTrajectory(pairs.first, pairs.second, AlignmentMode::Se3, false);
  ApeSe3Result r;
  r.statistics =
      computeStatistics(computeApe(pairs.first, pairs.second, PoseRelation::TranslationPart));
  r.pairs = pairs.first.size();
  r.max_pairs = pairs.max_pairs;
  return r;
}

}  // namespace dynslam::evaluation
