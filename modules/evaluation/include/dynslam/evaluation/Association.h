#pragma once
// Pairing the poses of a reference and an estimate, as evo's sync module does it.
//  - By time (TUM, EuRoC): evo.core.sync.associate_trajectories / matching_time_indices.
//  - By index (KITTI): the i-th pose of one file with the i-th of the other.
#include <dynslam/core/Trajectory.h>

#include <cstddef>
#include <vector>

namespace dynslam::evaluation {

/// Indices of matched elements: first[k] (in the first list) goes with second[k].
struct MatchingIndices {
  std::vector<std::size_t> first;
  std::vector<std::size_t> second;
};

/// For every stamp of `stamps_1` (in order) finds the stamp of `stamps_2 + offset_2` with the
/// smallest absolute difference (the first one on ties, like numpy's argmin, and without
/// assuming sorted stamps) and keeps the pair when that difference is <= max_diff.
/// One element of stamps_2 may be matched by several of stamps_1, as in evo.
MatchingIndices matchingTimeIndices(const std::vector<double>& stamps_1,
                                    const std::vector<double>& stamps_2, double max_diff = 0.01,
                                    double offset_2 = 0.0);

/// Two trajectories reduced to their associated poses, same length, pose k with pose k.
struct AssociatedTrajectories {
  core::Trajectory first;
  core::Trajectory second;
  /// The most pairs there could have been (the length of the shorter input).
  std::size_t max_pairs = 0;
};

/// evo's associate_trajectories: the trajectory with fewer poses (the second one when both have
/// as many) is matched against the longer one, so that none of the shorter one's poses is lost
/// to a one-to-one rule; `offset_2` is added to the second trajectory's stamps.
/// Throws EvaluationError when nothing matches.
AssociatedTrajectories associateByTime(const core::Trajectory& first,
                                       const core::Trajectory& second, double max_diff = 0.01,
                                       double offset_2 = 0.0);

/// Index pairing (evo for KITTI files): throws EvaluationError when the lengths differ.
AssociatedTrajectories associateByIndex(const core::Trajectory& first,
                                        const core::Trajectory& second);

}  // namespace dynslam::evaluation
