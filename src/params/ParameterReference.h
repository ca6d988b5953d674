#pragma once
// The parameter reference (docs/parameters.md): every ini key the programs read, with its
// default, the values it accepts and its meaning, taken from the options structs themselves.
// Each registered stage is configured once from an empty ini while a core::OptionsObserver
// records the options structs it loads; each struct's describe() (core::Options) lists its keys,
// so a new key or stage shows up here without anyone listing it.
#include <dynslam/core/Options.h>

#include <string>
#include <vector>

namespace dynslam::params {

using core::KeyDoc;

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

/// The markdown page: a contents list, then one table (key | default | accepts | meaning) per
/// section.
std::string toMarkdown(const std::vector<SectionDoc>& sections);

/// The command that regenerates docs/parameters.md (quoted in the page and in the test).
constexpr const char* kRegenerateCommand = "build/bin/dynslam-params --out docs/parameters.md";

}  // namespace dynslam::params
