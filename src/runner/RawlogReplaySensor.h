#pragma once
// A sensor driver of our own for `dynslam --sensors`: replays a rawlog's observations at their
// recorded rate, stamped as recorded, as a live camera and IMU would deliver them. It stands in
// for hardware in tests and demos (`driver = CRawlogReplaySensor`, `rawlog = FILE`).
#include <mrpt/hwdrivers/CGenericSensor.h>

#include <chrono>
#include <memory>
#include <optional>
#include <string>

namespace dynslam::io {
class RawlogSource;
}

namespace dynslam::runner {

class CRawlogReplaySensor : public mrpt::hwdrivers::CGenericSensor {
  DEFINE_GENERIC_SENSOR(CRawlogReplaySensor)

 public:
  CRawlogReplaySensor();
  ~CRawlogReplaySensor() override;

  /// Opens the rawlog (an error names it).
  void initialize() override;
  /// Hands out every observation whose recorded time, relative to the first, has come.
  void doProcess() override;
  /// Every observation was handed out.
  bool finished() const { return finished_; }

 protected:
  void loadConfig_sensorSpecific(const mrpt::config::CConfigFileBase& cfg,
                                 const std::string& section) override;

 private:
  std::string rawlog_;
  std::unique_ptr<io::RawlogSource> source_;
  std::shared_ptr<mrpt::obs::CObservation> next_;
  std::optional<double> first_stamp_;
  std::chrono::steady_clock::time_point start_;
  bool finished_ = false;
};

}  // namespace dynslam::runner
