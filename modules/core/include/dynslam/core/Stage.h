#pragma once
// A pipeline stage (observer): it receives every Frame in order, reads what earlier stages
// wrote and adds its own output. Stages are created by class name (StageRegistry) and
// configure themselves from their own ini section.
#include <dynslam/core/Config.h>
#include <dynslam/core/Frame.h>

#include <mrpt/system/COutputLogger.h>

#include <string>
#include <utility>
#include <vector>

namespace dynslam::core {

class Stage : public mrpt::system::COutputLogger {
 public:
  ~Stage() override = default;

  /// Reads this stage's options from `section` of `cfg` (typically loadOptionsStrict on its
  /// CLoadableOptions struct). Called once, before the first frame.
  virtual void configure(const IniConfig& cfg, const std::string& section) = 0;

  /// Processes one frame; may throw, which ends the run (the runner keeps what it has).
  virtual void process(Frame& frame) = 0;

  /// Called once after the last frame (flush files, join threads).
  virtual void finish() {}

  /// True for stages that set Frame::T_world_camera (estimators and odometries).
  virtual bool estimatesPose() const { return false; }

  /// Figures the stage measured over the run (name, value), valid after finish(); the runner
  /// writes them into summary.json beside the stage's timings.
  virtual std::vector<std::pair<std::string, double>> statistics() const { return {}; }
};

}  // namespace dynslam::core
