#pragma once
// bench-tracking over a set of runs (--scenarios A-B, --seeds A-B): every choreography
// (Scenario.seed) with every detector seed (--seed), each rendered, detected and segmented once
// and scored under each tracker configuration (the settings given, then each --sweep value).
// Prints one row per run and, per configuration, the mean MOTA / IDF1 / ID switches, the runs
// at IDF1 >= 0.90 and the runs better / worse than the first configuration: one command for the
// figures that used to take one invocation per seed.
#include "tracking_sim_input.h"

#include <functional>
#include <string>
#include <vector>

namespace dynslam::bench {

/// One tracker configuration's scores on one run.
struct RunScore {
  double mota = 0, idf1 = 0;
  size_t id_switches = 0;
};

/// Scores a prepared run under each configuration, in the order of the names given.
using ScoreRun = std::function<std::vector<RunScore>(const CachedRun&)>;

/// "2-13", "1,4,7" or "5": the values, in order; a UsageError naming flag otherwise.
std::vector<int> parseRange(const std::string& flag, const std::string& text);

/// Runs every (scenario seed, detector seed) pair with `jobs` in parallel and prints the table.
/// `configurations` names the columns (e.g. "as given", "identity_repair=10").
void benchRunSet(const BenchSettings& s, const std::vector<int>& scenarios,
                 const std::vector<int>& seeds, int jobs,
                 const std::vector<std::string>& configurations, const ScoreRun& score);

}  // namespace dynslam::bench
