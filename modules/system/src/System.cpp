#include <dynslam/system/System.h>

#include "BoundedQueue.h"
#include "SystemState.h"

#include <dynslam/core/Config.h>
#include <dynslam/core/Pipeline.h>
#include <dynslam/io/SensorSync.h>
#include <dynslam/system/RunConfiguration.h>
#include <dynslam/viz/MapScene.h>

#include <mrpt/maps/CColouredPointsMap.h>
#include <mrpt/obs/CObservation.h>

#include <atomic>
#include <chrono>
#include <exception>
#include <mutex>
#include <stdexcept>
#include <thread>

namespace dynslam::system {

const char* toString(TrackingStatus status) {
  switch (status) {
    case TrackingStatus::Initializing:
      return "initializing";
    case TrackingStatus::Tracking:
      return "tracking";
    case TrackingStatus::LostRestarting:
      return "lost_restarting";
  }
  return "unknown";
}

using ObservationPtr = std::shared_ptr<mrpt::obs::CObservation>;

/// Threaded: onNewObservation -> `observations` -> the synchronizing thread (SensorSync: frames
/// from observations, their images converted) -> `frames` -> the pipeline thread (the stages,
/// the map, the sinks, the subscribers). Two threads, so that making a frame overlaps processing
/// the one before, as the rawlog reader's own thread did. Synchronous: all on the caller's.
struct System::Impl {
  Impl(const core::IniConfig& ini, SystemSettings s)
      : settings(s),
        configured(configureRun(ini)),
        sync(configured.sync),
        observations(settings.queue_capacity ? settings.queue_capacity
                                             : std::size_t(configured.sync.queue_observations)),
        frames(std::size_t(configured.sync.frames_ahead)) {
    if (settings.map) {
      viz::MapSceneOptions options;
      options.every_n_frames = settings.map_every_n_frames;
      options.voxel_size = settings.map_voxel_size;
      options.max_points = settings.map_max_points;
      options.max_track_points = settings.map_max_track_points;
      options.min_frames = settings.map_update_min_frames;
      map.emplace(options);
    }
  }

  /// The frames `observation` completes (none, one, or more), or with a null observation the
  /// frames still waiting for later samples (the end of the stream).
  std::vector<core::Frame> synchronize(const ObservationPtr& observation) {
    std::vector<core::Frame> ready;
    std::lock_guard<std::mutex> lock(syncMutex);
    if (observation)
      sync.push(observation, ready);
    else
      sync.flush(ready);
    return ready;
  }

  void process(core::Frame& frame) {
    if (settings.max_frames >= 0 && state.frames() >= std::size_t(settings.max_frames)) return;
    if (settings.before_frame) settings.before_frame(frame);
    const auto start = std::chrono::steady_clock::now();
    configured.pipeline.process(frame);
    const FrameContext context{configured.pipeline, std::chrono::duration<double, std::milli>(
                                                        std::chrono::steady_clock::now() - start)
                                                        .count()};
    const std::size_t mapUpdates = map ? map->staticUpdates() : 0;
    if (map) map->addFrame(frame);
    state.update(frame);
    for (const auto& sink : sinks) sink->onFrame(frame, context);
    if (frame.T_world_camera)
      for (const auto& callback : localizationCallbacks) callback(*state.latestPose());
    if (map && map->staticUpdates() != mapUpdates && !mapCallbacks.empty()) {
      MapUpdate update;
      update.timestamp = mrpt::Clock::fromDouble(frame.t);
      update.map = map->staticPoints();
      for (const auto& callback : mapCallbacks) callback(update);
    }
  }

  /// An error on either thread ends both queues; the next push or the end rethrows it.
  void fail(std::exception_ptr error) {
    observations.fail(error);
    frames.fail(error);
  }

  void runSynchronizer() {
    try {
      while (auto observation = observations.pop())
        for (auto& frame : synchronize(*observation)) frames.push(std::move(frame));
      if (flushAtEnd && !observations.failed() && !observations.stopped())
        for (auto& frame : synchronize(nullptr)) frames.push(std::move(frame));
      frames.close();
    } catch (...) {
      // The frames made before the bad observation are still processed, as a run that stopped
      // there would have processed them; the error reaches the caller meanwhile.
      observations.fail(std::current_exception());
      frames.close();
    }
  }

  void runPipeline() {
    try {
      while (auto frame = frames.pop()) process(*frame);
    } catch (...) {
      fail(std::current_exception());
    }
  }

  void startThreads() {
    if (settings.synchronous || synchronizer.joinable()) return;
    synchronizer = std::thread([this] { runSynchronizer(); });
    pipelineThread = std::thread([this] { runPipeline(); });
  }

  void join() {
    if (synchronizer.joinable()) synchronizer.join();
    if (pipelineThread.joinable()) pipelineThread.join();
  }

  /// Synchronous mode's end of stream: the frames still waiting for later samples.
  void flushSynchronously() {
    for (auto& frame : synchronize(nullptr)) process(frame);
  }

