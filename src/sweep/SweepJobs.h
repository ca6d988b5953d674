#pragma once
// The jobs of a sweep (grid combination x rawlog), their folders and the dynslam command of
// each, as argv for local runs and as one shell line for GNU parallel / Slurm.
#include "sweep/SweepGrid.h"

#include <string>
#include <vector>

namespace dynslam::sweep {

struct SweepSpec {
  std::string dynslam;  ///< the dynslam program, as it is to be called
  std::string config;   ///< --config, as given
  std::vector<std::string> rawlogs;
  std::vector<std::string> gts;  ///< empty, or one per rawlog (same order)
  std::vector<SweptKey> keys;
  std::string out;                ///< --out DIR
  std::vector<std::string> sets;  ///< fixed --set overrides, applied before the swept ones
  /// --keep-maps: jobs write map.3Dscene too (off: --no-map, a sweep scores trajectories and a
  /// map per job costs time and disk for nothing).
  bool keep_maps = false;
};

struct Job {
  size_t index = 0;   ///< position in the job list (the Slurm array index)
  size_t rawlog = 0;  ///< index into SweepSpec::rawlogs
  Combination combination;
  std::vector<std::string> overrides;  ///< fixed sets, then the swept "Section.key=value"
  std::string name;                    ///< folder name under OUT/jobs
  std::string dir;                     ///< OUT/jobs/<name>
};

/// Every combination for every rawlog, rawlog-major. Folder names read as
/// "<rawlog stem>__Section.key=value__..." (characters a shell or file system dislikes become
/// '_'); a name longer than 96 characters is cut and given a hash of the whole, so different
/// jobs never share a folder.
std::vector<Job> makeJobs(const SweepSpec& spec);

/// The argv of dynslam for one job (--quiet, no progress bar: its output goes to a log file).
std::vector<std::string> dynslamArgv(const SweepSpec& spec, const Job& job);

/// One shell line running the job unless its summary.json already says "ok" (so re-running a
/// job list only does what is missing), with dynslam's output in <dir>/dynslam.log.
std::string shellLine(const SweepSpec& spec, const Job& job);

/// Single-quotes `s` for sh when it holds anything but safe characters.
std::string shellQuote(const std::string& s);

/// Writes OUT/jobs.txt (one shellLine per job, for `parallel < jobs.txt`) and returns its path.
std::string writeJobList(const SweepSpec& spec, const std::vector<Job>& jobs);

/// Writes OUT/sweep.slurm: a job array of jobs.size() tasks, task i running line i+1 of
/// jobs.txt, at most `throttle` at once (0: no limit). Returns its path.
std::string writeSlurmScript(const SweepSpec& spec, const std::vector<Job>& jobs,
                             const std::string& jobList, int throttle);

}  // namespace dynslam::sweep
