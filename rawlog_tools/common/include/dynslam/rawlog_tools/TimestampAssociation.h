#pragma once
// Pairs two time-stamped streams (TUM colour and depth) the way TUM's associate.py does: all
// candidate pairs closer than maxDifference, taken greedily from the closest, each element of
// either stream used at most once.
#include <cstddef>
#include <vector>

namespace dynslam::rawlog_tools {

struct AssociatedPair {
  size_t first = 0;   ///< index into the first stream
  size_t second = 0;  ///< index into the second stream
};

struct Association {
  std::vector<AssociatedPair> pairs;  ///< sorted by first-stream time
  size_t unmatchedFirst = 0;
  size_t unmatchedSecond = 0;
};

/// Stamps need not be sorted. A pair is accepted when |a - b| <= maxDifference.
Association associateNearest(const std::vector<double>& firstStamps,
                             const std::vector<double>& secondStamps, double maxDifference);

}  // namespace dynslam::rawlog_tools
