#include "Runner.h"

#include <dynslam/core/ProgressReporter.h>
#include "AnnotatedOutput.h"
#include "GroundTruthScore.h"
#include "KeyframeLog.h"
#include "LiveSensors.h"
#include "LiveView.h"
#include "ObjectStateLog.h"
#include "RunSummary.h"
#include "TimingLog.h"
#include "TrajectoryFiles.h"

#include <dynslam/core/Options.h>
#include <dynslam/core/Pipeline.h>
#include <dynslam/core/TrajectoryFile.h>
#include <dynslam/io/ObservationConversion.h>
#include <dynslam/io/RawlogSource.h>
#include <dynslam/io/SensorSync.h>
#include <dynslam/system/System.h>
#include <dynslam/viz/MapScene.h>

#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/obs/CObservation.h>
#include <mrpt/obs/CObservation3DRangeScan.h>
#include <mrpt/serialization/CArchive.h>

#include <unistd.h>
#include <algorithm>
#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <optional>
#include <thread>

namespace fs = std::filesystem;

namespace dynslam::runner {
namespace {

/// [SensorSync] max_observation_mb as the rawlog reader's limit on one field.
std::size_t maxObservationBytes(const system::System& system) {
  return std::size_t(system.sensorSync().max_observation_mb * 1024 * 1024);
}

/// The signal that interrupted the run (SIGINT: Ctrl-C; SIGTERM: kill, a job scheduler), 0 while
/// none has: the run stops reading, finishes every output and exits with 128 + that signal.
std::atomic<int> g_interrupted{0};
extern "C" void onInterrupt(int signal) { g_interrupted = signal; }

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
    // An earlier run's summary goes first: a run killed before it writes its own (kill -9, a
    // power cut) must not leave one that looks complete beside this run's outputs.
    std::error_code ignored;
    fs::remove(outPath("summary.json"), ignored);
    try {
      openOutputs();
      configure();
      playFrames();
      finishPlayback();
    } catch (const std::exception& e) {
      recordFailure(e);
    }
    if (system_) {
      try {
        system_->drain();  // after an error: what was made before it, then the sinks' ends
      } catch (const std::exception& e) {
        const std::string what = describe(e);
        std::cerr << "dynslam: error: " << what << "\n";
        rec_.failIfOk(what);
      }
    }
    rec_.poses = trajectory_ ? trajectory_->trajectory().count() : 0;
    // Counted once System's threads are done: before, its pipeline thread may still write.
    if (rec_.status == "failed" && trajectory_)
      std::cerr << "dynslam: " << trajectory_->trajectory().path() << " holds the " << rec_.poses
                << " poses estimated before the error\n";
    rec_.objects = trajectory_ ? trajectory_->objects() : 0;
    if (sensors_ && (rec_.sensor_drops = sensors_->dropped()) > 0)
      std::cerr << "dynslam: warning: the pipeline fell behind the sensors; " << rec_.sensor_drops
                << " observations dropped, the oldest first ([global] "
                << "max_queued_observations = " << sensors_->maxQueued() << " of " << args_.sensors
                << ")\n";
    rec_.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    rec_.cpu_s = processCpuSeconds() - startCpu_;
    finishOutputs();
    report();
    return exitCode();
  }

 private:
  std::string outPath(const char* name) const { return (fs::path(args_.out) / name).string(); }

  void openOutputs() {
    if (!args_.ground_truth.empty()) groundTruth_ = readGroundTruth(args_.ground_truth);
  }

  /// System from the ini, and every output of the run as one of its sinks.
  void configure() {
    system::SystemSettings settings;
    settings.map = args_.map || args_.gui;  // the live view shows the map without saving it
    settings.map_every_n_frames = args_.map_every_n_frames;
    settings.map_voxel_size = args_.map_voxel_size;
    settings.map_max_points = args_.map_max_points;
    settings.map_max_track_points = args_.map_max_track_points;
    settings.max_frames = args_.max_frames;
    if (args_.realtime)
      settings.before_frame = [this](core::Frame& f) { cameraRate_.waitFor(f.t, rec_); };
    system_.emplace(args_.config, args_.overrides, settings);
    rec_.estimator = system_->estimatesPose();
    if (!rec_.estimator)
      std::cerr << "dynslam: no pose estimator in [pipeline] stages of " << args_.config
                << ": frames are read and processed, but trajectory.tum stays empty\n";
    trajectory_ = std::make_shared<TrajectoryFiles>(args_.out);
    system_->addSink(trajectory_);
    system_->addSink(std::make_shared<TimingLog>(outPath("timing.csv"), system_->pipeline()));
    if (rec_.estimator) system_->addSink(std::make_shared<KeyframeLog>(outPath("keyframes.csv")));
    system_->addSink(std::make_shared<ObjectStateLog>(outPath("objects/states.csv")));
    if (!args_.frames_dir.empty())
      system_->addSink(std::make_shared<AnnotatedOutput>(args_.frames_dir, args_.frames_video));
    if (args_.gui) {
      LiveViewOptions liveOptions;
      liveOptions.max_rate_hz = args_.gui_max_rate_hz;
      live_ = std::make_shared<LiveViewSink>(liveOptions, *system_->map());
      system_->addSink(live_);
    }
    system_->addSink(std::make_shared<RecordSink>(*this));
    if (args_.sensors.empty()) {
      source_.emplace(args_.rawlog, maxObservationBytes(*system_));
    } else {
      sensors_ = std::make_unique<LiveSensors>(args_.sensors);
      if (!args_.record.empty()) {
        record_ = std::make_unique<mrpt::io::CFileGZOutputStream>();
        if (!record_->open(args_.record))
          throw std::runtime_error("--record: cannot write '" + args_.record + "'");
      }
    }
  }

