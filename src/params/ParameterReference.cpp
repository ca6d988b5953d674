#include "params/ParameterReference.h"

#include <dynslam/system/BuiltinStages.h>

#include <dynslam/core/Config.h>
#include <dynslam/core/Pipeline.h>
#include <dynslam/core/Stage.h>
#include <dynslam/core/StageRegistry.h>
#include <dynslam/io/SensorSync.h>
#include <dynslam/nav/NavigationOptions.h>
#include "nav_demo/NavDemoOptions.h"
#include <dynslam/sim/ScenarioOptions.h>

#include <mrpt/config/CConfigFileBase.h>
#include <mrpt/config/CLoadableOptions.h>

#include <cxxabi.h>
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <set>
#include <sstream>
#include <typeinfo>

namespace dynslam::params {
namespace {

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t");
  if (b == std::string::npos) return {};
  return s.substr(b, s.find_last_not_of(" \t") - b + 1);
}

/// "0.300000" -> "0.3", "1.000000e-05" -> "1e-05": MRPT writes doubles with %f / %e.
std::string tidyNumber(const std::string& v) {
  if (v.find_first_of(".eE") == std::string::npos) return v;
  char* end = nullptr;
  const double d = std::strtod(v.c_str(), &end);
  if (v.empty() || end != v.c_str() + v.size()) return v;
  return core::formatNumber(d);
}

/// A config "file" that keeps what saveToConfigFile writes, in order. MRPT hands over the key
/// padded and the value as "value   // comment" (MRPT_SAVE_CONFIG_VAR_COMMENT's layout). For
/// the options structs that are a CLoadableOptions but not a core::Options (no describe()).
class RecordingConfig : public mrpt::config::CConfigFileBase {
 public:
  std::vector<KeyDoc> keys;

  void getAllSections(std::vector<std::string>& sections) const override { sections = {"s"}; }
  void getAllKeys(const std::string&, std::vector<std::string>& out) const override {
    out.clear();
    for (const auto& k : keys) out.push_back(k.key);
  }
  void clear() override { keys.clear(); }

