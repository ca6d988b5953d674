#pragma once
// summary.json: what a dynslam run did (status, counts, frame rate, the APE with --gt, the
// realtime lag, the rawlog's observations, each stage's median time and statistics). The keys
// are listed in docs/programs.md.
#include "GroundTruthScore.h"
#include "Runner.h"

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace dynslam::core {
class Pipeline;
}
namespace dynslam::io {
struct SyncCounts;
}

namespace dynslam::runner {

/// User + system CPU time this process has used so far, all threads, s.
double processCpuSeconds();

/// What the run did, for summary.json.
struct RunRecord {
  std::string status = "ok";
  std::string error;
  size_t frames = 0, poses = 0, imu_samples = 0, gnss_fixes = 0;
  size_t objects = 0;  ///< object trajectories written (objects/<id>.tum)
  double wall_s = 0.0;
  double cpu_s = 0.0;  ///< user + system time of every thread over the run
  bool estimator = false;
  std::vector<double> lag_ms;   ///< --realtime: how late each frame reached the pipeline
  std::vector<double> dt_ms;    ///< --realtime: stamp differences between frames
  std::optional<ApeScore> ape;  ///< --gt
  std::string ape_error;        ///< --gt given but no score (nothing estimated, nothing associated)
  size_t map_points = 0;        ///< points in map.3Dscene's static map
  size_t sensor_drops = 0;      ///< --sensors: observations dropped for a full queue

  /// Marks the run failed with `what`, unless it has failed or been interrupted already.
  void failIfOk(const std::string& what);
};

/// The median (0 for none); of an even count, the mean of the two middle values.
double median(std::vector<double> v);

/// Writes summary.json; `counts` (the observations read) and `pipeline` may be null (the run
/// failed before them).
void writeSummary(const std::string& path, const RunnerArgs& args, const RunRecord& rec,
                  const io::SyncCounts* counts, const core::Pipeline* pipeline);

}  // namespace dynslam::runner
