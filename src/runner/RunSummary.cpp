#include "RunSummary.h"

#include <dynslam/core/AtomicFile.h>
#include <dynslam/core/JsonWriter.h>
#include <dynslam/core/Pipeline.h>
#include <dynslam/io/SensorSync.h>

#include <sys/resource.h>

#include <algorithm>

namespace dynslam::runner {

void RunRecord::failIfOk(const std::string& what) {
  if (status != "ok") return;
  status = "failed";
  error = what;
}

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  const size_t mid = v.size() / 2;
  std::nth_element(v.begin(), v.begin() + mid, v.end());
  if (v.size() % 2) return v[mid];
  return 0.5 * (v[mid] + *std::max_element(v.begin(), v.begin() + mid));
}

namespace {

void writeApe(core::JsonWriter& j, const RunnerArgs& args, const ApeScore& a) {
  j.key("ape").beginObject();
  j.member("ground_truth", args.ground_truth).member("alignment", "se3");
  j.member("pose_relation", "translation_part").member("unit", "m");
  j.member("pairs", a.pairs).member("max_pairs", a.max_pairs);
  const evaluation::ErrorStatistics& st = a.statistics;
  j.member("rmse", st.rmse).member("mean", st.mean).member("median", st.median);
  j.member("std", st.std).member("min", st.min).member("max", st.max).member("sse", st.sse);
  j.endObject();
}

void writeRealtime(core::JsonWriter& j, const RunRecord& rec) {
  // A frame is late when it reached the pipeline more than one camera interval after its
  // stamp's due time: the stages (not counting the detector thread) fell behind the camera.
  const double interval = median(rec.dt_ms);
  const auto late =
      std::count_if(rec.lag_ms.begin(), rec.lag_ms.end(), [&](double l) { return l > interval; });
  j.key("realtime").beginObject();
  j.member("camera_interval_ms", interval).member("lag_median_ms", median(rec.lag_ms));
  j.member("lag_max_ms",
           rec.lag_ms.empty() ? 0.0 : *std::max_element(rec.lag_ms.begin(), rec.lag_ms.end()));
  j.member("frames_late", static_cast<size_t>(late));
  j.endObject();
}

void writeObservations(core::JsonWriter& j, const io::SyncCounts& c) {
  j.key("observations").beginObject();
  j.member("total", c.observations).member("rgbd", c.rgbd).member("imu", c.imu);
  j.member("gnss", c.gnss).member("gnss_dropped", c.gnss_dropped).member("other", c.other);
  j.member("frames_without_depth", c.frames_without_depth);
  j.key("by_type").beginObject();
  for (const auto& [type, n] : c.by_type) j.member(type, n);
  j.endObject().endObject();
}

void writeStages(core::JsonWriter& j, const core::Pipeline* pipeline) {
  j.key("stages").beginArray();
  if (pipeline) {
    const auto stats = pipeline->statistics();
    for (size_t i = 0; i < pipeline->times().size(); ++i) {
      const auto& t = pipeline->times()[i];
      j.beginObject().member("name", t.name).member("median_ms", median(t.ms.samples()));
      j.member("frames", t.ms.count());
      if (!stats[i].empty()) {
        j.key("statistics").beginObject();
        for (const auto& [name, value] : stats[i]) j.member(name, value);
        j.endObject();
      }
      j.endObject();
    }
  }
  j.endArray();
}

}  // namespace

double processCpuSeconds() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  const auto seconds = [](const timeval& t) { return double(t.tv_sec) + 1e-6 * double(t.tv_usec); };
  return seconds(usage.ru_utime) + seconds(usage.ru_stime);
}

void writeSummary(const std::string& path, const RunnerArgs& args, const RunRecord& rec,
                  const io::SyncCounts* counts, const core::Pipeline* pipeline) {
  core::AtomicTextFile file(path);  // a run killed while writing leaves no half summary
  core::JsonWriter j(file.stream());
  j.beginObject();
  j.member("status", rec.status);
  if (!rec.error.empty()) j.member("error", rec.error);
  j.member("config", args.config);
  if (args.sensors.empty())
    j.member("rawlog", args.rawlog);
  else
    j.member("sensors", args.sensors).member("sensor_observations_dropped", rec.sensor_drops);
  j.key("overrides").beginArray();
  for (const auto& o : args.overrides) j.value(o);
  j.endArray();
  j.member("frames", rec.frames).member("poses", rec.poses).member("objects", rec.objects);
  j.member("estimator", rec.estimator);
  j.member("imu_samples", rec.imu_samples).member("gnss_fixes", rec.gnss_fixes);
  j.member("wall_time_s", rec.wall_s);
  j.member("fps", rec.wall_s > 0 ? rec.frames / rec.wall_s : 0.0);
  // Cores the run kept busy on average: what a robot's planner has left of the machine.
  j.member("cpu_time_s", rec.cpu_s);
  j.member("cpu_cores", rec.wall_s > 0 ? rec.cpu_s / rec.wall_s : 0.0);
  if (rec.ape)
    writeApe(j, args, *rec.ape);
  else if (!rec.ape_error.empty())
    j.member("ape_error", rec.ape_error);
  if (args.map) j.member("map_points", rec.map_points);
  if (args.realtime) writeRealtime(j, rec);
  if (counts) writeObservations(j, *counts);
  writeStages(j, pipeline);
  j.endObject();
  file.commit();
}

}  // namespace dynslam::runner