 protected:
  void writeString(const std::string&, const std::string& name, const std::string& str) override {
    KeyDoc doc;
    doc.key = trim(name);
    const auto comment = str.find(" // ");
    doc.default_value = tidyNumber(trim(str.substr(0, comment)));
    if (comment != std::string::npos) doc.meaning = trim(str.substr(comment + 4));
    keys.push_back(std::move(doc));
  }
  std::string readString(const std::string&, const std::string&, const std::string& defaultStr,
                         bool) const override {
    return defaultStr;
  }
};

std::vector<KeyDoc> keysOf(const mrpt::config::CLoadableOptions& options) {
  if (const auto* described = dynamic_cast<const core::Options*>(&options))
    return core::describeKeys(*described);
  RecordingConfig rec;
  options.saveToConfigFile(rec, "s");
  return rec.keys;
}

/// Records each options struct loadOptionsStrict is about to load, by section.
class Recorder : public core::OptionsObserver {
 public:
  std::vector<std::pair<std::string, std::vector<KeyDoc>>> sections;
  void aboutToLoad(const mrpt::config::CLoadableOptions& options,
                   const std::string& section) override {
    for (const auto& [name, keys] : sections)
      if (name == section) return;  // a stage reading its section twice
    sections.emplace_back(section, keysOf(options));
  }
};

/// Installs a Recorder for the scope; restores the previous observer after.
struct ScopedRecorder {
  Recorder recorder;
  core::OptionsObserver* previous = core::setOptionsObserver(&recorder);
  ~ScopedRecorder() { core::setOptionsObserver(previous); }
};

std::string demangled(const std::type_info& type) {
  int status = 0;
  std::unique_ptr<char, void (*)(void*)> name(
      abi::__cxa_demangle(type.name(), nullptr, nullptr, &status), std::free);
  return status == 0 ? name.get() : type.name();
}

std::string markdownCell(const std::string& s) {
  std::string out;
  for (char c : s) out += c == '|' ? std::string("\\|") : std::string(1, c);
  return out;
}

std::string anchor(const SectionDoc& s) {
  std::string a = s.program + "-" + s.section;
  for (char& c : a) c = (c >= 'A' && c <= 'Z') ? static_cast<char>(c - 'A' + 'a') : c;
  return a;
}

/// What one stage's configure() loaded, by section, when configured from `ini`.
struct StageRecord {
  std::string type;     ///< the C++ class
  std::vector<std::pair<std::string, std::vector<KeyDoc>>> sections;
};

StageRecord recordStage(const core::StageRegistry& registry, const std::string& className,
                        const std::string& ini) {
  auto stage = registry.create(className);
  StageRecord record;
  record.type = demangled(typeid(*stage));
  ScopedRecorder scoped;
  try {
    stage->configure(core::IniConfig::fromText(ini, "<defaults>"), className);
  } catch (const std::exception&) {
    // A stage may refuse its defaults (a model file absent here); the options were recorded
    // when it loaded them, before it checked anything.
  }
  record.sections = std::move(scoped.recorder.sections);
  return record;
}

/// Values of a selector key: its comment lists them as "a | b | c (its keys follow)", the
/// convention for a key whose value decides which other keys the section holds (e.g. [Detection]
/// detector). Empty for any other key.
std::vector<std::string> selectorValues(const KeyDoc& key) {
  const auto marker = key.meaning.find("(its keys follow)");
  if (marker == std::string::npos) return {};
  std::vector<std::string> values;
  std::istringstream in(key.meaning.substr(0, marker));
  for (std::string v; std::getline(in, v, '|');)
    if (!trim(v).empty()) values.push_back(trim(v));
  return values;
}

bool sameKey(const KeyDoc& a, const KeyDoc& b) {
  return a.key == b.key && a.default_value == b.default_value && a.accepts == b.accepts &&
         a.meaning == b.meaning;
}

/// saveToConfigFile writes only the chosen variant's keys; the stage is configured once per
/// other value of the selector, and each variant's own keys are added, their meaning prefixed
/// with "(selector = value)". Keys every variant shares stay as they are.
void addVariantKeys(const core::StageRegistry& registry, const std::string& className,
                    SectionDoc& doc) {
  for (const auto& selector : doc.keys) {
    const auto values = selectorValues(selector);
    if (values.empty()) continue;
    std::vector<std::pair<std::string, std::vector<KeyDoc>>> variants;
    for (const auto& value : values) {
      std::vector<KeyDoc> keys;
      if (value == selector.default_value) {
        keys = doc.keys;
      } else {
        const auto record = recordStage(
            registry, className, "[" + doc.section + "]\n" + selector.key + " = " + value + "\n");
        for (const auto& [section, k] : record.sections)
          if (section == doc.section) keys = k;
      }
      variants.emplace_back(value, std::move(keys));
    }
    // Shared: the selector itself (at its default) and what every variant writes alike.
    auto sharedByAll = [&](const KeyDoc& k) {
      if (k.key == selector.key) return true;
      return std::all_of(variants.begin(), variants.end(), [&](const auto& variant) {
        return std::any_of(variant.second.begin(), variant.second.end(),
                           [&](const KeyDoc& o) { return sameKey(k, o); });
      });
    };
    std::vector<KeyDoc> merged;
    for (const auto& k : doc.keys)
      if (sharedByAll(k)) merged.push_back(k);
    for (const auto& [value, keys] : variants)
      for (KeyDoc k : keys) {
        if (k.key == selector.key || sharedByAll(k)) continue;
        k.meaning = "(" + selector.key + " = " + value + ") " + k.meaning;
        merged.push_back(std::move(k));
      }
    doc.keys = std::move(merged);
    return;  // one selector per section
  }
}

}  // namespace

