#include "Runner.h"

#include <dynslam/core/ProgressReporter.h>
#include "AnnotatedOutput.h"
#include "GroundTruthScore.h"
#include "KeyframeLog.h"
#include "LiveView.h"
#include "RunConfiguration.h"
#include "TimingLog.h"

#include <dynslam/core/JsonWriter.h>
#include <dynslam/core/Pipeline.h>
#include <dynslam/core/TrajectoryFile.h>
#include <dynslam/io/FrameReader.h>
#include <dynslam/io/SensorSync.h>
#include <dynslam/io/TrajectoryWriter.h>
#include <dynslam/viz/MapScene.h>

#include <unistd.h>
#include <algorithm>
#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <set>
#include <thread>

namespace fs = std::filesystem;

namespace dynslam::runner {
namespace {

std::atomic<bool> g_interrupted{false};
extern "C" void onInterrupt(int) { g_interrupted = true; }

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  const size_t mid = v.size() / 2;
  std::nth_element(v.begin(), v.begin() + mid, v.end());
  if (v.size() % 2) return v[mid];
  return 0.5 * (v[mid] + *std::max_element(v.begin(), v.begin() + mid));
}

/// What the run did, for summary.json.
struct RunRecord {
  std::string status = "ok";
  std::string error;
  size_t frames = 0, poses = 0, imu_samples = 0, gnss_fixes = 0;
  size_t objects = 0;  ///< object trajectories written (objects/<id>.tum)
  double wall_s = 0.0;
  bool estimator = false;
  std::vector<double> lag_ms;  ///< --realtime: how late each frame reached the pipeline
  std::vector<double> dt_ms;   ///< --realtime: stamp differences between frames
  std::optional<ApeScore> ape;  ///< --gt
  std::string ape_error;        ///< --gt given but no score (nothing estimated, nothing associated)
  size_t map_points = 0;        ///< points in map.3Dscene's static map
};

/// --realtime: hands frames over on the schedule their stamps give, and records the lag.
class CameraRateClock {
 public:
  void waitFor(double stamp, RunRecord& rec) {
    using Clock = std::chrono::steady_clock;
    if (!started_) {
      start_ = Clock::now();
      first_ = stamp;
      started_ = true;
    } else {
      rec.dt_ms.push_back(1000.0 * (stamp - last_));
    }
    last_ = stamp;
    const auto due =
        start_ + std::chrono::duration_cast<Clock::duration>(
                     std::chrono::duration<double>(std::max(0.0, stamp - first_)));
    std::this_thread::sleep_until(due);
    rec.lag_ms.push_back(std::chrono::duration<double, std::milli>(Clock::now() - due).count());
  }

