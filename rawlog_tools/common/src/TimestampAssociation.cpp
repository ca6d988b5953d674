#include "dynslam/rawlog_tools/TimestampAssociation.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace dynslam::rawlog_tools {

Association associateNearest(const std::vector<double>& firstStamps,
                             const std::vector<double>& secondStamps, double maxDifference) {
  // Sorted view of the second stream, so candidates for each first stamp are a binary search
  // away instead of an O(n*m) scan.
  std::vector<size_t> secondOrder(secondStamps.size());
  std::iota(secondOrder.begin(), secondOrder.end(), size_t{0});
  std::sort(secondOrder.begin(), secondOrder.end(),
            [&](size_t a, size_t b) { return secondStamps[a] < secondStamps[b]; });

  struct Candidate {
    double difference;
    size_t first, second;
  };
  std::vector<Candidate> candidates;
  for (size_t i = 0; i < firstStamps.size(); ++i) {
    const double t = firstStamps[i];
    auto it = std::lower_bound(secondOrder.begin(), secondOrder.end(), t - maxDifference,
                               [&](size_t idx, double v) { return secondStamps[idx] < v; });
    for (; it != secondOrder.end() && secondStamps[*it] <= t + maxDifference; ++it)
      candidates.push_back({std::abs(secondStamps[*it] - t), i, *it});
  }
  // Closest first; ties broken by index so the result does not depend on sort stability.
  std::sort(candidates.begin(), candidates.end(), [](const Candidate& a, const Candidate& b) {
    if (a.difference != b.difference) return a.difference < b.difference;
    if (a.first != b.first) return a.first < b.first;
    return a.second < b.second;
  });

  std::vector<bool> firstUsed(firstStamps.size(), false), secondUsed(secondStamps.size(), false);
  Association result;
  for (const Candidate& c : candidates) {
    if (firstUsed[c.first] || secondUsed[c.second]) continue;
    firstUsed[c.first] = secondUsed[c.second] = true;
    result.pairs.push_back({c.first, c.second});
  }
  std::sort(result.pairs.begin(), result.pairs.end(),
            [&](const AssociatedPair& a, const AssociatedPair& b) {
              if (firstStamps[a.first] != firstStamps[b.first])
                return firstStamps[a.first] < firstStamps[b.first];
              return a.first < b.first;
            });
  result.unmatchedFirst = firstStamps.size() - result.pairs.size();
  result.unmatchedSecond = secondStamps.size() - result.pairs.size();
  return result;
}

}  // namespace dynslam::rawlog_tools
