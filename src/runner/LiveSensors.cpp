#include "LiveSensors.h"

#include "RawlogReplaySensor.h"

#include <dynslam/core/Config.h>
#include <dynslam/core/Options.h>

#include <mrpt/config/CConfigFile.h>
#include <mrpt/hwdrivers/CGenericSensor.h>
#include <mrpt/obs/CObservation.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <stdexcept>

namespace dynslam::runner {

namespace {

/// The [global] section of a sensors ini.
struct GlobalOptions : core::Options {
  double merge_hold_s = LiveSensors::kMergeHoldS;
  int max_queued_observations = LiveSensors::kMaxQueued;

  void describe(core::OptionVisitor& v) override {
    v.key("merge_hold_s", merge_hold_s, core::Range::closed(0, 10),
          "s; each observation waits this long for another sensor's earlier one");
    v.key("max_queued_observations", max_queued_observations, core::Range::closed(1, 1000000),
          "observations waiting at most; past it the oldest are dropped");
  }
};

}  // namespace

LiveSensors::LiveSensors(const std::string& ini_file) {
  if (!std::filesystem::exists(ini_file))
    throw std::runtime_error("--sensors: cannot read '" + ini_file + "'");
  CRawlogReplaySensor::doRegister();
  const mrpt::config::CConfigFile ini(ini_file);
  std::vector<std::string> sections;
  ini.getAllSections(sections);
  GlobalOptions global;  // unknown keys and values out of range: errors naming key and file
  core::loadOptionsStrict(global, core::IniConfig::fromMrpt(ini, ini_file), "global");
  merge_hold_s_ = global.merge_hold_s;
  max_queued_ = static_cast<std::size_t>(global.max_queued_observations);
  std::vector<std::string> names;
  for (const auto& section : sections) {
    if (section.empty() || section == "global") continue;
    const std::string driver = ini.read_string(section, "driver", "");
    const std::string where = "[" + section + "] of " + ini_file;
    if (driver.empty()) throw std::runtime_error(where + ": no driver = ...");
    std::shared_ptr<mrpt::hwdrivers::CGenericSensor> sensor(
        mrpt::hwdrivers::CGenericSensor::createSensor(driver));
    if (!sensor) throw std::runtime_error(where + ": unknown driver '" + driver + "'");
    try {
      sensor->loadConfig(ini, section);
      sensor->initialize();
    } catch (const std::exception& e) {  // no thread runs yet; the sensors made close with us
      throw std::runtime_error(where + ": sensor '" + driver + "' failed to start: " + e.what());
    }
    sensors_.push_back(sensor);
    names.push_back(section);
  }
  if (sensors_.empty()) throw std::runtime_error("--sensors " + ini_file + ": no sensor section");
  running_ = sensors_.size();
  for (size_t i = 0; i < sensors_.size(); ++i)
    threads_.emplace_back([this, i, name = names[i]] { run(*sensors_[i], name); });
}

LiveSensors::~LiveSensors() { stop(); }

void LiveSensors::run(mrpt::hwdrivers::CGenericSensor& sensor, const std::string& section) {
  const double rate = sensor.getProcessRate() > 0 ? sensor.getProcessRate() : 100.0;
  const auto period = std::chrono::duration<double>(1.0 / rate);
  const auto* replay = dynamic_cast<const CRawlogReplaySensor*>(&sensor);
  try {
    for (;;) {
      const auto start = std::chrono::steady_clock::now();
      sensor.doProcess();
      mrpt::hwdrivers::CGenericSensor::TListObservations got;
      sensor.getObservations(got);
      {
        std::lock_guard<std::mutex> lock(mutex_);
        const auto now = std::chrono::steady_clock::now();
        for (const auto& [stamp, object] : got)
          if (auto obs = std::dynamic_pointer_cast<mrpt::obs::CObservation>(object))
            queue_.emplace(mrpt::Clock::toDouble(obs->timestamp), Arrived{now, obs});
        for (; queue_.size() > max_queued_; ++dropped_) queue_.erase(queue_.begin());
        if (!got.empty()) arrived_.notify_all();
        if (stopping_ || (replay && replay->finished())) break;
      }
      std::this_thread::sleep_until(start + period);
    }
  } catch (const std::exception& e) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (error_.empty()) error_ = "sensor [" + section + "]: " + e.what();
  }
  std::lock_guard<std::mutex> lock(mutex_);
  --running_;
  arrived_.notify_all();
}

LiveSensors::Wait LiveSensors::next(double timeout_s,
                                    std::shared_ptr<mrpt::obs::CObservation>& out) {
  using Clock = std::chrono::steady_clock;
  const auto hold =
      std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(merge_hold_s_));
  const auto deadline = Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                           std::chrono::duration<double>(timeout_s));
  std::unique_lock<std::mutex> lock(mutex_);
  for (;;) {
    if (!error_.empty()) throw std::runtime_error(error_);
    // The earliest stamp goes once it has waited out the hold (or no sensor can send more).
    if (!queue_.empty() && (running_ == 0 || queue_.begin()->second.when + hold <= Clock::now())) {
      out = std::move(queue_.begin()->second.observation);
      queue_.erase(queue_.begin());
      return Wait::Observation;
    }
    if (queue_.empty() && running_ == 0) return Wait::Ended;
    if (Clock::now() >= deadline) return Wait::TimedOut;
    const auto until =
        queue_.empty() ? deadline : std::min(deadline, queue_.begin()->second.when + hold);
    arrived_.wait_until(lock, until);
  }
}

void LiveSensors::stop() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
  }
  for (auto& t : threads_)
    if (t.joinable()) t.join();
}

std::size_t LiveSensors::dropped() {
  std::lock_guard<std::mutex> lock(mutex_);
  return dropped_;
}

}  // namespace dynslam::runner
