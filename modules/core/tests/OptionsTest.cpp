#include <dynslam/core/Config.h>
#include <dynslam/core/Options.h>

#include <mrpt/config/CConfigFileMemory.h>

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

using namespace dynslam::core;

namespace {

enum class Mode { Fast, Exact };
constexpr Keyword<Mode> kModes[] = {{"fast", Mode::Fast}, {"exact", Mode::Exact}};

struct ExampleOptions : Options {
  double threshold = 0.5;
  int iterations = 100;
  bool refine = false;
  int refine_steps = 0;
  std::string model = "none";
  Mode mode = Mode::Exact;

  void describe(OptionVisitor& v) override {
    v.key("threshold", threshold, Range::closedOpen(0, 1), "a threshold");
    v.key("iterations", iterations, Range::atLeast(1), "how many times");
    v.key("refine", refine, "refine the result");
    v.key("refine_steps", refine_steps, Range::atLeast(0), "0 = off; steps of refinement");
    v.path("model", model, "model file");
    v.key("mode", mode, kModes, "fast | exact");
    v.requires("refine_steps", refine_steps > 0, "refine = true", refine);
  }
};

/// The message loadOptionsStrict gives for `ini`, or "" when it loads.
std::string loadError(const std::string& ini) {
  ExampleOptions o;
  try {
    loadOptionsStrict(o, IniConfig::fromText(ini, "my.ini"), "Ex");
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

}  // namespace

TEST(Options, LoadsWhatTheSectionHoldsAndKeepsDefaultsForTheRest) {
  ExampleOptions o;
  loadOptionsStrict(o,
                    IniConfig::fromText("[Ex]\nthreshold = 0.25   // a comment\nmode = fast\n"
                                        "refine = yes\nrefine_steps = 3\n"),
                    "Ex");
  EXPECT_DOUBLE_EQ(o.threshold, 0.25);
  EXPECT_EQ(o.iterations, 100);
  EXPECT_EQ(o.model, "none");
  EXPECT_EQ(o.mode, Mode::Fast);
  EXPECT_TRUE(o.refine);
  EXPECT_EQ(o.refine_steps, 3);
}

TEST(Options, ValueOutsideItsRangeIsAnErrorNamingKeyValueRangeSectionAndFile) {
  const std::string msg = loadError("[Ex]\nthreshold = 1\n");
  EXPECT_TRUE(contains(msg, "threshold = 1")) << msg;
  EXPECT_TRUE(contains(msg, "[0, 1)")) << msg;
  EXPECT_TRUE(contains(msg, "[Ex]")) << msg;
  EXPECT_TRUE(contains(msg, "my.ini")) << msg;
  EXPECT_TRUE(contains(loadError("[Ex]\niterations = 0\n"), ">= 1"));
}

TEST(Options, TextWhereANumberBelongsIsAnErrorNotAZero) {
  // MRPT's read_double would take "0.5 ; x" for 0.5 and "abc" for 0.
  EXPECT_TRUE(contains(loadError("[Ex]\nthreshold = abc\n"), "expected a number"));
  EXPECT_TRUE(contains(loadError("[Ex]\nthreshold = 0.5 ; x\n"), "'0.5 ; x'"));
  EXPECT_TRUE(contains(loadError("[Ex]\niterations = 2.5\n"), "expected a whole number"));
  EXPECT_TRUE(contains(loadError("[Ex]\nmode = slow\n"), "expected fast or exact"));
  EXPECT_TRUE(contains(loadError("[Ex]\nrefine = maybe\n"), "refine = 'maybe'"));
}

TEST(Options, SettingThatNeedsAnotherIsAnErrorNamingBoth) {
  const std::string msg = loadError("[Ex]\nrefine_steps = 3\n");
  EXPECT_TRUE(contains(msg, "refine_steps")) << msg;
  EXPECT_TRUE(contains(msg, "refine = true")) << msg;
  EXPECT_EQ(loadError("[Ex]\nrefine_steps = 3\nrefine = true\n"), "");
  EXPECT_EQ(loadError("[Ex]\nrefine = true\n"), "") << "the needed one alone is fine";
}

TEST(Options, ADefaultThatNeedsASettingTheIniTurnsOffIsNoError) {
  struct Defaulted : ExampleOptions {
    Defaulted() { refine = true, refine_steps = 5; }
  };
  Defaulted o;
  EXPECT_NO_THROW(loadOptionsStrict(o, IniConfig::fromText("[Ex]\nrefine = false\n"), "Ex"));
  EXPECT_FALSE(o.refine);
}

TEST(Options, UnknownKeyIsStillAnError) {
  EXPECT_TRUE(contains(loadError("[Ex]\nthresold = 0.2\n"), "unknown key 'thresold'"));
}

TEST(Options, SavedKeysLoadBackToTheSameValues) {
  ExampleOptions a;
  a.threshold = 0.125;
  a.iterations = 7;
  a.model = "m.onnx";
  a.mode = Mode::Fast;
  mrpt::config::CConfigFileMemory saved;
  a.saveToConfigFile(saved, "Ex");
  std::string text;  // as a file holds it: MRPT keeps the names it wrote padded until then
  saved.getContent(text);
  ExampleOptions b;
  b.loadFromConfigFile(mrpt::config::CConfigFileMemory(text), "Ex");
  EXPECT_DOUBLE_EQ(b.threshold, 0.125);
  EXPECT_EQ(b.iterations, 7);
  EXPECT_EQ(b.model, "m.onnx");
  EXPECT_EQ(b.mode, Mode::Fast);
  EXPECT_EQ(knownKeys(a).size(), 6u);
}

TEST(Options, DescribeKeysGivesDefaultRangeAndNeeds) {
  const auto keys = describeKeys(ExampleOptions{});
  ASSERT_EQ(keys.size(), 6u);
  EXPECT_EQ(keys[0].key, "threshold");
  EXPECT_EQ(keys[0].default_value, "0.5");
  EXPECT_EQ(keys[0].accepts, "[0, 1)");
  EXPECT_EQ(keys[1].accepts, ">= 1");
  EXPECT_EQ(keys[2].accepts, "true | false");
  EXPECT_EQ(keys[5].accepts, "fast | exact");
  EXPECT_EQ(keys[5].default_value, "exact");
  EXPECT_TRUE(contains(keys[3].meaning, "needs refine = true")) << keys[3].meaning;
}

TEST(Options, CheckRefusesValuesSetInCodeOutsideTheirRange) {
  ExampleOptions o;
  EXPECT_NO_THROW(o.check());
  o.threshold = -0.1;
  EXPECT_THROW(o.check(), std::invalid_argument);
}

TEST(Range, Text) {
  EXPECT_EQ(Range::any().text(), "any");
  EXPECT_EQ(Range::above(0).text(), "> 0");
  EXPECT_EQ(Range::closed(0, 2).text(), "[0, 2]");
  EXPECT_FALSE(Range::above(0).contains(0));
  EXPECT_FALSE(Range::any().contains(std::nan("")));
}

TEST(Options, ARelativePathTheWorkingDirectoryLacksIsTakenFromTheInisFolder) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("dynslam-options-" + std::to_string(getpid()));
  fs::create_directories(dir / "models");
  std::ofstream(dir / "models" / "net.onnx") << "x";
  std::ofstream(dir / "a.ini") << "[Ex]\nmodel = models/net.onnx\n";
  ExampleOptions o;
  loadOptionsStrict(o, IniConfig::fromFile((dir / "a.ini").string()), "Ex");
  EXPECT_EQ(o.model, (dir / "models" / "net.onnx").string()) << "found beside the ini";

  std::ofstream(dir / "b.ini") << "[Ex]\nmodel = models/missing.onnx\n";
  ExampleOptions missing;
  loadOptionsStrict(missing, IniConfig::fromFile((dir / "b.ini").string()), "Ex");
  EXPECT_EQ(missing.model, "models/missing.onnx") << "left for its user to refuse";
  const std::string lookup = pathLookup("models/missing.onnx");
  EXPECT_TRUE(contains(lookup, (fs::current_path() / "models/missing.onnx").string())) << lookup;
  EXPECT_TRUE(contains(lookup, (dir / "models/missing.onnx").string())) << lookup;
  fs::remove_all(dir);
}
