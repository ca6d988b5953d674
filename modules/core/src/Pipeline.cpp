#include "dynslam/core/Pipeline.h"

#include "dynslam/core/StageRegistry.h"

#include <mrpt/config/CConfigFileBase.h>

#include <chrono>
#include <sstream>

namespace dynslam::core {
namespace {

/// "A, B:sec  C" -> {"A", "B:sec", "C"}: commas and white space both separate.
std::vector<std::string> splitList(std::string text) {
  for (char& c : text)
    if (c == ',') c = ' ';
  std::istringstream in(text);
  std::vector<std::string> items;
  for (std::string item; in >> item;) items.push_back(item);
  return items;
}

}  // namespace

std::vector<StageEntry> pipelineStageEntries(const IniConfig& cfg) {
  std::vector<StageEntry> entries;
  for (const auto& entry : splitList(cfg.ini().read_string(Pipeline::kSection, "stages", ""))) {
    const auto colon = entry.find(':');
    const std::string className = entry.substr(0, colon);
    entries.push_back(
        {entry, className, colon == std::string::npos ? className : entry.substr(colon + 1)});
  }
  return entries;
}

Pipeline::Pipeline(const IniConfig& cfg, const StageRegistry& registry) {
  for (const auto& key : cfg.keys(kSection))
    if (key != "stages")
      throw ConfigError("unknown key '" + key + "' in section [pipeline] of " + cfg.source() +
                        "; known keys: stages");
  for (const auto& e : pipelineStageEntries(cfg)) {
    std::unique_ptr<Stage> stage;
    try {
      stage = registry.create(e.class_name);
    } catch (const ConfigError& error) {  // a typo in the ini: say which file and key
      throw ConfigError(std::string(error.what()) + " (key 'stages' in section [pipeline] of " +
                        cfg.source() + ")");
    }
    stage->setLoggerName(e.section);
    stage->configure(cfg, e.section);
    stages_.push_back(std::move(stage));
    sections_.push_back(e.section);
    times_.push_back({e.section, SampleReservoir()});
  }
}

Pipeline::~Pipeline() = default;
Pipeline::Pipeline(Pipeline&&) noexcept = default;
Pipeline& Pipeline::operator=(Pipeline&&) noexcept = default;

void Pipeline::process(Frame& frame) {
  using Clock = std::chrono::steady_clock;
  for (size_t i = 0; i < stages_.size(); ++i) {
    const auto start = Clock::now();
    stages_[i]->process(frame);
    times_[i].ms.add(std::chrono::duration<double, std::milli>(Clock::now() - start).count());
  }
}

void Pipeline::finish() {
  for (auto& s : stages_) s->finish();
}

std::vector<std::string> Pipeline::sectionsUsed() const {
  std::vector<std::string> s = sections_;
  s.push_back(kSection);
  return s;
}

std::vector<std::vector<std::pair<std::string, double>>> Pipeline::statistics() const {
  std::vector<std::vector<std::pair<std::string, double>>> all;
  for (const auto& s : stages_) all.push_back(s->statistics());
  return all;
}

bool Pipeline::estimatesPose() const {
  for (const auto& s : stages_)
    if (s->estimatesPose()) return true;
  return false;
}

}  // namespace dynslam::core
