#include "dynslam/evaluation/Rpe.h"

#include "dynslam/evaluation/EvaluationError.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace dynslam::evaluation {

DeltaUnit parseDeltaUnit(const std::string& name) {
  if (name == "f" || name == "frames") return DeltaUnit::Frames;
  if (name == "m" || name == "meters" || name == "metres") return DeltaUnit::Meters;
  throw std::invalid_argument("unknown delta unit '" + name + "' (expected f or m)");
}

IdPairs filterPairsByIndex(std::size_t num_poses, std::size_t delta, bool all_pairs) {
  if (delta == 0) throw EvaluationError("delta must be at least 1 frame");
  IdPairs pairs;
  if (all_pairs) {
    for (std::size_t i = 0; i + delta < num_poses; ++i) pairs.emplace_back(i, i + delta);
  } else {
    for (std::size_t i = 0; i + delta < num_poses; i += delta) pairs.emplace_back(i, i + delta);
  }
  return pairs;
}

namespace {
/// Consecutive path pairs: the first pair opens where the travelled path first reaches delta
/// (not at pose 0), each later one where another delta has been travelled. This is the rule of
/// the released evo that produced the KITTI_00 reference numbers; evo's development branch
/// has started opening the first pair at pose 0 instead.
IdPairs consecutivePathPairs(const core::Trajectory& poses, double delta) {
  std::vector<std::size_t> ids;
  double path = 0.0;
  for (std::size_t i = 1; i < poses.size(); ++i) {
    path += (poses[i].T_world_body.translation() - poses[i - 1].T_world_body.translation()).norm();
    if (path >= delta) {
      ids.push_back(i);
      path = 0.0;
    }
  }
  IdPairs pairs;
  for (std::size_t k = 0; k + 1 < ids.size(); ++k) pairs.emplace_back(ids[k], ids[k + 1]);
  return pairs;
}
}  // namespace

IdPairs filterPairsByPath(const core::Trajectory& poses, double delta, double tol, bool all_pairs) {
  if (!all_pairs) return consecutivePathPairs(poses, delta);

  // Accumulated path length at every pose (running sum, as numpy's cumsum).
  std::vector<double> distances(poses.size(), 0.0);
  for (std::size_t i = 1; i < poses.size(); ++i)
    distances[i] =
        distances[i - 1] +
        (poses[i - 1].T_world_body.translation() - poses[i].T_world_body.translation()).norm();
  IdPairs pairs;
  for (std::size_t i = 0; i + 1 < poses.size(); ++i) {
    std::size_t best = i + 1;
    double best_residual = std::abs((distances[i + 1] - distances[i]) - delta);
    for (std::size_t j = i + 2; j < poses.size(); ++j) {
      const double residual = std::abs((distances[j] - distances[i]) - delta);
      if (residual < best_residual) {
        best_residual = residual;
        best = j;
      }
    }
    if (best_residual <= tol) pairs.emplace_back(i, best);
  }
  return pairs;
}

std::vector<double> rpeErrors(const core::Trajectory& ref, const core::Trajectory& est,
                              const IdPairs& pairs, PoseRelation relation) {
  std::vector<double> errors;
  errors.reserve(pairs.size());
  for (const auto& [i, j] : pairs) {
    const Eigen::Matrix4d ref_rel =
        relativePose(ref[i].T_world_body.matrix(), ref[j].T_world_body.matrix());
    const Eigen::Matrix4d est_rel =
        relativePose(est[i].T_world_body.matrix(), est[j].T_world_body.matrix());
    errors.push_back(poseError(relativePose(ref_rel, est_rel), relation));
  }
  return errors;
}

RpeResult computeRpe(const core::Trajectory& ref, const core::Trajectory& est,
                     const RpeOptions& options) {
  if (ref.size() != est.size())
    throw EvaluationError("RPE needs trajectories with the same number of poses (" +
                          std::to_string(ref.size()) + " vs " + std::to_string(est.size()) + ")");
  if (!(options.delta > 0.0)) throw EvaluationError("delta must be a positive number");

  const core::Trajectory& pair_source = options.pairs_from_reference ? ref : est;
  RpeResult result;
  if (options.delta_unit == DeltaUnit::Frames) {
    if (options.delta != std::floor(options.delta))
      throw EvaluationError("delta must be an integer for delta unit frames");
    result.pairs = filterPairsByIndex(pair_source.size(), static_cast<std::size_t>(options.delta),
                                      options.all_pairs);
  } else {
    result.pairs = filterPairsByPath(pair_source, options.delta,
                                     options.delta * options.rel_delta_tol, options.all_pairs);
  }
  if (result.pairs.empty()) {
    std::ostringstream msg;
    msg << "delta = " << options.delta
        << (options.delta_unit == DeltaUnit::Frames ? " (frames)" : " (m)")
        << " produced an empty index list - try lower values or a less strict tolerance";
    throw EvaluationError(msg.str());
  }
  result.errors = rpeErrors(ref, est, result.pairs, options.relation);
  return result;
}

}  // namespace dynslam::evaluation
