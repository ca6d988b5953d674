#include "Runner.h"

#include <dynslam/core/ProgressReporter.h>
#include "AnnotatedOutput.h"
#include "GroundTruthScore.h"
#include "KeyframeLog.h"
#include "LiveView.h"
#include "RunConfiguration.h"
#include "RunSummary.h"
#include "TimingLog.h"

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
    const auto due = start_ + std::chrono::duration_cast<Clock::duration>(
                                  std::chrono::duration<double>(std::max(0.0, stamp - first_)));
    std::this_thread::sleep_until(due);
    rec.lag_ms.push_back(std::chrono::duration<double, std::milli>(Clock::now() - due).count());
  }

 private:
  bool started_ = false;
  double first_ = 0, last_ = 0;
  std::chrono::steady_clock::time_point start_;
};

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

/// The output folder and the --frames folder; false (the reason on stderr) when one cannot be
/// made.
bool createFolders(const RunnerArgs& args) {
  std::error_code ec;
  fs::create_directories(args.out, ec);
  if (ec) {
    std::cerr << "dynslam: error: cannot create output folder '" << args.out
              << "': " << ec.message() << "\n";
    return false;
  }
  if (!args.frames_dir.empty()) fs::create_directories(args.frames_dir, ec);
  if (ec) {
    std::cerr << "dynslam: error: cannot create the --frames folder '" << args.frames_dir
              << "': " << ec.message() << "\n";
    return false;
  }
  return true;
}

/// One run of the dynslam program, in the order its phases happen: open the outputs, configure
/// the stages, play the frames, finish the outputs, then report (summary.json and stdout).
class DynslamRun {
 public:
  explicit DynslamRun(const RunnerArgs& args) : args_(args) {}

  int run() {
    if (!createFolders(args_)) return 1;
    try {
      openOutputs();
      configure();
      playFrames();
      finishPlayback();
    } catch (const std::exception& e) {
      recordFailure(e);
    }
    rec_.poses = trajectory_ ? trajectory_->count() : 0;
    rec_.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    rec_.cpu_s = processCpuSeconds() - startCpu_;
    finishOutputs();
    report();
    return exitCode();
  }

 private:
  std::string outPath(const char* name) const { return (fs::path(args_.out) / name).string(); }

  void openOutputs() {
    trajectory_.emplace(outPath("trajectory.tum"));
    if (!args_.ground_truth.empty()) groundTruth_ = readGroundTruth(args_.ground_truth);
    if (!args_.frames_dir.empty()) annotated_.emplace(args_.frames_dir, args_.frames_video);
    if (args_.map || args_.gui) {
      viz::MapSceneOptions mapOptions;
      mapOptions.every_n_frames = args_.map_every_n_frames;
      mapOptions.voxel_size = args_.map_voxel_size;
      map_.emplace(mapOptions);
    }
  }

  void configure() {
    auto configured = configureRun(core::IniConfig::fromFile(args_.config, args_.overrides));
    pipeline_.emplace(std::move(configured.pipeline));
    const io::SensorSyncOptions syncOptions = configured.sync;
    timing_.emplace(outPath("timing.csv"), *pipeline_);
    rec_.estimator = pipeline_->estimatesPose();
    if (rec_.estimator) keyframeLog_.emplace(outPath("keyframes.csv"));
    if (!rec_.estimator)
      std::cerr << "dynslam: no pose estimator in [pipeline] stages of " << args_.config
                << ": frames are read and processed, but trajectory.tum stays empty\n";
    reader_.emplace(args_.rawlog, syncOptions);
    if (args_.gui) {
      LiveViewOptions liveOptions;
      liveOptions.max_rate_hz = args_.gui_max_rate_hz;
      live_.emplace(liveOptions);
    }
  }

