#pragma once
// The configured chain of stages. The ini names them in order:
//
//   [pipeline]
//   stages = HogPeopleDetector, DepthThresholdSegmenter, KalmanBoxTracker
//
// Each stage reads the section named after its class. A stage name may carry its own section
// as "Class:Section" so two instances of one class can be configured apart.
#include <dynslam/core/Config.h>
#include <dynslam/core/Frame.h>
#include <dynslam/core/SampleReservoir.h>

#include <memory>
#include <string>
#include <vector>

namespace dynslam::core {

class Stage;
class StageRegistry;

/// One entry of [pipeline] stages: "Class" or "Class:Section".
struct StageEntry {
  std::string entry;       ///< as written
  std::string class_name;  ///< the registered stage class
  std::string section;     ///< the section it reads: the class name unless the entry names one
};

/// The entries [pipeline] stages lists, in order (commas and white space both separate). For
/// programs that build some of the stages themselves (the benches) as Pipeline would.
std::vector<StageEntry> pipelineStageEntries(const IniConfig& cfg);

/// Wall-clock time each stage spent on each frame, in milliseconds (bounded: SampleReservoir).
struct StageTimes {
  std::string name;
  SampleReservoir ms;
};

class Pipeline {
 public:
  static constexpr const char* kSection = "pipeline";

  /// Creates and configures the stages that [pipeline] stages lists. Throws ConfigError for an
  /// unknown class, an unknown key in [pipeline] or in a stage's section.
  Pipeline(const IniConfig& cfg, const StageRegistry& registry);
  ~Pipeline();
  Pipeline(Pipeline&&) noexcept;
  Pipeline& operator=(Pipeline&&) noexcept;

  void process(Frame& frame);
  void finish();

  /// Sections the stages read, plus [pipeline] itself (for rejectUnknownSections).
  std::vector<std::string> sectionsUsed() const;
  bool estimatesPose() const;
  bool empty() const { return stages_.empty(); }
  const std::vector<StageTimes>& times() const { return times_; }
  /// Stage::statistics() of each stage, in the order of times().
  std::vector<std::vector<std::pair<std::string, double>>> statistics() const;

 private:
  std::vector<std::unique_ptr<Stage>> stages_;
  std::vector<std::string> sections_;
  std::vector<StageTimes> times_;
};

}  // namespace dynslam::core