std::vector<SectionDoc> collectParameters() {
  std::vector<SectionDoc> out;
  core::StageRegistry registry;
  system::registerBuiltinStages(registry);

  std::string classes;
  for (const auto& c : registry.classNames()) classes += (classes.empty() ? "`" : ", `") + c + "`";
  SectionDoc pipeline{
      core::Pipeline::kSection,
      "dynslam",
      "the runner (core::Pipeline)",
      "Stages run in the order listed; each reads the section named after its "
      "class, or `Class:Section` gives it a section of its own (two instances of "
      "one class configured apart).",
      {{"stages", "", "", "stage class names, separated by commas or blanks; registered: " + classes}}};
  out.push_back(pipeline);
  out.push_back({io::SensorSync::kSection, "dynslam", "the runner (io::SensorSync)", "",
                 keysOf(io::SensorSyncOptions())});

  for (const auto& className : registry.classNames()) {
    const StageRecord defaults = recordStage(registry, className, "");
    const std::string owner = "stage `" + className + "` (" + defaults.type + ")";
    for (const auto& [section, keys] : defaults.sections) {
      // No word on whether configure() succeeded: with the defaults that depends on the
      // machine (the detector's model file), and the page must not.
      SectionDoc doc{section, "dynslam", owner, "", keys};
      addVariantKeys(registry, className, doc);
      out.push_back(std::move(doc));
    }
  }

  {
    ScopedRecorder scoped;
    try {
      sim::ScenarioOptions().load(core::IniConfig::fromText("", "<defaults>"));
    } catch (const std::exception&) {
      // a scenario needs some keys set; the sections were recorded before the check
    }
    for (auto& [section, keys] : scoped.recorder.sections)
      out.push_back(
          {section, "dynslam-sim", "the scenario (sim::ScenarioOptions)", "", std::move(keys)});
  }
  out.push_back({navdemo::NavDemoOptions::kSection, "dynslam-nav-demo",
                 "dynslam-nav-demo (navdemo::NavDemoOptions)", "", keysOf(navdemo::NavDemoOptions())});
  out.push_back({navdemo::RobotOptions::kSection, "dynslam-nav-demo",
                 "dynslam-nav-demo's simulated robot (navdemo::RobotOptions)", "",
                 keysOf(navdemo::RobotOptions())});
  out.push_back({nav::NavigationOptions::kSection, "dynslam-nav-demo",
                 "the navigation adapter (nav::NavigationAdapter; also `bench-nav-adapter "
                 "--nav-config`)",
                 "The robot's navigation frame is its base at the SLAM system's first pose.",
                 keysOf(nav::NavigationOptions())});
  return out;
}

std::string toMarkdown(const std::vector<SectionDoc>& sections) {
  std::ostringstream md;
  size_t keys = 0;  // distinct names: a key two variants write (nms_iou) counts once
  for (const auto& s : sections) {
    std::set<std::string> names;
    for (const auto& k : s.keys) names.insert(k.key);
    keys += names.size();
  }
  md << "# Parameter reference\n\n"
     << "<!-- Generated from the code by `" << kRegenerateCommand
     << "`; do not edit: the test ParameterReference fails when this file and the code differ. "
        "-->\n\n"
     << "Every ini key the programs read (" << keys << " keys in " << sections.size()
     << " sections), with its default, the values it accepts and its meaning, as the options "
        "structs describe them. Regenerate with `"
     << kRegenerateCommand << "`.\n\n"
     << "A key can be set in the ini file given to `--config` or on the command line with "
        "`--set Section.key=value`. Unknown sections and keys are errors that name them. A section "
        "that is absent leaves every key at its default.\n\n";
  std::string program;
  for (const auto& s : sections) {
    if (s.program != program) {
      program = s.program;
      md << (program == "dynslam"       ? "- `dynslam` (`--config FILE.ini`)\n"
             : program == "dynslam-sim" ? "- `dynslam-sim` scenario files (`params/sim/*.ini`)\n"
                                        : "- `dynslam-nav-demo` navigation scenarios "
                                          "(`params/nav/*.ini`)\n");
    }
    md << "  - [`[" << s.section << "]`](#" << anchor(s) << ") " << s.owner << ", " << s.keys.size()
       << " keys\n";
  }
  for (const auto& s : sections) {
    md << "\n<a id=\"" << anchor(s) << "\"></a>\n## `[" << s.section << "]` (" << s.program
       << ")\n\nRead by " << s.owner << ".";
    if (!s.note.empty()) md << " " << s.note;
    md << "\n\n| key | default | accepts | meaning |\n|---|---|---|---|\n";
    for (const auto& k : s.keys)
      md << "| `" << k.key << "` | "
         << (k.default_value.empty() ? "*(empty)*" : "`" + markdownCell(k.default_value) + "`")
         << " | " << markdownCell(k.accepts) << " | " << markdownCell(k.meaning) << " |\n";
  }
  return md.str();
}

}  // namespace dynslam::params
