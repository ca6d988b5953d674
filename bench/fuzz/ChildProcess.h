#pragma once
// One program run of bench-fuzz-inputs: started with its output in a log file, an address-space
// limit and a wall-clock limit; what ended it and what it used.
#include <string>
#include <vector>

namespace dynslam::bench::fuzz {

struct ChildLimits {
  double seconds = 10;      ///< killed (SIGKILL) after this long: a hang
  double memory_mb = 2048;  ///< RLIMIT_AS: an allocation beyond it fails instead of swapping
                            ///< (0: none)
};

struct ChildResult {
  int exit_code = -1;  ///< when it exited
  int signal = 0;      ///< when a signal ended it (not the time limit's SIGKILL)
  bool timed_out = false;
  double seconds = 0;
  double max_rss_mb = 0;
  std::string output;  ///< stdout and stderr together
};

/// Runs argv[0] (a path) with `argv`, its output to `log` (then read back into output).
ChildResult runChild(const std::vector<std::string>& argv, const std::string& log,
                     const ChildLimits& limits);

}  // namespace dynslam::bench::fuzz
