#pragma once
// What each job of a sweep left: its status from summary.json, and APE / RPE of its
// trajectory.tum against the rawlog's ground truth (the evaluation module, as evo computes
// them: poses associated by time, APE after an SE(3) Umeyama alignment, RPE between
// consecutive frames, both on the translation part, in metres).
#include "sweep/SweepJobs.h"

#include <dynslam/evaluation/Statistics.h>

#include <optional>
#include <string>
#include <vector>

namespace dynslam::sweep {

struct JobResult {
  const Job* job = nullptr;
  bool ok = false;
  std::string reason;  ///< why not ok
  std::optional<evaluation::ErrorStatistics> ape, rpe;
  std::optional<double> fps;
};

/// Reads <job dir>/summary.json and, when the run succeeded and a ground truth is given,
/// scores <job dir>/trajectory.tum. A job that did not run, failed, or whose trajectory cannot
/// be scored is not ok, with the reason.
JobResult collectJob(const SweepSpec& spec, const Job& job);

/// OUT/results.csv: one row per job: index, rawlog, one column per swept key, status
/// (ok/failed), APE rmse/mean/median/std, RPE rmse/mean (m), fps, reason, folder.
std::string writeResultsCsv(const SweepSpec& spec, const std::vector<JobResult>& results);

}  // namespace dynslam::sweep
