#include "sweep/SweepJobs.h"

#include <dynslam/core/AtomicFile.h>

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <stdexcept>

namespace fs = std::filesystem;

namespace dynslam::sweep {
namespace {

constexpr size_t kMaxNameLength = 96;

/// FNV-1a: a stable hash (std::hash may differ between builds, and a resumed sweep must find
/// the folders an earlier build named).
std::string hashHex(const std::string& s) {
  uint64_t h = 1469598103934665603ull;
  for (unsigned char c : s) h = (h ^ c) * 1099511628211ull;
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
  return std::string(buf, 10);
}

bool safeChar(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '.' ||
         c == '=' || c == '-' || c == '+' || c == ',' || c == '_';
}

std::string sanitized(const std::string& s) {
  std::string out = s;
  for (char& c : out)
    if (!safeChar(c)) c = '_';
  return out;
}

std::string folderName(const std::string& stem, const std::vector<std::string>& swept) {
  std::string name = sanitized(stem);
  for (const auto& s : swept) name += "__" + sanitized(s);
  if (name.size() <= kMaxNameLength) return name;
  const std::string hash = hashHex(name);
  return name.substr(0, kMaxNameLength - hash.size() - 1) + "-" + hash;
}

/// Rawlog stems, made unique with a hash of the path where two rawlogs share one.
std::vector<std::string> rawlogStems(const std::vector<std::string>& rawlogs) {
  std::vector<std::string> stems;
  for (const auto& r : rawlogs) stems.push_back(fs::path(r).stem().string());
  for (size_t i = 0; i < stems.size(); ++i)
    for (size_t j = 0; j < stems.size(); ++j)
      if (i != j && fs::path(rawlogs[i]).stem() == fs::path(rawlogs[j]).stem()) {
        stems[i] = fs::path(rawlogs[i]).stem().string() + "-" + hashHex(rawlogs[i]);
        break;
      }
  return stems;
}

}  // namespace

std::vector<Job> makeJobs(const SweepSpec& spec) {
  std::vector<Job> jobs;
  const auto stems = rawlogStems(spec.rawlogs);
  const auto combos = combinations(spec.keys);
  for (size_t r = 0; r < spec.rawlogs.size(); ++r)
    for (const auto& c : combos) {
      Job job;
      job.index = jobs.size();
      job.rawlog = r;
      job.combination = c;
      const auto swept = overridesOf(spec.keys, c);
      job.overrides = spec.sets;
      job.overrides.insert(job.overrides.end(), swept.begin(), swept.end());
      job.name = folderName(stems[r], swept);
      job.dir = (fs::path(spec.out) / "jobs" / job.name).string();
      jobs.push_back(std::move(job));
    }
  return jobs;
}

std::vector<std::string> dynslamArgv(const SweepSpec& spec, const Job& job) {
  std::vector<std::string> argv{
      spec.dynslam, "--config", spec.config, "--rawlog", spec.rawlogs[job.rawlog],
      "--out",      job.dir,    "--quiet"};
  if (!spec.keep_maps) argv.push_back("--no-map");
  for (const auto& o : job.overrides) {
    argv.push_back("--set");
    argv.push_back(o);
  }
  return argv;
}

std::string shellQuote(const std::string& s) {
  bool plain = !s.empty();
  for (char c : s) plain = plain && (safeChar(c) || c == '/' || c == ':');
  if (plain) return s;
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

std::string shellLine(const SweepSpec& spec, const Job& job) {
  const std::string dir = shellQuote(job.dir);
  std::string command;
  for (const auto& a : dynslamArgv(spec, job))
    command += (command.empty() ? "" : " ") + shellQuote(a);
  const std::string summary = shellQuote(job.dir + "/summary.json");
  return "grep -qs '\"status\": \"ok\"' " + summary + " || { mkdir -p " + dir + " && " + command +
         " > " + shellQuote(job.dir + "/dynslam.log") + " 2>&1; }";
}

std::string writeJobList(const SweepSpec& spec, const std::vector<Job>& jobs) {
  const std::string path = (fs::path(spec.out) / "jobs.txt").string();
  core::AtomicTextFile file(path);
  for (const auto& job : jobs) file.stream() << shellLine(spec, job) << '\n';
  file.commit();
  return path;
}

std::string writeSlurmScript(const SweepSpec& spec, const std::vector<Job>& jobs,
                             const std::string& jobList, int throttle) {
  const std::string path = (fs::path(spec.out) / "sweep.slurm").string();
  core::AtomicTextFile file(path);
  std::ostream& out = file.stream();
  out << "#!/bin/bash\n"
      << "# dynslam-sweep job array: task i runs line i+1 of the job list (one dynslam run).\n"
      << "# Submit with: sbatch " << shellQuote(path) << "\n"
      << "# Paths are as dynslam-sweep was given them: relative ones are taken from the folder\n"
      << "# sbatch runs in (Slurm's default working directory), so submit from that same folder.\n"
      << "#SBATCH --job-name=dynslam-sweep\n"
      << "#SBATCH --array=0-" << (jobs.empty() ? 0 : jobs.size() - 1)
      << (throttle > 0 ? "%" + std::to_string(throttle) : std::string()) << "\n"
      << "#SBATCH --ntasks=1\n"
      << "#SBATCH --cpus-per-task=1\n"
      << "#SBATCH --output=" << (fs::path(spec.out) / "slurm-%A_%a.log").string() << "\n"
      << "set -euo pipefail\n"
      << "line=$(sed -n \"$((SLURM_ARRAY_TASK_ID + 1))p\" " << shellQuote(jobList) << ")\n"
      << "exec bash -c \"$line\"\n";
  file.commit();
  return path;
}

}  // namespace dynslam::sweep
