#include <dynslam/core/Config.h>
#include <dynslam/testing/TestEnv.h>

#include <mrpt/config/CConfigFileBase.h>
#include <mrpt/config/CLoadableOptions.h>

#include <fstream>

using namespace dynslam::core;

namespace {

struct ExampleOptions : mrpt::config::CLoadableOptions {
  double threshold = 0.5;
  int iterations = 100;
  std::string model = "none";

  void loadFromConfigFile(const mrpt::config::CConfigFileBase& c, const std::string& s) override {
    MRPT_LOAD_CONFIG_VAR(threshold, double, c, s);
    MRPT_LOAD_CONFIG_VAR(iterations, int, c, s);
    MRPT_LOAD_CONFIG_VAR(model, string, c, s);
  }
  void saveToConfigFile(mrpt::config::CConfigFileBase& c, const std::string& s) const override {
    MRPT_SAVE_CONFIG_VAR_COMMENT(threshold, "a threshold");
    MRPT_SAVE_CONFIG_VAR_COMMENT(iterations, "how many times");
    MRPT_SAVE_CONFIG_VAR_COMMENT(model, "model file");
  }
};

}  // namespace

TEST(Config, LoadsKnownKeysAndKeepsDefaults) {
  const auto cfg = IniConfig::fromText("[Ex]\nthreshold = 0.25\n");
  ExampleOptions o;
  loadOptionsStrict(o, cfg, "Ex");
  EXPECT_DOUBLE_EQ(o.threshold, 0.25);
  EXPECT_EQ(o.iterations, 100);
  EXPECT_EQ(o.model, "none");
}

TEST(Config, UnknownKeyIsAnErrorNamingKeySectionAndSource) {
  const auto cfg = IniConfig::fromText("[Ex]\nthresold = 0.25\n", "my.ini");
  ExampleOptions o;
  try {
    loadOptionsStrict(o, cfg, "Ex");
    FAIL() << "no error for an unknown key";
  } catch (const ConfigError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("'thresold'"), std::string::npos) << msg;
    EXPECT_NE(msg.find("[Ex]"), std::string::npos) << msg;
    EXPECT_NE(msg.find("my.ini"), std::string::npos) << msg;
    EXPECT_NE(msg.find("threshold"), std::string::npos) << "lists the known keys: " << msg;
  }
}

TEST(Config, KnownKeysComeFromSaveToConfigFile) {
  const auto keys = knownKeys(ExampleOptions{});
  ASSERT_EQ(keys.size(), 3u);
  EXPECT_NE(std::find(keys.begin(), keys.end(), "iterations"), keys.end());
}

TEST(Config, OverridesReplaceAndAddValues) {
  auto cfg = IniConfig::fromText("[Ex]\nthreshold = 0.25\n");
  cfg.applyOverride("Ex.threshold=0.75");
  cfg.applyOverride("Ex.iterations = 7");
  ExampleOptions o;
  loadOptionsStrict(o, cfg, "Ex");
  EXPECT_DOUBLE_EQ(o.threshold, 0.75);
  EXPECT_EQ(o.iterations, 7);
}

TEST(Config, OverrideOfUnknownKeyIsCaughtWhenLoading) {
  auto cfg = IniConfig::fromText("[Ex]\n");
  cfg.applyOverride("Ex.bogus=1");
  ExampleOptions o;
  EXPECT_THROW(loadOptionsStrict(o, cfg, "Ex"), ConfigError);
}

TEST(Config, MalformedOverrideIsAnError) {
  auto cfg = IniConfig::fromText("");
  for (const char* bad : {"novalue", "nodot=1", ".key=1", "sec.=1", "a=b.c"})
    EXPECT_THROW(cfg.applyOverride(bad), ConfigError) << bad;
}

TEST(Config, MissingFileNamesIt) {
  try {
    IniConfig::fromFile("/nonexistent/dir/params.ini");
    FAIL();
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/dir/params.ini"), std::string::npos);
  }
}

