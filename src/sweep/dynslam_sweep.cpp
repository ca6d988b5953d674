// dynslam-sweep: runs dynslam over a grid of ini values and rawlogs, locally in parallel or as
// a job list for GNU parallel / Slurm, and tabulates APE, RPE and FPS per job.
#include "sweep/LocalRunner.h"
#include "sweep/SummaryJson.h"
#include "sweep/SweepJobs.h"
#include "sweep/SweepPlot.h"
#include "sweep/SweepResults.h"

#include <dynslam/core/CommandLine.h>

#include <filesystem>
#include <iostream>

namespace fs = std::filesystem;
using namespace dynslam::sweep;

namespace {

const char* kUsage =
    R"(usage: dynslam-sweep --config FILE.ini --grid "Section.key=v1,v2;Section.key2=a,b"
                     --rawlog A [--rawlog B ...] [--gt A.tum [--gt B.tum ...]] --out DIR
                     [--jobs N] [--set Section.key=value]... [--dynslam PATH]
                     [--emit parallel|slurm] [--collect] [--no-check] [--keep-maps]
       dynslam-sweep -h | --help

Runs `dynslam --config FILE.ini --rawlog R --set ...` for every combination of the --grid values
and every rawlog R, each into its own folder DIR/jobs/<rawlog>__<Section.key=value>__..., then
scores each trajectory.tum against the ground truth given for its rawlog (evo's APE after SE(3)
alignment and RPE between consecutive frames, translation, m).

Options:
  --config FILE.ini   the dynslam configuration every job starts from
  --grid TEXT         the swept keys: "Section.key=v1,v2;Section.key2=a,b" (every combination,
                      the last key varying fastest)
  --rawlog FILE       an input rawlog (repeatable: every combination runs on each)
  --gt FILE.tum       the ground truth of the rawlog in the same position (repeatable; none:
                      no scores, only status and FPS)
  --out DIR           the sweep's folder (created)
  --jobs N            dynslam processes at once (default 1); with --emit slurm: the array's limit
  --set S.k=v         a fixed override for every job (repeatable), before the swept ones
  --dynslam PATH      the dynslam program (default: the one beside dynslam-sweep)
  --emit parallel     write DIR/jobs.txt, one shell command per job, and run nothing; e.g.
                        parallel --jobs 4 --sshloginfile hosts.txt < DIR/jobs.txt
                      (paths stay as given, so give ones valid on every host)
  --emit slurm        also write DIR/sweep.slurm, a job array whose task i runs line i+1 of
                      jobs.txt
  --collect           run nothing: gather results.csv and the plots from what the jobs left
  --no-check          skip the one-frame dynslam run that checks the configuration first
  --keep-maps         let every job write map.3Dscene (by default jobs run with --no-map)
  -h, --help          print this text and exit

Outputs: DIR/results.csv (one row per job: job, rawlog, the swept values, status ok/failed,
APE rmse/mean/median/std, RPE rmse/mean, FPS from the run's summary.json, the reason of a
failure, the job's folder), DIR/plot_<Section.key>.png (APE RMSE against each swept key's
values), DIR/jobs/<job>/ (dynslam's outputs and dynslam.log), DIR/check/ (the one-frame check).
Resumable: a job whose folder holds a summary.json with "status": "ok" is not run again (also
by the job-list lines); a failed or interrupted one is. Progress goes to stderr.
Before the first job of a new sweep runs, it is tried on one frame, so an unknown Section.key,
section or stage stops the sweep with dynslam's own message instead of failing every job.
Exit codes: 0 every job ok, 1 some job failed or bad input (results.csv still written for the
jobs), 2 usage (a bad --grid names the part), 130 Ctrl-C.
)";

std::string dynslamBeside(const std::string& argv0) {
  if (argv0.find('/') == std::string::npos) return "dynslam";  // found through PATH
  return (fs::path(argv0).parent_path() / "dynslam").string();
}

void requireFile(const std::string& what, const std::string& path) {
  if (!fs::is_regular_file(path))
    throw std::runtime_error(what + " '" + path + "' does not exist or is not a file");
}

std::string joined(const std::vector<std::string>& items, const char* sep) {
  std::string s;
  for (const auto& i : items) s += (s.empty() ? "" : sep) + i;
  return s;
}

/// Tries the first job on one frame, into DIR/check; throws with dynslam's message when the
/// configuration or the rawlog is rejected.
void checkConfiguration(const SweepSpec& spec, const Job& job) {
  Job probe = job;
  probe.dir = (fs::path(spec.out) / "check").string();
  const std::string& dir = probe.dir;
  auto argv = dynslamArgv(spec, probe);
  argv.insert(argv.end(), {"--max-frames", "1"});
  const JobOutcome o = runOne(argv, dir);
  if (!o.ok)
    throw std::runtime_error(
        "dynslam rejects the job " + job.name + " (--set " + joined(job.overrides, " --set ") +
        ") on its first frame: " + o.reason + " (log: " + dir +
        "/dynslam.log; if only this job's value is bad, --no-check runs every job and reports "
        "this one as failed)");
}

int emit(const SweepSpec& spec, const std::vector<Job>& jobs, const std::string& mode,
         int throttle) {
  const std::string list = writeJobList(spec, jobs);
  std::cerr << "dynslam-sweep: wrote " << jobs.size() << " job lines to " << list << "\n";
  if (mode == "slurm") {
    const std::string script = writeSlurmScript(spec, jobs, list, throttle);
    std::cerr << "dynslam-sweep: wrote " << script << "; submit it with: sbatch " << script << "\n";
  } else {
    std::cerr << "dynslam-sweep: run them with e.g.: parallel --jobs N [--sshloginfile FILE] < "
              << list << "\n";
  }
  std::cerr << "dynslam-sweep: afterwards, the same command with --collect instead of --emit "
               "writes results.csv\n";
  return 0;
}

/// The flags of a sweep, checked.
struct SweepRequest {
  SweepSpec spec;
  int processes = 1;  ///< --jobs
  bool jobsGiven = false;
  std::string emit;  ///< --emit: "", parallel or slurm
  bool collect = false, check = true;
};

SweepRequest readRequest(const dynslam::core::CommandLine& cl, const char* argv0) {
  using dynslam::core::UsageError;
  SweepRequest r;
  SweepSpec& spec = r.spec;
  spec.config = cl.required("--config");
  spec.out = cl.required("--out");
  spec.rawlogs = cl.all("--rawlog");
  if (spec.rawlogs.empty()) throw UsageError("--rawlog is required");
  spec.gts = cl.all("--gt");
  if (!spec.gts.empty() && spec.gts.size() != spec.rawlogs.size())
    throw UsageError("give one --gt per --rawlog (" + std::to_string(spec.rawlogs.size()) +
                     " rawlogs, " + std::to_string(spec.gts.size()) + " --gt)");
  spec.sets = cl.all("--set");
  spec.keep_maps = cl.has("--keep-maps");
  spec.dynslam = cl.valueOr("--dynslam", dynslamBeside(argv0));
  try {
    spec.keys = parseGrid(cl.required("--grid"));
  } catch (const GridError& e) {
    throw UsageError(e.what());
  }
  const long long processes = cl.optionalInteger("--jobs").value_or(1);
  if (processes < 1) throw UsageError("--jobs must be >= 1");
  r.processes = static_cast<int>(processes);
  r.jobsGiven = cl.has("--jobs");
  r.emit = cl.valueOr("--emit", "");
  if (!r.emit.empty() && r.emit != "parallel" && r.emit != "slurm")
    throw UsageError("--emit '" + r.emit + "': expected parallel or slurm");
  r.collect = cl.has("--collect");
  if (!r.emit.empty() && r.collect) throw UsageError("--emit and --collect exclude each other");
  r.check = !cl.has("--no-check");
  return r;
}

/// --emit: the job list (and the Slurm script), after checking the configuration when
/// everything it names is on this machine.
int emitJobs(const SweepRequest& r, const std::vector<Job>& jobs) {
  const SweepSpec& spec = r.spec;
  // The job list may be meant for other hosts, where the paths lead elsewhere: the
  // configuration is checked here only when everything it names is on this machine too.
  std::string absent;
  for (const auto& path : {spec.config, spec.rawlogs.front(), spec.dynslam})
    if (absent.empty() && !fs::is_regular_file(path)) absent = path;
  if (r.check && absent.empty())
    checkConfiguration(spec, jobs.front());
  else if (r.check)
    std::cerr << "dynslam-sweep: configuration not checked: '" << absent
              << "' is not on this machine\n";
  return emit(spec, jobs, r.emit, r.jobsGiven ? r.processes : 0);
}

/// The jobs still to run (none with --collect), after checking that the inputs exist.
std::vector<const Job*> pendingJobs(const SweepRequest& r, const std::vector<Job>& jobs) {
  std::vector<const Job*> pending;
  if (r.collect) return pending;
  const SweepSpec& spec = r.spec;
  requireFile("--config", spec.config);
  for (const auto& rawlog : spec.rawlogs) requireFile("--rawlog", rawlog);
  for (const auto& gt : spec.gts) requireFile("--gt", gt);
  if (spec.dynslam.find('/') != std::string::npos) requireFile("dynslam program", spec.dynslam);
  for (const auto& job : jobs)
    if (!jobCompleted(job.dir)) pending.push_back(&job);
  return pending;
}

void announce(const SweepRequest& r, size_t jobs, size_t pending, size_t skipped) {
  const std::string shape = std::to_string(jobs) + " jobs (" +
                            std::to_string(jobs / r.spec.rawlogs.size()) + " combinations x " +
                            std::to_string(r.spec.rawlogs.size()) + " rawlogs)";
  if (r.collect)
    std::cerr << "dynslam-sweep: collecting " << shape << " from " << r.spec.out << "/jobs\n";
  else
    std::cerr << "dynslam-sweep: " << shape << "; skipped " << skipped << " already done; running "
              << pending << " on " << r.processes << " process" << (r.processes > 1 ? "es" : "")
              << "\n";
}

struct RunTally {
  size_t ran = 0, failed = 0;
  bool interrupted = false;
};

/// Runs the pending jobs locally, reporting each as it ends.
RunTally runPending(const SweepRequest& r, const std::vector<const Job*>& pending,
                    size_t jobCount) {
  RunTally tally;
  if (pending.empty()) return tally;
  // Keys and sections are the same in every job: once one job has succeeded they are known
  // good, and the check would only stop the sweep on a job whose own value is bad.
  const bool someJobSucceeded = pending.size() < jobCount;
  if (r.check && !someJobSucceeded) checkConfiguration(r.spec, *pending.front());
  tally.interrupted =
      !runLocally(r.spec, pending, r.processes, [&](const Job& job, const JobOutcome& o) {
        ++tally.ran;
        tally.failed += o.ok ? 0 : 1;
        std::cerr << "dynslam-sweep: [" << tally.ran << "/" << pending.size() << "] "
                  << (o.ok ? "ok     " : "FAILED ") << job.name << " ("
                  << static_cast<int>(o.seconds + 0.5) << " s"
                  << (tally.failed ? ", " + std::to_string(tally.failed) + " failed so far" : "")
                  << ")" << (o.ok ? "" : ": " + o.reason) << "\n";
      });
  return tally;
}

/// results.csv and the plots from every job's folder; the exit code.
int collect(const SweepRequest& r, const std::vector<Job>& jobs, const RunTally& tally,
            size_t skipped) {
  std::vector<JobResult> results;
  for (const auto& job : jobs) results.push_back(collectJob(r.spec, job));
  const std::string csv = writeResultsCsv(r.spec, results);
  const auto plots = writeSweepPlots(r.spec, results);
  size_t failed = 0;
  for (const auto& result : results) failed += result.ok ? 0 : 1;
  std::cerr << "dynslam-sweep: ran " << tally.ran << ", skipped " << skipped << "; "
            << jobs.size() - failed << " of " << jobs.size() << " jobs ok, " << failed
            << " failed; wrote " << csv << " and " << plots.size() << " plot"
            << (plots.size() == 1 ? "" : "s") << "\n";
  if (tally.interrupted) {
    std::cerr << "dynslam-sweep: interrupted; run the same command again to finish the sweep\n";
    return 130;
  }
  return failed ? 1 : 0;
}

int sweep(const dynslam::core::CommandLine& cl, const char* argv0) {
  const SweepRequest r = readRequest(cl, argv0);
  fs::create_directories(r.spec.out);
  const std::vector<Job> jobs = makeJobs(r.spec);
  if (!r.emit.empty()) return emitJobs(r, jobs);
  const std::vector<const Job*> pending = pendingJobs(r, jobs);
  const size_t skipped = r.collect ? 0 : jobs.size() - pending.size();
  announce(r, jobs.size(), pending.size(), skipped);
  const RunTally tally = runPending(r, pending, jobs.size());
  return collect(r, jobs, tally, skipped);
}

}  // namespace

int main(int argc, char** argv) {
  return dynslam::core::runProgram("dynslam-sweep", [&] {
    dynslam::core::CommandLine cl({"--config", "--grid", "--out", "--jobs", "--dynslam", "--emit"},
                                  {"--collect", "--no-check", "--keep-maps"},
                                  {"--rawlog", "--gt", "--set"});
    cl.parse(argc, argv);
    if (cl.helpRequested()) {
      std::cout << kUsage;
      return 0;
    }
    return sweep(cl, argv[0]);
  });
}
