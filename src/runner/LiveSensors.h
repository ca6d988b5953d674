#pragma once
// `dynslam --sensors FILE.ini`: MRPT hwdrivers sensors configured as rawlog-grabber configures
// them (one section per sensor with `driver = COpenNI2Sensor | CKinect | CCameraSensor |
// CIMUXSens_MT4 | CGPSInterface | CRawlogReplaySensor ...`, `process_rate`, `sensorLabel`; a
// [global] section holds only `merge_hold_s` and `max_queued_observations`), each on a thread of
// its own at its process_rate, as MRPT's ICP_SLAM_App_Live runs them; their observations merged
// in time order: each is held for merge_hold_s (default kMergeHoldS) after it arrives, so that a
// sample of another sensor stamped before it but delivered a little later (another thread,
// another bus) still goes first. When the pipeline falls behind the sensors, the queue keeps
// the newest max_queued_observations (default kMaxQueued) and drops the oldest: a live run
// must stay near the present, and its memory bounded.
#include <chrono>
#include <condition_variable>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace mrpt::obs {
class CObservation;
}
namespace mrpt::hwdrivers {
class CGenericSensor;
}

namespace dynslam::runner {

class LiveSensors {
 public:
  static constexpr double kMergeHoldS = 0.1;
  static constexpr int kMaxQueued = 256;  // 1.3 s of a 30 Hz camera and a 160 Hz IMU

  /// Creates, configures and initializes every sensor of `ini_file` and starts its thread.
  /// Throws std::runtime_error naming the file and section: an unknown driver, a bad setting, a
  /// sensor that fails to initialize (the ones configured before it are closed; none ran).
  explicit LiveSensors(const std::string& ini_file);
  ~LiveSensors();
  LiveSensors(const LiveSensors&) = delete;
  LiveSensors& operator=(const LiveSensors&) = delete;

  enum class Wait { Observation, Ended, TimedOut };
  /// The next observation, waiting at most `timeout_s`; Ended once every sensor has finished
  /// (replay sensors at the end of their rawlog) and nothing is left.
  Wait next(double timeout_s, std::shared_ptr<mrpt::obs::CObservation>& out);
  void stop();
  /// Observations dropped so far because the queue held max_queued_observations.
  std::size_t dropped();
  std::size_t maxQueued() const { return max_queued_; }

 private:
  void run(mrpt::hwdrivers::CGenericSensor& sensor, const std::string& section);

  std::vector<std::shared_ptr<mrpt::hwdrivers::CGenericSensor>> sensors_;
  std::vector<std::thread> threads_;
  double merge_hold_s_ = kMergeHoldS;
  std::size_t max_queued_ = kMaxQueued;
  std::size_t dropped_ = 0;
  std::mutex mutex_;
  std::condition_variable arrived_;
  struct Arrived {
    std::chrono::steady_clock::time_point when;
    std::shared_ptr<mrpt::obs::CObservation> observation;
  };
  std::multimap<double, Arrived> queue_;  // by stamp
  std::size_t running_ = 0;
  bool stopping_ = false;
  std::string error_;  // a sensor thread's failure
};

}  // namespace dynslam::runner