TEST(Config, FromFileAppliesOverrides) {
  const std::string path = dynslam::testing::scratchDir() + "/p.ini";
  std::ofstream(path) << "[Ex]\nmodel = a.onnx\n";
  const auto cfg = IniConfig::fromFile(path, {"Ex.model=b.onnx"});
  EXPECT_EQ(cfg.source(), path);
  EXPECT_EQ(cfg.ini().read_string("Ex", "model", ""), "b.onnx");
}

TEST(Config, UnknownSectionIsAnError) {
  const auto cfg = IniConfig::fromText("[pipeline]\n[Tracker]\n[Trakcer]\n", "x.ini");
  EXPECT_NO_THROW(rejectUnknownSections(cfg, {"pipeline", "Tracker", "Trakcer"}));
  try {
    rejectUnknownSections(cfg, {"pipeline", "Tracker"});
    FAIL();
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("[Trakcer]"), std::string::npos) << e.what();
  }
}

namespace {
enum class Shade { Light, Dark, Grey };
constexpr Keyword<Shade> kShades[] = {
    {"light", Shade::Light}, {"dark", Shade::Dark}, {"grey", Shade::Grey}};
}  // namespace

TEST(Config, KeywordKeysReadTheirWordsAndNameTheOthers) {
  const auto cfg = IniConfig::fromText("[Ex]\nshade = dark\nother = black\n");
  EXPECT_EQ(readKeyword(cfg.ini(), "Ex", "shade", Shade::Light, kShades), Shade::Dark);
  EXPECT_EQ(readKeyword(cfg.ini(), "Ex", "absent", Shade::Grey, kShades), Shade::Grey)
      << "the current value stays when the key is absent";
  EXPECT_STREQ(wordOf(Shade::Grey, kShades), "grey");
  try {
    readKeyword(cfg.ini(), "Ex", "other", Shade::Light, kShades);
    FAIL() << "black accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "other = 'black': expected light, dark or grey");
  }
}

TEST(Config, ReadBoolTakesTrueFalseAndRejectsOtherWords) {
  const auto cfg = IniConfig::fromText("[Ex]\na = true\nb = 0\nc = yes\nd = maybe\n");
  EXPECT_TRUE(readBool(cfg.ini(), "Ex", "a", false));
  EXPECT_FALSE(readBool(cfg.ini(), "Ex", "b", true));
  EXPECT_TRUE(readBool(cfg.ini(), "Ex", "c", false));
  EXPECT_TRUE(readBool(cfg.ini(), "Ex", "absent", true)) << "absent: the current value";
  EXPECT_FALSE(readBool(cfg.ini(), "Ex", "absent", false));
  try {
    readBool(cfg.ini(), "Ex", "d", true);
    FAIL() << "'maybe' accepted (MRPT's read_bool takes it for false)";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("d = 'maybe'"), std::string::npos) << e.what();
  }
}

namespace {

struct SwitchOptions : mrpt::config::CLoadableOptions {
  bool enabled = true;
  void loadFromConfigFile(const mrpt::config::CConfigFileBase& c, const std::string& s) override {
    enabled = readBool(c, s, "enabled", enabled);
  }
  void saveToConfigFile(mrpt::config::CConfigFileBase& c, const std::string& s) const override {
    MRPT_SAVE_CONFIG_VAR_COMMENT(enabled, "on or off");
  }
};

}  // namespace

TEST(Config, AValueRefusedWhileLoadingNamesTheSectionAndTheSource) {
  const auto cfg = IniConfig::fromText("[Ex]\nenabled = maybe\n", "ex.ini");
  SwitchOptions o;
  try {
    loadOptionsStrict(o, cfg, "Ex");
    FAIL() << "enabled = maybe accepted";
  } catch (const ConfigError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("[Ex]"), std::string::npos) << what;
    EXPECT_NE(what.find("ex.ini"), std::string::npos) << what;
    EXPECT_NE(what.find("enabled = 'maybe'"), std::string::npos) << what;
  }
}
