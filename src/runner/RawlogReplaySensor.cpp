#include "RawlogReplaySensor.h"

#include <dynslam/io/RawlogSource.h>

#include <mrpt/obs/CObservation.h>

#include <stdexcept>

IMPLEMENTS_GENERIC_SENSOR(CRawlogReplaySensor, dynslam::runner)

namespace dynslam::runner {

CRawlogReplaySensor::CRawlogReplaySensor() = default;
CRawlogReplaySensor::~CRawlogReplaySensor() = default;

void CRawlogReplaySensor::loadConfig_sensorSpecific(const mrpt::config::CConfigFileBase& cfg,
                                                    const std::string& section) {
  rawlog_ = cfg.read_string(section, "rawlog", "");
  if (rawlog_.empty())
    throw std::invalid_argument("[" + section + "] CRawlogReplaySensor needs rawlog = FILE");
}

void CRawlogReplaySensor::initialize() {
  source_ = std::make_unique<io::RawlogSource>(rawlog_);
  m_state = ssWorking;
}

void CRawlogReplaySensor::doProcess() {
  if (finished_ || !source_) return;
  const auto now = std::chrono::steady_clock::now();
  for (;;) {
    if (!next_) next_ = source_->next();
    if (!next_) {
      finished_ = true;
      return;
    }
    const double stamp = mrpt::Clock::toDouble(next_->timestamp);
    if (!first_stamp_) {
      first_stamp_ = stamp;
      start_ = now;
    }
    if (std::chrono::duration<double>(now - start_).count() < stamp - *first_stamp_) return;
    next_->load();  // externally stored images, here rather than on System's threads
    appendObservation(next_);
    next_.reset();
  }
}

}  // namespace dynslam::runner
