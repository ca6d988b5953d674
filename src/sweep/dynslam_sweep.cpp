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

Runs `dynslam --config FILE.ini --rawlog R --set ...` for every combination of the --grid values
and every rawlog R, each into its own folder DIR/jobs/<rawlog>__<Section.key=value>__..., then
scores each trajectory.tum against the ground truth given for its rawlog (one --gt per --rawlog,
same order; evo's APE after SE(3) alignment and RPE between consecutive frames, translation, m).
Writes DIR/results.csv (one row per job: swept values, rawlog, status ok/failed and the reason,
APE rmse/mean/median/std, RPE rmse/mean, FPS from the run's summary.json) and
DIR/plot_<Section.key>.png (APE RMSE against each swept key's values).

  --jobs N        dynslam processes at once (default 1); with --emit slurm: the array's limit
  --set S.k=v     a fixed override for every job (repeatable), before the swept ones
  --dynslam PATH  the dynslam program (default: the one beside dynslam-sweep)
  --emit parallel write DIR/jobs.txt, one shell command per job, and run nothing; e.g.
                    parallel --jobs 4 --sshloginfile hosts.txt < DIR/jobs.txt
                  (paths stay as given, so give ones valid on every host)
  --emit slurm    also write DIR/sweep.slurm, a job array whose task i runs line i+1 of jobs.txt
  --collect       run nothing: gather results.csv and the plots from what the jobs left
  --no-check      skip the one-frame dynslam run that checks the configuration first
  --keep-maps     let every job write map.3Dscene (by default jobs run with --no-map)

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

int sweep(const dynslam::core::CommandLine& cl, const char* argv0) {
  SweepSpec spec;
  spec.config = cl.required("--config");
  spec.out = cl.required("--out");
  spec.rawlogs = cl.all("--rawlog");
  if (spec.rawlogs.empty()) throw dynslam::core::UsageError("--rawlog is required");
  spec.gts = cl.all("--gt");
  if (!spec.gts.empty() && spec.gts.size() != spec.rawlogs.size())
    throw dynslam::core::UsageError("give one --gt per --rawlog (" +
                                    std::to_string(spec.rawlogs.size()) + " rawlogs, " +
                                    std::to_string(spec.gts.size()) + " --gt)");
  spec.sets = cl.all("--set");
  spec.keep_maps = cl.has("--keep-maps");
  spec.dynslam = cl.valueOr("--dynslam", dynslamBeside(argv0));
  try {
    spec.keys = parseGrid(cl.required("--grid"));
  } catch (const GridError& e) {
    throw dynslam::core::UsageError(e.what());
  }
  const long long jobsFlag = cl.optionalInteger("--jobs").value_or(1);
  if (jobsFlag < 1) throw dynslam::core::UsageError("--jobs must be >= 1");
  const std::string mode = cl.valueOr("--emit", "");
  if (!mode.empty() && mode != "parallel" && mode != "slurm")
    throw dynslam::core::UsageError("--emit '" + mode + "': expected parallel or slurm");
  if (!mode.empty() && cl.has("--collect"))
    throw dynslam::core::UsageError("--emit and --collect exclude each other");

  fs::create_directories(spec.out);
  const std::vector<Job> jobs = makeJobs(spec);
  if (!mode.empty()) {
    // The job list may be meant for other hosts, where the paths lead elsewhere: the
    // configuration is checked here only when everything it names is on this machine too.
    std::string absent;
    for (const auto& path : {spec.config, spec.rawlogs.front(), spec.dynslam})
      if (absent.empty() && !fs::is_regular_file(path)) absent = path;
    if (!cl.has("--no-check") && absent.empty())
      checkConfiguration(spec, jobs.front());
    else if (!cl.has("--no-check"))
      std::cerr << "dynslam-sweep: configuration not checked: '" << absent
                << "' is not on this machine\n";
    return emit(spec, jobs, mode, cl.has("--jobs") ? static_cast<int>(jobsFlag) : 0);
  }

  std::vector<const Job*> pending;
  if (!cl.has("--collect")) {
    requireFile("--config", spec.config);
    for (const auto& r : spec.rawlogs) requireFile("--rawlog", r);
    for (const auto& g : spec.gts) requireFile("--gt", g);
    if (spec.dynslam.find('/') != std::string::npos) requireFile("dynslam program", spec.dynslam);
    for (const auto& job : jobs)
      if (!jobCompleted(job.dir)) pending.push_back(&job);
  }
  const size_t skipped = cl.has("--collect") ? 0 : jobs.size() - pending.size();
  const std::string shape = std::to_string(jobs.size()) + " jobs (" +
                            std::to_string(jobs.size() / spec.rawlogs.size()) + " combinations x " +
                            std::to_string(spec.rawlogs.size()) + " rawlogs)";
  if (cl.has("--collect"))
    std::cerr << "dynslam-sweep: collecting " << shape << " from " << spec.out << "/jobs\n";
  else
    std::cerr << "dynslam-sweep: " << shape << "; skipped " << skipped << " already done; running "
              << pending.size() << " on " << jobsFlag << " process" << (jobsFlag > 1 ? "es" : "")
              << "\n";

  bool interrupted = false;
  size_t ran = 0, failedRuns = 0;
  if (!pending.empty()) {
    // Keys and sections are the same in every job: once one job has succeeded they are known
    // good, and the check would only stop the sweep on a job whose own value is bad.
    const bool someJobSucceeded = pending.size() < jobs.size();
    if (!cl.has("--no-check") && !someJobSucceeded) checkConfiguration(spec, *pending.front());
    interrupted = !runLocally(
        spec, pending, static_cast<int>(jobsFlag), [&](const Job& job, const JobOutcome& o) {
          ++ran;
          failedRuns += o.ok ? 0 : 1;
          std::cerr << "dynslam-sweep: [" << ran << "/" << pending.size() << "] "
                    << (o.ok ? "ok     " : "FAILED ") << job.name << " ("
                    << static_cast<int>(o.seconds + 0.5) << " s"
                    << (failedRuns ? ", " + std::to_string(failedRuns) + " failed so far" : "")
                    << ")" << (o.ok ? "" : ": " + o.reason) << "\n";
        });
  }

  std::vector<JobResult> results;
  for (const auto& job : jobs) results.push_back(collectJob(spec, job));
  const std::string csv = writeResultsCsv(spec, results);
  const auto plots = writeSweepPlots(spec, results);
  size_t failed = 0;
  for (const auto& r : results) failed += r.ok ? 0 : 1;
  std::cerr << "dynslam-sweep: ran " << ran << ", skipped " << skipped << "; "
            << jobs.size() - failed << " of " << jobs.size() << " jobs ok, " << failed
            << " failed; wrote " << csv << " and " << plots.size() << " plot"
            << (plots.size() == 1 ? "" : "s") << "\n";
  if (interrupted) {
    std::cerr << "dynslam-sweep: interrupted; run the same command again to finish the sweep\n";
    return 130;
  }
  return failed ? 1 : 0;
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
