#include "Runner.h"

#include <dynslam/core/ProgressReporter.h>
#include "BuiltinStages.h"

#include <dynslam/core/JsonWriter.h>
#include <dynslam/core/Pipeline.h>
#include <dynslam/core/StageRegistry.h>
#include <dynslam/io/RawlogSource.h>
#include <dynslam/io/SensorSync.h>
#include <dynslam/io/TrajectoryWriter.h>
#include <dynslam/viz/AnnotatedFrame.h>

#include <opencv2/imgcodecs.hpp>

#include <unistd.h>
#include <algorithm>
#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>

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
  double wall_s = 0.0;
  bool estimator = false;
};

void writeSummary(const std::string& path, const RunnerArgs& args, const RunRecord& rec,
                  const io::SensorSync* sync, const core::Pipeline* pipeline) {
  std::ofstream out(path);
  core::JsonWriter j(out);
  j.beginObject();
  j.member("status", rec.status);
  if (!rec.error.empty()) j.member("error", rec.error);
  j.member("config", args.config).member("rawlog", args.rawlog);
  j.key("overrides").beginArray();
  for (const auto& o : args.overrides) j.value(o);
  j.endArray();
  j.member("frames", rec.frames).member("poses", rec.poses);
  j.member("estimator", rec.estimator);
  j.member("imu_samples", rec.imu_samples).member("gnss_fixes", rec.gnss_fixes);
  j.member("wall_time_s", rec.wall_s);
  j.member("fps", rec.wall_s > 0 ? rec.frames / rec.wall_s : 0.0);
  if (sync) {
    const auto& c = sync->counts();
    j.key("observations").beginObject();
    j.member("total", c.observations).member("rgbd", c.rgbd).member("imu", c.imu);
    j.member("gnss", c.gnss).member("gnss_dropped", c.gnss_dropped).member("other", c.other);
    j.member("frames_without_depth", c.frames_without_depth);
    j.key("by_type").beginObject();
    for (const auto& [type, n] : c.by_type) j.member(type, n);
    j.endObject().endObject();
  }
  j.key("stages").beginArray();
  if (pipeline)
    for (const auto& t : pipeline->times()) {
      j.beginObject().member("name", t.name).member("median_ms", median(t.ms));
      j.member("frames", t.ms.size()).endObject();
    }
  j.endArray();
  j.endObject();
}

/// DIR/NNNNNN.png: the frame after every stage, as viz::renderAnnotatedFrame draws it.
void writeAnnotatedFrame(const std::string& dir, const core::Frame& frame) {
  char name[32];
  std::snprintf(name, sizeof name, "%06zu.png", frame.index);
  const std::string path = (fs::path(dir) / name).string();
  if (!cv::imwrite(path, viz::renderAnnotatedFrame(frame)))
    throw std::runtime_error("cannot write the annotated frame '" + path + "'");
}

}  // namespace

int runDynslam(const RunnerArgs& args) {
  const auto start = std::chrono::steady_clock::now();
  RunRecord rec;
  std::optional<core::Pipeline> pipeline;
  std::optional<io::SensorSync> sync;
  std::optional<io::TumTrajectoryWriter> trajectory;

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
    const auto cfg = core::IniConfig::fromFile(args.config, args.overrides);
    core::StageRegistry registry;
    registerBuiltinStages(registry);
    pipeline.emplace(cfg, registry);
    io::SensorSyncOptions syncOptions;
    core::loadOptionsStrict(syncOptions, cfg, io::SensorSync::kSection);
    auto known = pipeline->sectionsUsed();
    known.push_back(io::SensorSync::kSection);
    core::rejectUnknownSections(cfg, known);
    sync.emplace(syncOptions);
    rec.estimator = pipeline->estimatesPose();
    if (!rec.estimator)
      std::cerr << "dynslam: no pose estimator in [pipeline] stages of " << args.config
                << ": frames are read and processed, but trajectory.tum stays empty\n";

    io::RawlogSource source(args.rawlog);
    core::ProgressReporter progress(stderr, !args.quiet && isatty(STDERR_FILENO) != 0);
    std::signal(SIGINT, onInterrupt);
    std::vector<core::Frame> ready;
    bool more = true;
    while (more && !g_interrupted) {
      const auto obs = source.next();
      if (obs)
        sync->push(obs, ready);
      else {
        sync->flush(ready);
        more = false;
      }
      for (auto& frame : ready) {
        if (args.max_frames >= 0 && static_cast<long>(rec.frames) >= args.max_frames) {
          more = false;
          break;
        }
        pipeline->process(frame);
        if (!args.frames_dir.empty()) writeAnnotatedFrame(args.frames_dir, frame);
        ++rec.frames;
        rec.imu_samples += frame.imu.size();
        rec.gnss_fixes += frame.gnss.size();
        if (frame.T_world_camera) {
          trajectory->append({frame.t, *frame.T_world_camera});
          ++rec.poses;
        }
      }
      ready.clear();
      if (!args.quiet) progress.update(rec.frames, source.progress());
    }
    pipeline->finish();
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
  writeSummary(summaryPath, args, rec, sync ? &*sync : nullptr, pipeline ? &*pipeline : nullptr);
  std::cerr << "dynslam: wrote " << summaryPath << "\n";
  return rec.status == "failed" ? 1 : (rec.status == "interrupted" ? 130 : 0);
}

}  // namespace dynslam::runner
