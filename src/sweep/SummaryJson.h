#pragma once
// Reads the top-level scalar members of a dynslam summary.json ("status", "error", "fps",
// "frames", ...); nested objects and arrays are skipped. Enough JSON for files JsonWriter wrote.
// Written by hand because the one parser at hand, mrpt::containers::yaml (it reads our JSON
// fine), returns what it parsed of a truncated file, {"status": "ok", "fr -> status ok, with
// only a message on stderr: a job killed while writing its summary would count as done.
#include <map>
#include <optional>
#include <string>

namespace dynslam::sweep {

struct RunSummary {
  /// Top-level members with a string, number, true/false or null value, as text (strings
  /// unescaped).
  std::map<std::string, std::string> members;
  std::string get(const std::string& key) const;  ///< "" when absent
  std::optional<double> number(const std::string& key) const;
};

/// nullopt when the file is absent, unreadable or not a JSON object (a run still writing it,
/// or one killed before it wrote anything).
std::optional<RunSummary> readRunSummary(const std::string& path);

/// True when `dir`/summary.json exists and says "status": "ok": the job's completed marker.
bool jobCompleted(const std::string& dir);

}  // namespace dynslam::sweep
