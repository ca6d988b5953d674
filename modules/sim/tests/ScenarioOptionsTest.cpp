// The scenario's ini sections: each key read once from its describe(), values out of range or
// not among a key's words refused naming the section, the key and the file; every shipped
// scenario loads.
#include <dynslam/core/Config.h>
#include <dynslam/sim/ScenarioOptions.h>
#include <dynslam/testing/TestEnv.h>
#include <gtest/gtest.h>

#include <filesystem>

namespace dynslam::sim {
namespace {

std::string loadError(const std::string& ini) {
  try {
    ScenarioOptions().load(core::IniConfig::fromText(ini, "scenario.ini"));
  } catch (const std::exception& e) {
    return e.what();
  }
  return "no error";
}

TEST(ScenarioOptions, TheStereoDepthModelTakesTheCamerasFocalLengthAndItsOwnKeysOnly) {
  ScenarioOptions o;
  o.load(
      core::IniConfig::fromText("[Scenario]\nfx = 380\n[Noise]\ndepth_model = stereo\n"
                                "stereo_baseline = 0.095\n[Calibration]\ntime_offset_s = 0.01\n"));
  EXPECT_EQ(o.noise.rgbd.depth_model, DepthModel::Stereo);
  EXPECT_DOUBLE_EQ(o.noise.rgbd.focal_px, 380);
  EXPECT_DOUBLE_EQ(o.noise.rgbd.stereo_baseline, 0.095);
  EXPECT_DOUBLE_EQ(o.calibration.time_offset_s, 0.01);
  EXPECT_NE(loadError("[Noise]\nstereo_baseline = 0.095\n").find("stereo_baseline"),
            std::string::npos);
  EXPECT_NE(
      loadError("[Noise]\ndepth_model = stereo\ndepth_sigma_z2 = 0.002\n").find("depth_sigma_z2"),
      std::string::npos);
  EXPECT_NE(loadError("[Calibration]\ntime_offset_s = 0.3\n").find("time_offset_s"),
            std::string::npos);
}

TEST(ScenarioOptions, ValuesAreReadIntoEverySection) {
  ScenarioOptions o;
  o.load(core::IniConfig::fromText(
      "[Scenario]\nscene = street\nseed = 7\n[Camera]\npath = drive\n[Cars]\nparked = 2\n"
      "[Imu]\ngyro_bias0_y = 0.01\nnoise = false\n[Gnss]\nenabled = true\nlever_arm_z = 1.5\n"
      "[Noise]\nedge_hole_width = 0\n[Augment]\nfloor_frames = 3\n"));
  EXPECT_EQ(o.world.scene, "street");
  EXPECT_EQ(o.world.seed, 7);
  EXPECT_EQ(o.camera.path, "drive");
  EXPECT_EQ(o.cars.parked, 2);
  EXPECT_DOUBLE_EQ(o.imu.imu.gyro_bias0.y(), 0.01);
  EXPECT_FALSE(o.imu.imu.noise);
  EXPECT_TRUE(o.gnss.enabled);
  EXPECT_DOUBLE_EQ(o.gnss.gnss.lever_arm.z(), 1.5);
  EXPECT_EQ(o.noise.rgbd.edge_hole_width, 0);
  EXPECT_EQ(o.augment.floor_frames, 3);
}

TEST(ScenarioOptions, BadValuesAreRefusedNamingSectionKeyAndFile) {
  for (const auto& [ini, expected] :
       {std::pair{"[Scenario]\nscene = forest\n", "[Scenario] in scenario.ini: scene = 'forest'"},
        std::pair{"[Scenario]\nduration = 0\n", "duration = 0: must be > 0"},
        std::pair{"[Camera]\npath = fly\n", "path = 'fly': expected orbit or drive"},
        std::pair{"[People]\nwalkers = two\n", "walkers = 'two': expected a whole number"},
        std::pair{"[Gnss]\nfix_quality = 9\n", "fix_quality = 9: must be in [0, 8]"},
        std::pair{"[Imu]\nnoise = maybe\n", "noise = 'maybe'"},
        std::pair{"[Augment]\nfloor_max_tilt_deg = 90\n", "floor_max_tilt_deg = 90"},
        std::pair{"[Scenario]\nscene = room\n[Cars]\ndriving = 1\n", "[Cars] in scenario.ini"},
        std::pair{"[Scenario]\nscene = augment\n", "[Augment] rawlog is empty"}}) {
    const std::string error = loadError(ini);
    EXPECT_NE(error.find(expected), std::string::npos) << ini << " -> " << error;
  }
}

TEST(ScenarioOptions, EveryShippedScenarioLoads) {
  namespace fs = std::filesystem;
  size_t files = 0;
  for (const auto& entry : fs::directory_iterator(fs::path(testing::sourceDir()) / "params/sim")) {
    if (entry.path().extension() != ".ini") continue;
    ++files;
    EXPECT_NO_THROW(ScenarioOptions().load(core::IniConfig::fromFile(entry.path().string())))
        << entry.path();
  }
  EXPECT_GE(files, 9u);
}

}  // namespace
}  // namespace dynslam::sim