  /// The next observation of the rawlog or the live sensors (recorded with --record), its
  /// images decoded; nullptr at the end. A read error lets System finish what came before it.
  std::shared_ptr<mrpt::obs::CObservation> nextObservation() {
    try {
      if (!sensors_) {
        auto observation = source_->next();
        // Externally stored images decoded here, on the reading thread, not on System's:
        // decoding on the pipeline's thread took about 30 % of a run.
        if (observation) observation->load();
        readFraction_ = source_->progress();
        return observation;
      }
      return nextLiveObservation();
    } catch (...) {
      system_->drain();  // the frames read before the damage, as a run that stopped there
      throw;
    }
  }

  std::shared_ptr<mrpt::obs::CObservation> nextLiveObservation() {
    using Clock = std::chrono::steady_clock;
    const auto since = Clock::now();
    std::shared_ptr<mrpt::obs::CObservation> observation;
    for (;;) {  // in short waits, so that Ctrl-C is seen
      const LiveSensors::Wait waited = sensors_->next(0.2, observation);
      if (waited == LiveSensors::Wait::Ended || g_interrupted) return nullptr;
      if (waited == LiveSensors::Wait::Observation) break;
      if (args_.sensor_timeout_s > 0 &&
          std::chrono::duration<double>(Clock::now() - since).count() > args_.sensor_timeout_s)
        throw std::runtime_error("no observation from the sensors of " + args_.sensors + " for " +
                                 core::formatNumber(args_.sensor_timeout_s) +
                                 " s (--sensor-timeout)");
    }
    if (record_) recordObservation(*observation);
    return observation;
  }

  /// --record: the observation into the rawlog; images a replayed rawlog stores as files are
  /// copied into the recording's own <stem>_Images folder under the same names.
  void recordObservation(const mrpt::obs::CObservation& observation) {
    if (const auto* scan = dynamic_cast<const mrpt::obs::CObservation3DRangeScan*>(&observation)) {
      const fs::path images = fs::path(args_.record).parent_path() /
                              (fs::path(args_.record).stem().string() + "_Images");
      const auto copy = [&](const std::string& from, const std::string& name) {
        fs::create_directories((images / name).parent_path());
        fs::copy_file(from, images / name, fs::copy_options::overwrite_existing);
      };
      if (scan->hasIntensityImage && scan->intensityImage.isExternallyStored())
        copy(scan->intensityImage.getExternalStorageFileAbsolutePath(),
             scan->intensityImage.getExternalStorageFile());
      if (scan->hasRangeImage && scan->rangeImage_isExternallyStored())
        copy(scan->rangeImage_getExternalStorageFileAbsolutePath(""),
             scan->rangeImage_getExternalStorageFile(""));
    }
    mrpt::serialization::archiveFrom(*record_) << observation;
  }

  /// The rawlog's observations into System, one by one, until the end, --max-frames or Ctrl-C.
  void playFrames() {
    progress_.emplace(stderr, !args_.quiet && isatty(STDERR_FILENO) != 0);
    std::signal(SIGINT, onInterrupt);
    std::signal(SIGTERM, onInterrupt);
    const auto enough = [&] {
      return args_.max_frames >= 0 && long(system_->framesProcessed()) >= args_.max_frames;
    };
    while (!g_interrupted && !enough()) {
      const auto observation = nextObservation();
      if (!observation) break;
      system_->onNewObservation(observation);
    }
    if (g_interrupted)
      system_->stop();
    else
      system_->flush();
  }

  /// Counts and progress, as each frame leaves the pipeline (on System's thread).
  class RecordSink : public system::FrameSink {
   public:
    explicit RecordSink(DynslamRun& run) : run_(run) {}
    void onFrame(const core::Frame& frame, const system::FrameContext&) override {
      RunRecord& rec = run_.rec_;
      ++rec.frames;
      rec.imu_samples += frame.imu.size();
      rec.gnss_fixes += frame.gnss.size();
      if (!run_.args_.quiet) run_.progress_->update(rec.frames, run_.readFraction_.load());
    }