  /// Every stage's and sink's end, also after an error, so the sinks' files are complete.
  void finish(std::exception_ptr error) {
    if (finished) return;
    finished = true;
    try {
      configured.pipeline.finish();
    } catch (...) {
      if (!error) error = std::current_exception();
    }
    for (const auto& sink : sinks) try {
        sink->onEnd();
      } catch (...) {
        if (!error) error = std::current_exception();
      }
    if (error) std::rethrow_exception(error);
  }

  SystemSettings settings;
  RunConfiguration configured;
  mutable std::mutex syncMutex;  // the synchronizer's counts are read from other threads
  io::SensorSync sync;
  std::optional<viz::MapSceneBuilder> map;
  std::vector<std::shared_ptr<FrameSink>> sinks;
  std::vector<std::function<void(const LocalizationUpdate&)>> localizationCallbacks;
  std::vector<std::function<void(const MapUpdate&)>> mapCallbacks;
  SystemState state;
  BoundedQueue<ObservationPtr> observations;
  BoundedQueue<core::Frame> frames;
  std::atomic<bool> flushAtEnd{true};
  std::thread synchronizer, pipelineThread;
  bool started = false, finished = false;
};

System::System(const std::string& ini_file, const std::vector<std::string>& overrides,
               SystemSettings settings)
    : impl_(std::make_unique<Impl>(core::IniConfig::fromFile(ini_file, overrides), settings)) {}

System::System(const mrpt::config::CConfigFileBase& ini, const std::vector<std::string>& overrides,
               SystemSettings settings) {
  core::IniConfig cfg = core::IniConfig::fromMrpt(ini);
  for (const auto& o : overrides) cfg.applyOverride(o);
  impl_ = std::make_unique<Impl>(cfg, settings);
}

System::~System() {
  try {
    stop();
  } catch (...) {  // a destructor reports nothing: stop() or flush() say what went wrong
  }
}

void System::addSink(std::shared_ptr<FrameSink> sink) {
  if (impl_->started) throw std::logic_error("System::addSink after the first observation");
  impl_->sinks.push_back(std::move(sink));
}

void System::subscribeToLocalization(std::function<void(const LocalizationUpdate&)> callback) {
  if (impl_->started)
    throw std::logic_error("System::subscribeToLocalization after the first observation");
  impl_->localizationCallbacks.push_back(std::move(callback));
}

void System::subscribeToMapUpdates(std::function<void(const MapUpdate&)> callback) {
  if (impl_->started)
    throw std::logic_error("System::subscribeToMapUpdates after the first observation");
  impl_->mapCallbacks.push_back(std::move(callback));
}

void System::onNewObservation(const std::shared_ptr<mrpt::obs::CObservation>& observation) {
  auto& impl = *impl_;
  if (!observation) throw std::invalid_argument("System::onNewObservation: a null observation");
  if (impl.finished) throw std::logic_error("System::onNewObservation after flush() or stop()");
  impl.started = true;
  if (!impl.settings.synchronous) {
    impl.startThreads();
    impl.observations.push(observation);  // throws the processing's error
    return;
  }
  if (impl.observations.failed())
    throw std::logic_error("System::onNewObservation after the processing failed");
  try {
    for (auto& frame : impl.synchronize(observation)) impl.process(frame);
  } catch (...) {
    impl.fail(std::current_exception());
    impl.observations.unreportedError();  // thrown here, not again by flush()
    throw;
  }
}

void System::flush() { end(true); }
void System::drain() { end(false); }

void System::end(bool flushFrames) {
  auto& impl = *impl_;
  if (impl.finished) return;
  impl.flushAtEnd = flushFrames;
  impl.observations.close();
  impl.join();
  std::exception_ptr error = impl.observations.unreportedError();
  if (impl.settings.synchronous && flushFrames && !impl.observations.failed()) try {
      impl.flushSynchronously();
    } catch (...) {
      error = std::current_exception();
    }
  impl.finish(error);
}

void System::stop() {
  auto& impl = *impl_;
  if (impl.finished) return;
  impl.observations.stop();
  impl.frames.stop();
  impl.join();
  impl.finish(impl.observations.unreportedError());
}

std::optional<LocalizationUpdate> System::latestPose() const { return impl_->state.latestPose(); }
std::optional<Eigen::Vector3d> System::latestVelocity() const {
  return impl_->state.latestVelocity();
}
std::vector<MovingObject> System::movingObjects() const { return impl_->state.movingObjects(); }
TrackingStatus System::status() const { return impl_->state.status(); }
std::size_t System::framesProcessed() const { return impl_->state.frames(); }

const io::SensorSyncOptions& System::sensorSync() const { return impl_->configured.sync; }

io::SyncCounts System::counts() const {
  std::lock_guard<std::mutex> lock(impl_->syncMutex);
  return impl_->sync.counts();
}

std::optional<Eigen::Vector3d> System::gnssOrigin() const {
  std::lock_guard<std::mutex> lock(impl_->syncMutex);
  return impl_->sync.gnssOrigin();
}

bool System::estimatesPose() const { return impl_->configured.pipeline.estimatesPose(); }
const core::Pipeline& System::pipeline() const { return impl_->configured.pipeline; }
const viz::MapSceneBuilder* System::map() const { return impl_->map ? &*impl_->map : nullptr; }

}  // namespace dynslam::system