  void playFrames() {
    progress_.emplace(stderr, !args_.quiet && isatty(STDERR_FILENO) != 0);
    std::signal(SIGINT, onInterrupt);
    CameraRateClock cameraRate;
    while (!g_interrupted) {
      if (args_.max_frames >= 0 && static_cast<long>(rec_.frames) >= args_.max_frames) break;
      std::optional<core::Frame> next = reader_->next();
      if (!next) break;
      core::Frame& frame = *next;
      if (args_.realtime) cameraRate.waitFor(frame.t, rec_);
      const auto processStart = std::chrono::steady_clock::now();
      pipeline_->process(frame);
      timing_->append(
          frame.index, frame.t, *pipeline_,
          std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - processStart)
              .count());
      writeFrame(frame);
      if (!args_.quiet) progress_->update(rec_.frames, reader_->progress());
    }
  }

  /// Everything one processed frame adds to the outputs and to the record.
  void writeFrame(const core::Frame& frame) {
    if (keyframeLog_) keyframeLog_->append(frame);
    if (annotated_) annotated_->write(frame);
    if (map_) map_->addFrame(frame);
    if (live_) {
      live_->update(frame, *map_);
      lastFrame_ = frame;
    }
    ++rec_.frames;
    rec_.imu_samples += frame.imu.size();
    rec_.gnss_fixes += frame.gnss.size();
    if (frame.T_world_camera) {
      trajectory_->append({frame.t, *frame.T_world_camera});
      ++rec_.poses;
    }
    for (const auto& object : frame.object_poses)
      appendObjectPose(args_.out, object.object_id, {frame.t, object.T_world_object}, objectFiles_);
    rec_.objects = objectFiles_.size();
  }

  void finishPlayback() {
    pipeline_->finish();
    if (annotated_) annotated_->finish();
    if (live_ && lastFrame_) live_->update(*lastFrame_, *map_, true);
    if (g_interrupted) {
      rec_.status = "interrupted";
      std::cerr << "\ndynslam: interrupted; outputs hold the first " << rec_.frames << " frames\n";
    }
    if (!args_.quiet) progress_->finish(rec_.frames);
  }

  void recordFailure(const std::exception& e) {
    rec_.status = "failed";
    rec_.error = e.what();
    std::cerr << "\ndynslam: error: " << e.what() << "\n";
    if (trajectory_)
      std::cerr << "dynslam: " << trajectory_->path() << " holds the " << trajectory_->count()
                << " poses estimated before the error\n";
  }

  /// What is written once the frames are done, also after an error or Ctrl-C (like
  /// trajectory.tum, the map holds what was done); after the frame rate is taken, as neither
  /// is part of it (the screenshot waits for the window to redraw).
  void finishOutputs() {
    if (live_ && !args_.gui_screenshot.empty()) {
      try {
        const std::string source = live_->saveScreenshot(args_.gui_screenshot);
        std::cerr << "dynslam: wrote " << args_.gui_screenshot << " (" << source << " image, "
                  << live_->updates() << " window updates)\n";
      } catch (const std::exception& e) {
        std::cerr << "dynslam: error: " << e.what() << "\n";
        rec_.failIfOk(e.what());
      }
    }
    if (live_)
      std::cerr << "dynslam: --gui: " << live_->updates() << " window updates, "
                << (live_->updates() ? 1000.0 * live_->updateSeconds() / live_->updates() : 0.0)
                << " ms each on the run's thread\n";
    if (map_ && args_.map) {
      try {
        map_->save(outPath("map.3Dscene"));
        rec_.map_points = map_->pointCount();
      } catch (const std::exception& e) {
        std::cerr << "dynslam: error: " << e.what() << "\n";
        rec_.failIfOk(e.what());
      }
    }
  }

  /// --gt's score, summary.json, and the totals on stdout.
  void report() {
    if (!args_.ground_truth.empty() && !groundTruth_.empty())
      scoreRun(args_, groundTruth_, rec_.poses, rec_);
    const std::string summaryPath = outPath("summary.json");
    writeSummary(summaryPath, args_, rec_, reader_ ? &*reader_ : nullptr,
                 pipeline_ ? &*pipeline_ : nullptr);
    std::cerr << "dynslam: wrote " << summaryPath << "\n";
    std::printf("dynslam: %zu frames, %zu poses in %.1f s (%.1f FPS)\n", rec_.frames, rec_.poses,
                rec_.wall_s, rec_.wall_s > 0 ? rec_.frames / rec_.wall_s : 0.0);
    if (rec_.ape)
      std::printf("dynslam: APE RMSE %.4f m (SE(3)-aligned, %zu of %zu poses associated) vs %s\n",
                  rec_.ape->statistics.rmse, rec_.ape->pairs, rec_.ape->max_pairs,
                  args_.ground_truth.c_str());
    else if (!rec_.ape_error.empty())
      std::printf("dynslam: no APE: %s\n", rec_.ape_error.c_str());
    std::fflush(stdout);
  }

  int exitCode() {
    const int code = rec_.status == "failed" ? 1 : (rec_.status == "interrupted" ? 130 : 0);
    if (live_) {
      // MRPT's window is not destroyed: closing CDisplayWindow3D while its wx thread still
      // draws corrupted the heap in about 1 run of 3 under Xvfb ("malloc(): unsorted double
      // linked list corrupted", exit 134 / 139, summary.json never written). Every output is
      // closed first; the process then ends without running the GUI's destructors.
      trajectory_.reset();
      timing_.reset();
      keyframeLog_.reset();
      std::fflush(nullptr);
      std::_Exit(code);
    }
    return code;
  }

  const RunnerArgs& args_;
  const std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
  const double startCpu_ = processCpuSeconds();
  RunRecord rec_;
  core::Trajectory groundTruth_;
  std::optional<core::Pipeline> pipeline_;
  std::optional<io::FrameReader> reader_;
  std::optional<core::ProgressReporter> progress_;
  std::optional<io::TumTrajectoryWriter> trajectory_;
  std::set<int> objectFiles_;  // ids whose objects/<id>.tum this run has created
  std::optional<AnnotatedOutput> annotated_;
  std::optional<TimingLog> timing_;
  std::optional<KeyframeLog> keyframeLog_;   // with a pose estimator
  std::optional<viz::MapSceneBuilder> map_;  // also built for --gui, saved only with args.map
  std::optional<LiveView> live_;
  std::optional<core::Frame> lastFrame_;  // --gui: the last frame, shown once more at the end
};

}  // namespace

int runDynslam(const RunnerArgs& args) { return DynslamRun(args).run(); }

}  // namespace dynslam::runner
