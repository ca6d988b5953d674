#pragma once
// Turns the observation stream of a rawlog into Frames: one per RGB-D observation, carrying the
// IMU samples and GNSS fixes with timestamps in (previous frame, this frame], and where the
// camera and the IMU sit on the body (their observations' sensorPose). A frame is handed
// out once an observation later than it arrives (or the stream ends), so samples stamped at
// the frame's own time are never lost to file order.
#include <dynslam/core/Config.h>
#include <dynslam/core/Frame.h>
#include <dynslam/core/Options.h>

#include <mrpt/obs/CObservation.h>

#include <deque>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace mrpt::obs {
class CObservation3DRangeScan;
class CObservationIMU;
class CObservationGPS;
}  // namespace mrpt::obs

namespace dynslam::io {

/// Bad stream order (a sensor's time going backwards, a sample arriving after the frame it
/// belongs to was handed out). The message names the observation and both timestamps.
struct SyncError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// [SensorSync]: every key, its range and meaning in describe() (SensorSync.cpp);
/// docs/parameters.md.
struct SensorSyncOptions : core::Options {
  std::string camera_label;
  std::string imu_label;
  std::string gnss_label;
  bool skip_frames_without_depth = false;
  // Bounds on what reading holds (used by the rawlog reader and System's queues, not here):
  // memory stays bounded whatever the file claims and however far the reader gets ahead.
  double max_observation_mb = 512;
  int queue_observations = 64;
  int frames_ahead = 4;

  void describe(core::OptionVisitor& v) override;
};

/// What the stream held, for the run summary.
struct SyncCounts {
  size_t observations = 0;
  size_t rgbd = 0, imu = 0, gnss = 0;
  size_t gnss_dropped = 0;  ///< no GGA, or GGA quality 0 (no fix)
  size_t other = 0;         ///< observation types or labels the pipeline does not use
  size_t frames = 0;
  size_t frames_without_depth = 0;
  std::map<std::string, size_t> by_type;  ///< class name -> count
};

class SensorSync {
 public:
  static constexpr const char* kSection = "SensorSync";

  explicit SensorSync(SensorSyncOptions options = {});

  /// Takes the next observation of the stream; frames that became complete go to `out`.
  void push(const mrpt::obs::CObservation::Ptr& obs, std::vector<core::Frame>& out);
  /// End of stream: hands out the frames still waiting.
  void flush(std::vector<core::Frame>& out);

  const SyncCounts& counts() const { return counts_; }
  /// Latitude, longitude (deg) and altitude (m) of the ENU origin, once a fix was seen.
  std::optional<Eigen::Vector3d> gnssOrigin() const { return origin_; }

 private:
  void emitUpTo(double t, std::vector<core::Frame>& out);
  void emit(core::Frame& frame, std::vector<core::Frame>& out);
  void checkOrder(const mrpt::obs::CObservation& obs, double t, bool strictly_increasing);
  /// A sample at `t` (IMU, GNSS) must come before the frame it belongs to was handed out.
  void checkNotLate(const char* what, double t) const;
  void takeRgbd(const mrpt::obs::CObservation3DRangeScan& scan);
  void takeImu(const mrpt::obs::CObservationIMU& imu);
  void takeGnss(const mrpt::obs::CObservationGPS& gps);

  SensorSyncOptions options_;
  SyncCounts counts_;
  std::deque<core::Frame> waiting_;
  std::deque<core::ImuSample> imu_;
  std::deque<core::GnssFix> gnss_;
  std::map<std::string, double> last_t_;  // per sensor
  std::optional<double> last_frame_t_;    // last frame handed out
  std::optional<Eigen::Vector3d> origin_;
  std::optional<Eigen::Isometry3d> T_body_imu_;  // sensorPose of the latest IMU observation
};

}  // namespace dynslam::io
