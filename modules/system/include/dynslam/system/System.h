#pragma once
// dynslam as a library: observations in, poses, moving objects and the static map out.
//
//   dynslam::system::System slam("params/sim_vio.ini", {"Estimator.max_solver_time=100"});
//   slam.subscribeToLocalization([](const LocalizationUpdate& u) { ... });
//   for (each observation) slam.onNewObservation(obs);   // only enqueues
//   slam.flush();                                        // end of stream: waits for the rest
//
// Input follows the contract of MOLA's RawDataConsumer: onNewObservation() enqueues and
// returns; the pipeline runs on a thread of its own (SensorSync turns the observations into
// frames, then the ini's stages process them). With SystemSettings::synchronous the caller's
// thread does the work inside onNewObservation() instead (deterministic playback, tests).
// Errors of the processing (a bad stream order, a stage's failure) are thrown by the next
// onNewObservation() or flush(); drain() then processes the frames made before a bad
// observation, and what was processed stays in the outputs.
#include <dynslam/system/FrameSink.h>
#include <dynslam/system/SystemOutputs.h>

#include <Eigen/Core>

#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace mrpt::config {
class CConfigFileBase;
}
namespace mrpt::obs {
class CObservation;
}
namespace dynslam::io {
struct SyncCounts;
struct SensorSyncOptions;
}  // namespace dynslam::io
namespace dynslam::viz {
class MapSceneBuilder;
}

namespace dynslam::system {

struct SystemSettings {
  /// Process inside onNewObservation() on the caller's thread (no thread of its own).
  bool synchronous = false;
  /// Observations waiting for the processing thread at most; onNewObservation() blocks while
  /// the queue is full (a rawlog is read no further ahead than this). 0: the ini's
  /// [SensorSync] queue_observations (default 64).
  std::size_t queue_capacity = 0;
  /// Frames processed at most (-1: all); later observations are ignored.
  long max_frames = -1;
  /// Build the static point map (map updates, map()); the frames it takes and its voxel size.
  bool map = true;
  int map_every_n_frames = 10;
  double map_voxel_size = 0.05;
  std::size_t map_max_points = 1000000;      ///< the static map's voxels at most
  std::size_t map_max_track_points = 20000;  ///< points of each trajectory line at most
  /// The map handed to subscribers keeps voxels seen in at least this many of the frames it
  /// took (viz::MapSceneOptions::min_frames); a navigator wants 2-3.
  int map_update_min_frames = 1;
  /// Called on the processing thread before each frame enters the pipeline (the dynslam
  /// program's --realtime holds a rawlog's frames back to their recorded rate here).
  std::function<void(core::Frame&)> before_frame;
};

class System {
 public:
  /// Configures every stage from the ini (with "section.key=value" overrides) as the dynslam
  /// program does; throws core::ConfigError naming the key for a bad configuration.
  System(const std::string& ini_file, const std::vector<std::string>& overrides = {},
         SystemSettings settings = {});
  System(const mrpt::config::CConfigFileBase& ini, const std::vector<std::string>& overrides = {},
         SystemSettings settings = {});
  /// Stops the processing thread (stop()).
  ~System();
  System(const System&) = delete;
  System& operator=(const System&) = delete;

  /// Before the first observation: sinks get every processed frame, in order.
  void addSink(std::shared_ptr<FrameSink> sink);
  /// Called on the processing thread after each posed frame / each map change.
  void subscribeToLocalization(std::function<void(const LocalizationUpdate&)> callback);
  void subscribeToMapUpdates(std::function<void(const MapUpdate&)> callback);

  /// Enqueues one observation (CObservation3DRangeScan, CObservationIMU, CObservationGPS by
  /// the labels of [SensorSync]; other types are counted and ignored).
  void onNewObservation(const std::shared_ptr<mrpt::obs::CObservation>& observation);
  /// End of the stream: processes what is queued and the frames still waiting for later
  /// samples, finishes the stages and the sinks. No observation may follow.
  void flush();
  /// The input broke off (a truncated or corrupt recording) or the processing failed: processes
  /// what is queued (up to the bad observation), but not the frames still waiting for later
  /// samples; finishes the stages and the sinks.
  void drain();
  /// Stops after the frame being processed; what is queued is dropped, sinks are finished.
  void stop();

  // Thread-safe, at any time.
  std::optional<LocalizationUpdate> latestPose() const;
  /// The camera's world velocity, m/s, from its last two poses.
  std::optional<Eigen::Vector3d> latestVelocity() const;
  std::vector<MovingObject> movingObjects() const;
  TrackingStatus status() const;
  std::size_t framesProcessed() const;
  /// The synchronizer's counts (observations by type, frames, those it did not use).
  io::SyncCounts counts() const;
  /// The ini's [SensorSync] settings, the input bounds among them (a rawlog reader's
  /// max_observation_mb).
  const io::SensorSyncOptions& sensorSync() const;
  std::optional<Eigen::Vector3d> gnssOrigin() const;

  /// Whether [pipeline] holds a stage that estimates the camera pose.
  bool estimatesPose() const;
  /// The pipeline (stage statistics, the estimator); read it after flush() or stop().
  const core::Pipeline& pipeline() const;
  /// The static map (nullptr with SystemSettings::map off); read it after flush() or stop().
  const viz::MapSceneBuilder* map() const;

 private:
  void end(bool flushFrames);
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace dynslam::system
