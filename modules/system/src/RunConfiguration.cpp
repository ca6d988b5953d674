#include <dynslam/system/RunConfiguration.h>

#include <dynslam/system/BuiltinStages.h>

#include <dynslam/core/Options.h>
#include <dynslam/core/StageRegistry.h>

#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/config/CLoadableOptions.h>

#include <algorithm>
#include <cstdlib>

namespace dynslam::system {
namespace {

/// Each options struct's keys as they stand once loaded, section by section in load order.
class LoadedOptions : public core::OptionsObserver {
 public:
  std::vector<std::pair<std::string, std::vector<core::KeyDoc>>> sections;

  void loaded(const mrpt::config::CLoadableOptions& options, const std::string& section) override {
    auto it = std::find_if(sections.begin(), sections.end(),
                           [&](const auto& s) { return s.first == section; });
    if (it == sections.end()) it = sections.insert(sections.end(), {section, {}});
    for (auto& key : keysOf(options)) {
      auto& keys = it->second;
      auto same = std::find_if(keys.begin(), keys.end(),
                               [&](const core::KeyDoc& k) { return k.key == key.key; });
      if (same == keys.end())
        keys.push_back(std::move(key));
      else
        *same = std::move(key);
    }
  }

 private:
  static std::vector<core::KeyDoc> keysOf(const mrpt::config::CLoadableOptions& options) {
    if (const auto* described = dynamic_cast<const core::Options*>(&options))
      return core::describeKeys(*described);
    mrpt::config::CConfigFileMemory written;  // a struct without describe(): values only
    options.saveToConfigFile(written, "s");
    std::string text;  // through text: MRPT finds the names it wrote padded only after that
    written.getContent(text);
    const mrpt::config::CConfigFileMemory ini(text);
    std::vector<std::string> names;
    ini.getAllKeys("s", names);
    std::vector<core::KeyDoc> keys;
    for (auto& name : names) {
      name.erase(name.find_last_not_of(' ') + 1);
      std::string value = ini.read_string("s", name, "");
      char* end = nullptr;  // "0.020000" as MRPT writes doubles -> "0.02"
      const double number = std::strtod(value.c_str(), &end);
      if (!value.empty() && *end == '\0' && value.find('.') != std::string::npos)
        value = core::formatNumber(number);
      keys.push_back({name, value, "", ""});
    }
    return keys;
  }
};

}  // namespace

RunConfiguration configureRun(const core::IniConfig& cfg) {
  core::StageRegistry registry;
  registerBuiltinStages(registry);
  RunConfiguration run{core::Pipeline(cfg, registry), {}};
  core::loadOptionsStrict(run.sync, cfg, io::SensorSync::kSection);
  auto known = run.pipeline.sectionsUsed();
  known.push_back(io::SensorSync::kSection);
  core::rejectUnknownSections(cfg, known);
  return run;
}

void printEffectiveConfig(const std::string& config, const std::vector<std::string>& overrides,
                          std::ostream& out) {
  const auto cfg = core::IniConfig::fromFile(config, overrides);
  LoadedOptions seen;
  core::OptionsObserver* previous = core::setOptionsObserver(&seen);
  try {
    configureRun(cfg);
  } catch (...) {
    core::setOptionsObserver(previous);
    throw;
  }
  core::setOptionsObserver(previous);

  out << "# The configuration of " << config;
  for (const auto& o : overrides) out << " --set " << o;
  out << ": every key a run reads, at the value it would use.\n\n[" << core::Pipeline::kSection
      << "]\nstages = " << cfg.ini().read_string(core::Pipeline::kSection, "stages", "") << "\n";
  for (const auto& [section, keys] : seen.sections) {
    out << "\n[" << section << "]\n";
    for (const auto& k : keys) {
      const std::string line = k.key + " = " + k.default_value;
      // After an empty value MRPT's reader takes the comment for the value: it goes above.
      if (k.default_value.empty() && !k.meaning.empty()) out << "// " << k.meaning << "\n";
      out << line;
      if (!k.default_value.empty() && !k.meaning.empty())
        out << std::string(line.size() < 40 ? 40 - line.size() : 1, ' ') << "// " << k.meaning;
      out << "\n";
    }
  }
}

}  // namespace dynslam::system
