#include "dynslam/evaluation/Association.h"

#include "dynslam/evaluation/EvaluationError.h"

#include <cmath>
#include <sstream>

namespace dynslam::evaluation {

MatchingIndices matchingTimeIndices(const std::vector<double>& stamps_1,
                                    const std::vector<double>& stamps_2, double max_diff,
                                    double offset_2) {
  MatchingIndices matches;
  if (stamps_2.empty()) return matches;
  // The offset is added to every stamp before differencing (not subtracted from stamp_1), so
  // that ties and tolerance edges round exactly as in evo.
  std::vector<double> shifted(stamps_2.size());
  for (std::size_t k = 0; k < stamps_2.size(); ++k) shifted[k] = stamps_2[k] + offset_2;

  // A full scan per stamp (O(n*m)) on purpose: it needs no sorting assumption and keeps
  // numpy's "first minimum wins" rule; a few thousand x a few ten thousand stamps take
  // well under a second.
  for (std::size_t i = 0; i < stamps_1.size(); ++i) {
    const double stamp = stamps_1[i];
    std::size_t best = 0;
    double best_diff = std::abs(shifted[0] - stamp);
    for (std::size_t k = 1; k < shifted.size(); ++k) {
      const double diff = std::abs(shifted[k] - stamp);
      if (diff < best_diff) {
        best_diff = diff;
        best = k;
      }
    }
    if (best_diff <= max_diff) {
      matches.first.push_back(i);
      matches.second.push_back(best);
    }
  }
  return matches;
}

namespace {
core::Trajectory select(const core::Trajectory& trajectory, const std::vector<std::size_t>& ids) {
  core::Trajectory out;
  out.reserve(ids.size());
  for (const std::size_t id : ids) out.push_back(trajectory[id]);
  return out;
}

std::vector<double> stampsOf(const core::Trajectory& trajectory) {
  std::vector<double> stamps;
  stamps.reserve(trajectory.size());
  for (const auto& pose : trajectory) stamps.push_back(pose.t);
  return stamps;
}
}  // namespace

AssociatedTrajectories associateByTime(const core::Trajectory& first,
                                       const core::Trajectory& second, double max_diff,
                                       double offset_2) {
  // Start from the trajectory with fewer poses so that each of its poses can find a partner;
  // with equal lengths the second one counts as the shorter, as in evo.
  const bool second_longer = second.size() > first.size();
  const core::Trajectory& shorter = second_longer ? first : second;
  const core::Trajectory& longer = second_longer ? second : first;
  // The offset belongs to the second trajectory's clock: added to it when it is the longer
  // one, subtracted from the first one's otherwise.
  const MatchingIndices matches = matchingTimeIndices(stampsOf(shorter), stampsOf(longer), max_diff,
                                                      second_longer ? offset_2 : -offset_2);
  if (matches.first.empty()) {
    std::ostringstream msg;
    msg << "found no matching timestamps between the two trajectories with max. time diff "
        << max_diff << " s and time offset " << offset_2 << " s";
    throw EvaluationError(msg.str());
  }
  AssociatedTrajectories out;
  out.max_pairs = shorter.size();
  core::Trajectory short_sync = select(shorter, matches.first);
  core::Trajectory long_sync = select(longer, matches.second);
  out.first = second_longer ? std::move(short_sync) : std::move(long_sync);
  out.second = second_longer ? std::move(long_sync) : std::move(short_sync);
  return out;
}

AssociatedTrajectories associateByIndex(const core::Trajectory& first,
                                        const core::Trajectory& second) {
  if (first.size() != second.size()) {
    throw EvaluationError("trajectories paired by index must have the same number of poses (" +
                          std::to_string(first.size()) + " vs " + std::to_string(second.size()) +
                          ")");
  }
  if (first.empty()) throw EvaluationError("trajectories are empty");
  return AssociatedTrajectories{first, second, first.size()};
}

}  // namespace dynslam::evaluation
