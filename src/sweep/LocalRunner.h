#pragma once
// Runs dynslam jobs as child processes on this machine, at most N at a time.
#include "sweep/SweepJobs.h"

#include <functional>
#include <string>
#include <vector>

namespace dynslam::sweep {

struct JobOutcome {
  bool ok = false;
  std::string reason;  ///< why it failed: summary.json's error, or the exit code / signal
  double seconds = 0.0;
};

/// Starts dynslam for each job (its old summary.json removed first, so a stale one is never
/// read back; stdout and stderr into <dir>/dynslam.log), keeping at most `parallel` running,
/// and calls `done` as each one ends. On Ctrl-C (the children get it too and stop with their
/// partial outputs) no further job starts; returns false then, true otherwise.
bool runLocally(const SweepSpec& spec, const std::vector<const Job*>& jobs, int parallel,
                const std::function<void(const Job&, const JobOutcome&)>& done);

/// Runs one dynslam command and returns its outcome (used to check the configuration on one
/// frame before a sweep starts).
JobOutcome runOne(const std::vector<std::string>& argv, const std::string& dir);

}  // namespace dynslam::sweep
