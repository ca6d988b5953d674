#include "sweep/SweepResults.h"

#include "sweep/SummaryJson.h"

#include <dynslam/core/AtomicFile.h>
#include <dynslam/core/TrajectoryFile.h>
#include <dynslam/evaluation/Alignment.h>
#include <dynslam/evaluation/Ape.h>
#include <dynslam/evaluation/Association.h>
#include <dynslam/evaluation/Rpe.h>

#include <cstdio>
#include <filesystem>
#include <stdexcept>

namespace fs = std::filesystem;

namespace dynslam::sweep {
namespace {

namespace ev = evaluation;

/// evo's defaults for the sweep: --t_max_diff 0.01, APE with -a (SE(3)), RPE delta 1 frame.
void score(const std::string& gtPath, const std::string& estPath, JobResult& r) {
  const auto gt = core::readTum(gtPath);
  const auto est = core::readTum(estPath);
  const ev::AssociatedTrajectories pairs = ev::associateByTime(gt, est, 0.01);
  r.rpe = ev::computeStatistics(ev::computeRpe(pairs.first, pairs.second, ev::RpeOptions()).errors);
  r.ape = ev::evoApeSe3(gt, est, 0.01).statistics;
}

/// A CSV field: quoted when it holds a separator, a quote or a line break.
std::string csvField(const std::string& s) {
  if (s.find_first_of(",\"\n\r") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

std::string number(const std::optional<double>& v) {
  if (!v) return "";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.9g", *v);
  return buf;
}

}  // namespace

JobResult collectJob(const SweepSpec& spec, const Job& job) {
  JobResult r;
  r.job = &job;
  const auto summary = readRunSummary((fs::path(job.dir) / "summary.json").string());
  if (!summary) {
    r.reason = fs::exists(job.dir) ? "no readable summary.json (interrupted or still running?)"
                                   : "not run yet";
    return r;
  }
  r.fps = summary->number("fps");
  const std::string status = summary->get("status");
  if (status != "ok") {
    const std::string error = summary->get("error");
    r.reason = "dynslam " + (status.empty() ? std::string("status unknown") : status) +
               (error.empty() ? "" : ": " + error);
    return r;
  }
  if (!spec.gts.empty()) {
    try {
      score(spec.gts[job.rawlog], (fs::path(job.dir) / "trajectory.tum").string(), r);
    } catch (const std::exception& e) {
      r.reason = std::string("evaluation: ") + e.what();
      return r;
    }
  }
  r.ok = true;
  return r;
}

std::string writeResultsCsv(const SweepSpec& spec, const std::vector<JobResult>& results) {
  const std::string path = (fs::path(spec.out) / "results.csv").string();
  core::AtomicTextFile file(path);  // dynslam-sweep killed while writing: the previous table stays
  std::ostream& out = file.stream();
  out << "job,rawlog";
  for (const auto& k : spec.keys) out << ',' << csvField(k.name());
  out << ",status,ape_rmse,ape_mean,ape_median,ape_std,rpe_rmse,rpe_mean,fps,reason,folder\n";
  for (const auto& r : results) {
    const Job& job = *r.job;
    out << job.index << ',' << csvField(spec.rawlogs[job.rawlog]);
    for (size_t k = 0; k < spec.keys.size(); ++k)
      out << ',' << csvField(spec.keys[k].values[job.combination.value_index[k]]);
    auto stat = [](const auto& s, double ev::ErrorStatistics::*field) {
      return s ? std::optional<double>((*s).*field) : std::nullopt;
    };
    out << ',' << (r.ok ? "ok" : "failed") << ',' << number(stat(r.ape, &ev::ErrorStatistics::rmse))
        << ',' << number(stat(r.ape, &ev::ErrorStatistics::mean)) << ','
        << number(stat(r.ape, &ev::ErrorStatistics::median)) << ','
        << number(stat(r.ape, &ev::ErrorStatistics::std)) << ','
        << number(stat(r.rpe, &ev::ErrorStatistics::rmse)) << ','
        << number(stat(r.rpe, &ev::ErrorStatistics::mean)) << ',' << number(r.fps) << ','
        << csvField(r.reason) << ',' << csvField(job.name) << '\n';
  }
  file.commit();
  return path;
}

}  // namespace dynslam::sweep
