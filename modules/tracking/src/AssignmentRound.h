#pragma once
// One assignment round of the tracker (internal to KalmanBoxTracker): the depth-IoU rounds and
// the appearance round differ only in which tracks and observations take part and in the gain.
#include "dynslam/tracking/KalmanBoxTracker.h"

#include <dynslam/core/HungarianAssignment.h>

#include <Eigen/Core>

#include <vector>

namespace dynslam::tracking {

/// The tracks `trackTakes` admits that have no observation yet against the observations
/// `observationTakes` admits that are not used yet, by the Hungarian algorithm on
/// `gain(track, observation)` (0: the pair is refused; pairs of different categories always
/// are), a pair kept when its gain is > 0. Refused pairs get gain 0 before the assignment, not
/// after it: maximising the total could otherwise pick two refused pairs over one good one.
template <class Tracks, class TrackTakes, class ObservationTakes, class Gain>
void assignRound(const Tracks& tracked, const std::vector<BoxObservation>& observations,
                 TrackTakes trackTakes, ObservationTakes observationTakes, Gain gain,
                 std::vector<int>& observationOf, std::vector<char>& observationUsed) {
  std::vector<int> rows, cols;
  for (size_t i = 0; i < tracked.size(); ++i)
    if (observationOf[i] < 0 && trackTakes(tracked[i])) rows.push_back(int(i));
  for (size_t j = 0; j < observations.size(); ++j)
    if (!observationUsed[j] && observationTakes(observations[j])) cols.push_back(int(j));
  if (rows.empty() || cols.empty()) return;
  Eigen::MatrixXd g = Eigen::MatrixXd::Zero(rows.size(), cols.size());
  for (size_t r = 0; r < rows.size(); ++r)
    for (size_t c = 0; c < cols.size(); ++c) {
      const BoxObservation& o = observations[cols[c]];
      if (o.category == tracked[rows[r]].track.category) g(r, c) = gain(tracked[rows[r]], o);
    }
  const std::vector<int> assigned = core::solveMaxGainAssignment(g);
  for (size_t r = 0; r < rows.size(); ++r)
    if (assigned[r] >= 0 && g(r, assigned[r]) > 0) {
      observationOf[rows[r]] = cols[assigned[r]];
      observationUsed[cols[assigned[r]]] = 1;
    }
}

}  // namespace dynslam::tracking
