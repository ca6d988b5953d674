#pragma once
// Relative pose error, evo.core.metrics.RPE: for index pairs (i, j) chosen by a delta, the
// error pose E = (Q_i^-1 Q_j)^-1 (P_i^-1 P_j) (Q reference, P estimate), reduced to a scalar by
// the pose relation. Pair selection mirrors evo.core.filters.
#include <dynslam/core/Trajectory.h>
#include <dynslam/evaluation/PoseRelation.h>

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace dynslam::evaluation {

using IdPairs = std::vector<std::pair<std::size_t, std::size_t>>;

enum class DeltaUnit {
  Frames,  ///< index distance
  Meters,  ///< travelled path length
};

/// "f"/"frames" or "m"/"meters"; throws std::invalid_argument otherwise.
DeltaUnit parseDeltaUnit(const std::string& name);

/// filter_pairs_by_index: consecutive pairs (0, d), (d, 2d), ...; with all_pairs every
/// (i, i + d). delta must be >= 1.
IdPairs filterPairsByIndex(std::size_t num_poses, std::size_t delta, bool all_pairs);

/// filter_pairs_by_path on the positions of `poses`.
///  - consecutive: walks the path from pose 0, accumulating segment lengths; each pose where
///    the accumulated length reaches `delta` is marked (and the count restarts), and pairs link
///    successive marks. Pose 0 itself is not a mark (evo's released rule, which reproduces the
///    KITTI_00 reference figures). `tol` is unused here, as in evo.
///  - all_pairs: for every i < n-1, the j > i whose path length from i is closest to delta
///    (first one on ties), kept when within `tol` of delta.
IdPairs filterPairsByPath(const core::Trajectory& poses, double delta, double tol, bool all_pairs);

struct RpeOptions {
  PoseRelation relation = PoseRelation::TranslationPart;
  double delta = 1.0;
  DeltaUnit delta_unit = DeltaUnit::Frames;
  /// Tolerance of all_pairs path search, relative to delta (evo's --delta_tol, default 0.1).
  double rel_delta_tol = 0.1;
  bool all_pairs = false;
  /// Choose pairs on the reference poses; evo (since 1.x) chooses them on the estimate unless
  /// --pairs_from_reference is given.
  bool pairs_from_reference = false;
};

struct RpeResult {
  IdPairs pairs;
  std::vector<double> errors;  ///< errors[k] belongs to pairs[k]
};

/// Throws EvaluationError when the lengths differ, delta is invalid, or no pair is found.
RpeResult computeRpe(const core::Trajectory& ref, const core::Trajectory& est,
                     const RpeOptions& options);

/// The error of given pairs (evo's RPE.process_data with explicit id pairs).
std::vector<double> rpeErrors(const core::Trajectory& ref, const core::Trajectory& est,
                              const IdPairs& pairs, PoseRelation relation);

}  // namespace dynslam::evaluation