   private:
    DynslamRun& run_;
  };

  /// --gui: the window, redrawn with each frame and once more at the end.
  class LiveViewSink : public system::FrameSink {
   public:
    LiveViewSink(const LiveViewOptions& options, const viz::MapSceneBuilder& map)
        : view(options), map_(map) {}
    void onFrame(const core::Frame& frame, const system::FrameContext&) override {
      view.update(frame, map_);
      last_ = frame;
    }
    void onEnd() override {
      if (last_) view.update(*last_, map_, true);
    }
    LiveView view;

   private:
    const viz::MapSceneBuilder& map_;
    std::optional<core::Frame> last_;
  };

  void finishPlayback() {
    if (g_interrupted) {
      rec_.status = "interrupted";
      std::cerr << "\ndynslam: interrupted (" << (g_interrupted == SIGTERM ? "SIGTERM" : "Ctrl-C")
                << "); outputs hold the first " << rec_.frames << " frames\n";
    }
    if (!args_.quiet) progress_->finish(rec_.frames);
  }

  void recordFailure(const std::exception& e) {
    rec_.status = "failed";
    rec_.error = describe(e);
    std::cerr << "\ndynslam: error: " << rec_.error << "\n";
  }

  /// The error's message; one about the input's order or content also names the input, which
  /// the synchronisation that found it does not know.
  std::string describe(const std::exception& e) const {
    if (!dynamic_cast<const io::SyncError*>(&e) && !dynamic_cast<const io::ConversionError*>(&e))
      return e.what();
    return (args_.sensors.empty() ? "--rawlog " + args_.rawlog : "--sensors " + args_.sensors) +
           ": " + e.what();
  }

  /// What is written once the frames are done, also after an error or Ctrl-C (like
  /// trajectory.tum, the map holds what was done); after the frame rate is taken, as neither
  /// is part of it (the screenshot waits for the window to redraw).
  void finishOutputs() {
    if (live_ && !args_.gui_screenshot.empty()) {
      try {
        const std::string source = live_->view.saveScreenshot(args_.gui_screenshot);
        std::cerr << "dynslam: wrote " << args_.gui_screenshot << " (" << source << " image, "
                  << live_->view.updates() << " window updates)\n";
      } catch (const std::exception& e) {
        std::cerr << "dynslam: error: " << e.what() << "\n";
        rec_.failIfOk(e.what());
      }
    }
    if (live_)
      std::cerr << "dynslam: --gui: " << live_->view.updates() << " window updates, "
                << (live_->view.updates()
                        ? 1000.0 * live_->view.updateSeconds() / live_->view.updates()
                        : 0.0)
                << " ms each on the run's thread\n";
    const viz::MapSceneBuilder* map = system_ ? system_->map() : nullptr;
    if (map && args_.map) {
      try {
        map->save(outPath("map.3Dscene"));
        rec_.map_points = map->pointCount();
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
    const std::optional<io::SyncCounts> counts =
        system_ ? std::optional<io::SyncCounts>(system_->counts()) : std::nullopt;
    writeSummary(summaryPath, args_, rec_, counts ? &*counts : nullptr,
                 system_ ? &system_->pipeline() : nullptr);
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
    const int code =
        rec_.status == "failed" ? 1 : (rec_.status == "interrupted" ? 128 + g_interrupted : 0);
    if (live_) {
      // MRPT's window is not destroyed: closing CDisplayWindow3D while its wx thread still
      // draws corrupted the heap in about 1 run of 3 under Xvfb ("malloc(): unsorted double
      // linked list corrupted", exit 134 / 139, summary.json never written). Every output is
      // closed first; the process then ends without running the GUI's destructors.
      trajectory_.reset();
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
  CameraRateClock cameraRate_;           // --realtime, on System's thread
  std::atomic<double> readFraction_{0};  // of the rawlog, for the progress line
  std::optional<core::ProgressReporter> progress_;
  std::shared_ptr<TrajectoryFiles> trajectory_;
  std::shared_ptr<LiveViewSink> live_;  // --gui
  // Declared after the sinks it holds and before the rawlog: destroyed first of the two.
  std::optional<system::System> system_;
  std::optional<io::RawlogSource> source_;
  std::unique_ptr<LiveSensors> sensors_;                   // --sensors
  std::unique_ptr<mrpt::io::CFileGZOutputStream> record_;  // --record
};

}  // namespace

int runDynslam(const RunnerArgs& args) { return DynslamRun(args).run(); }

}  // namespace dynslam::runner