 private:
  bool started_ = false;
  double first_ = 0, last_ = 0;
  std::chrono::steady_clock::time_point start_;
};

void writeSummary(const std::string& path, const RunnerArgs& args, const RunRecord& rec,
                  const io::FrameReader* reader, const core::Pipeline* pipeline) {
  std::ofstream out(path);
  core::JsonWriter j(out);
  j.beginObject();
  j.member("status", rec.status);
  if (!rec.error.empty()) j.member("error", rec.error);
  j.member("config", args.config).member("rawlog", args.rawlog);
  j.key("overrides").beginArray();
  for (const auto& o : args.overrides) j.value(o);
  j.endArray();
  j.member("frames", rec.frames).member("poses", rec.poses).member("objects", rec.objects);
  j.member("estimator", rec.estimator);
  j.member("imu_samples", rec.imu_samples).member("gnss_fixes", rec.gnss_fixes);
  j.member("wall_time_s", rec.wall_s);
  j.member("fps", rec.wall_s > 0 ? rec.frames / rec.wall_s : 0.0);
  if (rec.ape) {
    const ApeScore& a = *rec.ape;
    j.key("ape").beginObject();
    j.member("ground_truth", args.ground_truth).member("alignment", "se3");
    j.member("pose_relation", "translation_part").member("unit", "m");
    j.member("pairs", a.pairs).member("max_pairs", a.max_pairs);
    const evaluation::ErrorStatistics& st = a.statistics;
    j.member("rmse", st.rmse).member("mean", st.mean).member("median", st.median);
    j.member("std", st.std).member("min", st.min).member("max", st.max).member("sse", st.sse);
    j.endObject();
  } else if (!rec.ape_error.empty()) {
    j.member("ape_error", rec.ape_error);
  }
  if (args.map) j.member("map_points", rec.map_points);
  if (args.realtime) {
    // A frame is late when it reached the pipeline more than one camera interval after its
    // stamp's due time: the stages (not counting the detector thread) fell behind the camera.
    const double interval = median(rec.dt_ms);
    const auto late = std::count_if(rec.lag_ms.begin(), rec.lag_ms.end(),
                                    [&](double l) { return l > interval; });
    j.key("realtime").beginObject();
    j.member("camera_interval_ms", interval).member("lag_median_ms", median(rec.lag_ms));
    j.member("lag_max_ms",
             rec.lag_ms.empty() ? 0.0 : *std::max_element(rec.lag_ms.begin(), rec.lag_ms.end()));
    j.member("frames_late", static_cast<size_t>(late));
    j.endObject();
  }
  if (reader) {
    const io::SyncCounts c = reader->counts();
    j.key("observations").beginObject();
    j.member("total", c.observations).member("rgbd", c.rgbd).member("imu", c.imu);
    j.member("gnss", c.gnss).member("gnss_dropped", c.gnss_dropped).member("other", c.other);
    j.member("frames_without_depth", c.frames_without_depth);
    j.key("by_type").beginObject();
    for (const auto& [type, n] : c.by_type) j.member(type, n);
    j.endObject().endObject();
  }
  j.key("stages").beginArray();
  if (pipeline) {
    const auto stats = pipeline->statistics();
    for (size_t i = 0; i < pipeline->times().size(); ++i) {
      const auto& t = pipeline->times()[i];
      j.beginObject().member("name", t.name).member("median_ms", median(t.ms));
      j.member("frames", t.ms.size());
      if (!stats[i].empty()) {
        j.key("statistics").beginObject();
        for (const auto& [name, value] : stats[i]) j.member(name, value);
        j.endObject();
      }
      j.endObject();
    }
  }
  j.endArray();
  j.endObject();
}

/// Appends one line to OUT/objects/<id>.tum, creating (truncating) the file the first time this
/// run writes it. Opened and closed per line: a long run follows thousands of objects, and one
/// open stream each would hold a buffer and a file descriptor per object for the whole run
/// (the 10,000-frame soak grew by 5 MB with 525 of them open).
void appendObjectPose(const std::string& out, int id, const core::StampedPose& pose,
                      std::set<int>& created) {
  const fs::path dir = fs::path(out) / "objects";
  const bool first = created.insert(id).second;
  if (first) fs::create_directories(dir);
  const std::string path = (dir / (std::to_string(id) + ".tum")).string();
  std::ofstream file(path, first ? std::ios::trunc : std::ios::app);
  core::appendTumLine(file, pose);
  if (!file) throw std::runtime_error("cannot write the object trajectory '" + path + "'");
}

/// --gt: the APE of what trajectory.tum holds (read back, as evo would read it).
void scoreRun(const RunnerArgs& args, const core::Trajectory& ground_truth, size_t poses,
              RunRecord& rec) {
  if (poses == 0) {
    rec.ape_error = "no pose was estimated";
    return;
  }
  try {
    rec.ape = scoreAgainstGroundTruth(
        ground_truth, core::readTum((fs::path(args.out) / "trajectory.tum").string()));
  } catch (const std::exception& e) {
    rec.ape_error = e.what();
  }
}

}  // namespace

