#pragma once
// The parameter reference (docs/parameters.md): every ini key the programs read, with its
// default and its meaning, taken from the options structs themselves. Each registered stage is
// configured once from an empty ini while a core::OptionsObserver records what its
// saveToConfigFile() writes (core::writeKey: key, default, comment), so a new key or stage shows
// up here without anyone listing it.
#include <string>
#include <vector>

namespace dynslam::params {

struct KeyDoc {
  std::string key;
  std::string default_value;  ///< as the ini would hold it ("" for an empty string)
  std::string meaning;        ///< the comment saveToConfigFile writes beside it
};

struct SectionDoc {
  std::string section;  ///< the ini section, e.g. "Tracking"
  std::string program;  ///< "dynslam" or "dynslam-sim"
  std::string owner;    ///< who reads it: "stage Tracking (dynslam::tracking::TrackingStage)"
  std::string note;     ///< extra text (e.g. how [pipeline] names stages), may be empty
  std::vector<KeyDoc> keys;
};

/// The sections of dynslam (the runner's [pipeline] and [SensorSync], then every registered
/// stage's sections in registry order) and of dynslam-sim's scenario files.
std::vector<SectionDoc> collectParameters();

/// The markdown page: a contents list, then one table (key | default | meaning) per section.
std::string toMarkdown(const std::vector<SectionDoc>& sections);

/// The command that regenerates docs/parameters.md (quoted in the page and in the test).
constexpr const char* kRegenerateCommand = "build/bin/dynslam-params --out docs/parameters.md";

}  // namespace dynslam::params
