#include <dynslam/core/Pipeline.h>
#include <dynslam/core/StageRegistry.h>

#include <gtest/gtest.h>

#include <mrpt/config/CConfigFileBase.h>
#include <mrpt/config/CLoadableOptions.h>

using namespace dynslam::core;

namespace {

/// Adds `offset` to the frame time so the test can see order and configuration took effect.
class ShiftTime : public Stage {
 public:
  struct Options : mrpt::config::CLoadableOptions {
    double offset = 1.0;
    void loadFromConfigFile(const mrpt::config::CConfigFileBase& c, const std::string& s) override {
      MRPT_LOAD_CONFIG_VAR(offset, double, c, s);
    }
    void saveToConfigFile(mrpt::config::CConfigFileBase& c, const std::string& s) const override {
      MRPT_SAVE_CONFIG_VAR_COMMENT(offset, "seconds added");
    }
  } options;
  void configure(const IniConfig& cfg, const std::string& section) override {
    loadOptionsStrict(options, cfg, section);
  }
  void process(Frame& f) override { f.t = f.t * 10 + options.offset; }
};

class FakePose : public Stage {
 public:
  void configure(const IniConfig&, const std::string&) override {}
  void process(Frame& f) override { f.T_world_camera = Eigen::Isometry3d::Identity(); }
  bool estimatesPose() const override { return true; }
};

StageRegistry registry() {
  StageRegistry r;
  r.add<ShiftTime>("ShiftTime");
  r.add<FakePose>("FakePose");
  return r;
}

}  // namespace

TEST(Pipeline, RunsStagesInIniOrderWithTheirOwnSections) {
  const auto cfg = IniConfig::fromText(
      "[pipeline]\nstages = ShiftTime:first, ShiftTime:second FakePose\n"
      "[first]\noffset = 1\n[second]\noffset = 2\n");
  Pipeline p(cfg, registry());
  Frame f;
  f.t = 0;
  p.process(f);
  EXPECT_DOUBLE_EQ(f.t, 12.0);  // (0*10+1)*10+2: first then second
  EXPECT_TRUE(f.T_world_camera.has_value());
  EXPECT_TRUE(p.estimatesPose());
  ASSERT_EQ(p.times().size(), 3u);
  EXPECT_EQ(p.times()[1].name, "second");
  EXPECT_EQ(p.times()[1].ms.count(), 1u);
  const auto used = p.sectionsUsed();
  EXPECT_NO_THROW(rejectUnknownSections(cfg, used));
}

TEST(Pipeline, StageEntriesSplitOnCommasAndBlanksAndNameTheirSections) {
  const auto cfg =
      IniConfig::fromText("[pipeline]\nstages = ShiftTime:first,ShiftTime:second  FakePose\n");
  const auto e = pipelineStageEntries(cfg);
  ASSERT_EQ(e.size(), 3u);
  EXPECT_EQ(e[0].entry, "ShiftTime:first");
  EXPECT_EQ(e[1].class_name, "ShiftTime");
  EXPECT_EQ(e[1].section, "second");
  EXPECT_EQ(e[2].class_name, "FakePose");
  EXPECT_EQ(e[2].section, "FakePose");
}

TEST(Pipeline, UnknownStageClassIsAnErrorNamingIt) {
  const auto cfg = IniConfig::fromText("[pipeline]\nstages = ShiftTime, Teleporter\n");
  try {
    Pipeline p(cfg, registry());
    FAIL();
  } catch (const ConfigError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("'Teleporter'"), std::string::npos) << msg;
    EXPECT_NE(msg.find("ShiftTime"), std::string::npos) << "lists known classes: " << msg;
  }
}

TEST(Pipeline, UnknownKeyInStageSectionIsAnError) {
  const auto cfg = IniConfig::fromText("[pipeline]\nstages = ShiftTime\n[ShiftTime]\nofset=3\n");
  EXPECT_THROW(Pipeline(cfg, registry()), ConfigError);
}

TEST(Pipeline, UnknownKeyInPipelineSectionIsAnError) {
  const auto cfg = IniConfig::fromText("[pipeline]\nstages = ShiftTime\nstage = FakePose\n");
  EXPECT_THROW(Pipeline(cfg, registry()), ConfigError);
}

TEST(Pipeline, EmptyPipelineEstimatesNoPose) {
  const auto cfg = IniConfig::fromText("[pipeline]\nstages =\n");
  Pipeline p(cfg, registry());
  EXPECT_TRUE(p.empty());
  EXPECT_FALSE(p.estimatesPose());
}

TEST(Registry, DuplicateRegistrationIsAProgrammingError) {
  StageRegistry r = registry();
  EXPECT_THROW(r.add<FakePose>("FakePose"), std::logic_error);
  EXPECT_TRUE(r.contains("ShiftTime"));
  EXPECT_EQ(r.classNames().size(), 2u);
}