int runDynslam(const RunnerArgs& args) {
  const auto start = std::chrono::steady_clock::now();
  RunRecord rec;
  std::optional<core::Pipeline> pipeline;
  std::optional<io::FrameReader> reader;
  std::optional<io::TumTrajectoryWriter> trajectory;
  std::set<int> objectFiles;  // ids whose objects/<id>.tum this run has created
  std::optional<AnnotatedOutput> annotated;
  std::optional<TimingLog> timing;
  std::optional<KeyframeLog> keyframeLog;   // with a pose estimator
  std::optional<viz::MapSceneBuilder> map;  // also built for --gui, saved only with args.map
  std::optional<LiveView> live;
  std::optional<core::Frame> lastFrame;  // --gui: the last frame, shown once more at the end
  core::Trajectory groundTruth;

  std::error_code ec;
  fs::create_directories(args.out, ec);
  if (ec) {
    std::cerr << "dynslam: error: cannot create output folder '" << args.out
              << "': " << ec.message() << "\n";
    return 1;
  }
  const std::string summaryPath = (fs::path(args.out) / "summary.json").string();
  if (!args.frames_dir.empty()) fs::create_directories(args.frames_dir, ec);
  if (ec) {
    std::cerr << "dynslam: error: cannot create the --frames folder '" << args.frames_dir
              << "': " << ec.message() << "\n";
    return 1;
  }

  try {
    trajectory.emplace((fs::path(args.out) / "trajectory.tum").string());
    if (!args.ground_truth.empty()) groundTruth = readGroundTruth(args.ground_truth);
    if (!args.frames_dir.empty()) annotated.emplace(args.frames_dir, args.frames_video);
    if (args.map || args.gui) {
      viz::MapSceneOptions mapOptions;
      mapOptions.every_n_frames = args.map_every_n_frames;
      mapOptions.voxel_size = args.map_voxel_size;
      map.emplace(mapOptions);
    }
    auto configured = configureRun(core::IniConfig::fromFile(args.config, args.overrides));
    pipeline.emplace(std::move(configured.pipeline));
    const io::SensorSyncOptions syncOptions = configured.sync;
    timing.emplace((fs::path(args.out) / "timing.csv").string(), *pipeline);
    rec.estimator = pipeline->estimatesPose();
    if (rec.estimator) keyframeLog.emplace((fs::path(args.out) / "keyframes.csv").string());
    if (!rec.estimator)
      std::cerr << "dynslam: no pose estimator in [pipeline] stages of " << args.config
                << ": frames are read and processed, but trajectory.tum stays empty\n";

    reader.emplace(args.rawlog, syncOptions);
    if (args.gui) {
      LiveViewOptions liveOptions;
      liveOptions.max_rate_hz = args.gui_max_rate_hz;
      live.emplace(liveOptions);
    }
    core::ProgressReporter progress(stderr, !args.quiet && isatty(STDERR_FILENO) != 0);
    std::signal(SIGINT, onInterrupt);
    CameraRateClock cameraRate;
    while (!g_interrupted) {
      if (args.max_frames >= 0 && static_cast<long>(rec.frames) >= args.max_frames) break;
      std::optional<core::Frame> next = reader->next();
      if (!next) break;
      core::Frame& frame = *next;
      if (args.realtime) cameraRate.waitFor(frame.t, rec);
      const auto processStart = std::chrono::steady_clock::now();
      pipeline->process(frame);
      timing->append(
          frame.index, frame.t, *pipeline,
          std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - processStart)
              .count());
      if (keyframeLog) keyframeLog->append(frame);
      if (annotated) annotated->write(frame);
      if (map) map->addFrame(frame);
      if (live) {
        live->update(frame, *map);
        lastFrame = frame;
      }
      ++rec.frames;
      rec.imu_samples += frame.imu.size();
      rec.gnss_fixes += frame.gnss.size();
      if (frame.T_world_camera) {
        trajectory->append({frame.t, *frame.T_world_camera});
        ++rec.poses;
      }
      for (const auto& object : frame.object_poses)
        appendObjectPose(args.out, object.object_id, {frame.t, object.T_world_object}, objectFiles);
      rec.objects = objectFiles.size();
      if (!args.quiet) progress.update(rec.frames, reader->progress());
    }
    pipeline->finish();
    if (annotated) annotated->finish();
    if (live && lastFrame) live->update(*lastFrame, *map, true);
    if (g_interrupted) {
      rec.status = "interrupted";
      std::cerr << "\ndynslam: interrupted; outputs hold the first " << rec.frames << " frames\n";
    }
    if (!args.quiet) progress.finish(rec.frames);
  } catch (const std::exception& e) {
    rec.status = "failed";
    rec.error = e.what();
    std::cerr << "\ndynslam: error: " << e.what() << "\n";
    if (trajectory)
      std::cerr << "dynslam: " << trajectory->path() << " holds the " << trajectory->count()
                << " poses estimated before the error\n";
  }
  rec.poses = trajectory ? trajectory->count() : 0;
  rec.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  // The map holds what was done, also after an error or Ctrl-C (like trajectory.tum); its
  // saving is not part of the frame rate.
  // After the frame rate is taken: the screenshot waits for the window to redraw.
  if (live && !args.gui_screenshot.empty()) {
    try {
      const std::string source = live->saveScreenshot(args.gui_screenshot);
      std::cerr << "dynslam: wrote " << args.gui_screenshot << " (" << source << " image, "
                << live->updates() << " window updates)\n";
    } catch (const std::exception& e) {
      std::cerr << "dynslam: error: " << e.what() << "\n";
      if (rec.status == "ok") {
        rec.status = "failed";
        rec.error = e.what();
      }
    }
  }
  if (live)
    std::cerr << "dynslam: --gui: " << live->updates() << " window updates, "
              << (live->updates() ? 1000.0 * live->updateSeconds() / live->updates() : 0.0)
              << " ms each on the run's thread\n";
  if (map && args.map) {
    const std::string mapPath = (fs::path(args.out) / "map.3Dscene").string();
    try {
      map->save(mapPath);
      rec.map_points = map->pointCount();
    } catch (const std::exception& e) {
      std::cerr << "dynslam: error: " << e.what() << "\n";
      if (rec.status == "ok") {
        rec.status = "failed";
        rec.error = e.what();
      }
    }
  }
  if (!args.ground_truth.empty() && !groundTruth.empty())
    scoreRun(args, groundTruth, rec.poses, rec);
  writeSummary(summaryPath, args, rec, reader ? &*reader : nullptr,
               pipeline ? &*pipeline : nullptr);
  std::cerr << "dynslam: wrote " << summaryPath << "\n";
  std::printf("dynslam: %zu frames, %zu poses in %.1f s (%.1f FPS)\n", rec.frames, rec.poses,
              rec.wall_s, rec.wall_s > 0 ? rec.frames / rec.wall_s : 0.0);
  if (rec.ape)
    std::printf("dynslam: APE RMSE %.4f m (SE(3)-aligned, %zu of %zu poses associated) vs %s\n",
                rec.ape->statistics.rmse, rec.ape->pairs, rec.ape->max_pairs,
                args.ground_truth.c_str());
  else if (!rec.ape_error.empty())
    std::printf("dynslam: no APE: %s\n", rec.ape_error.c_str());
  std::fflush(stdout);
  const int code = rec.status == "failed" ? 1 : (rec.status == "interrupted" ? 130 : 0);
  if (live) {
    // MRPT's window is not destroyed: closing CDisplayWindow3D while its wx thread still draws
    // corrupted the heap in about 1 run of 3 under Xvfb ("malloc(): unsorted double linked
    // list corrupted", exit 134 / 139, summary.json never written). Every output is closed
    // first; the process then ends without running the GUI's destructors.
    trajectory.reset();
    timing.reset();
    keyframeLog.reset();
    std::fflush(nullptr);
    std::_Exit(code);
  }
  return code;
}

}  // namespace dynslam::runner
