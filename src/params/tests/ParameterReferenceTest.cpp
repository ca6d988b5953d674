// docs/parameters.md is what dynslam-params generates from the code, and it covers every key.
#include "params/ParameterReference.h"

#include <dynslam/core/Config.h>
#include <dynslam/core/StageRegistry.h>
#include <dynslam/testing/TestEnv.h>

#include <dynslam/system/BuiltinStages.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <sstream>

using namespace dynslam;

namespace {

const params::SectionDoc* find(const std::vector<params::SectionDoc>& all,
                               const std::string& program, const std::string& section) {
  for (const auto& s : all)
    if (s.program == program && s.section == section) return &s;
  return nullptr;
}

}  // namespace

TEST(ParameterReference, CommittedPageIsWhatTheCodeGenerates) {
  const std::string path = dynslam::testing::sourceDir() + "/docs/parameters.md";
  const std::string committed = dynslam::testing::readTextFile(path);
  const std::string generated = params::toMarkdown(params::collectParameters());
  if (committed == generated) return;
  // Name the first line that differs, so the failure says what drifted.
  std::istringstream a(committed), b(generated);
  std::string la, lb;
  int line = 1;
  while (std::getline(a, la) && std::getline(b, lb) && la == lb) ++line;
  ADD_FAILURE() << path << " differs from the code at line " << line << ":\n  committed: " << la
                << "\n  generated: " << lb
                << "\nRegenerate it from the repository root with: " << params::kRegenerateCommand;
}

TEST(ParameterReference, EveryStageAndEveryKeyIsThere) {
  const auto all = params::collectParameters();
  core::StageRegistry registry;
  system::registerBuiltinStages(registry);
  for (const auto& className : registry.classNames()) {
    const auto* s = find(all, "dynslam", className);
    ASSERT_TRUE(s) << "registered stage " << className << " has no section in the reference";
    EXPECT_FALSE(s->keys.empty()) << className;
  }
  ASSERT_TRUE(find(all, "dynslam", "pipeline"));
  ASSERT_TRUE(find(all, "dynslam", "SensorSync"));
  ASSERT_TRUE(find(all, "dynslam-sim", "Scenario"));

  // The same keys strict loading accepts: a key the reference lists is accepted by the stage,
  // and (checked on one stage) an unknown one is not.
  const auto* tracking = find(all, "dynslam", "Tracking");
  ASSERT_TRUE(tracking);
  auto stage = registry.create("Tracking");
  for (const auto& k : tracking->keys)
    EXPECT_NO_THROW(stage->configure(
        core::IniConfig::fromText("[Tracking]\n" + k.key + " = " + k.default_value + "\n"),
        "Tracking"))
        << k.key << " = " << k.default_value;
  EXPECT_THROW(
      stage->configure(core::IniConfig::fromText("[Tracking]\nnot_a_key = 1\n"), "Tracking"),
      core::ConfigError);

  size_t undocumented = 0, keys = 0;
  for (const auto& s : all)
    for (const auto& k : s.keys) {
      ++keys;
      if (k.meaning.empty()) {
        ++undocumented;
        ADD_FAILURE() << "[" << s.section << "] " << k.key << " (" << s.program
                      << ") has no comment in its saveToConfigFile";
      }
    }
  EXPECT_GT(keys, 100u);
  EXPECT_EQ(undocumented, 0u);
}

TEST(ParameterReference, ObserverIsOffOutsideTheGenerator) {
  params::collectParameters();
  EXPECT_EQ(core::setOptionsObserver(nullptr), nullptr)
      << "collectParameters left its recorder installed";
}
