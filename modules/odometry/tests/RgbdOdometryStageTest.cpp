#include <dynslam/core/Config.h>
#include <dynslam/odometry/RgbdOdometryStage.h>
#include <dynslam/testing/SyntheticRoom.h>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>

using namespace dynslam;

TEST(RgbdOdometry, RecoversAKnownCameraMotion) {
  odometry::RgbdOdometryStage stage;
  stage.configure(core::IniConfig::fromText(""), "RgbdOdometry");

  const auto truth =
      dynslam::testing::handheldPath(25);  // long enough for several keyframe changes
  const auto camera = dynslam::testing::vgaCamera();
  double worstT = 0, worstR = 0;
  for (size_t i = 0; i < truth.size(); ++i) {
    core::Frame f;
    f.index = i;
    f.t = 0.033 * i;
    f.intrinsics = camera;
    dynslam::testing::renderRoom(truth[i], camera, f.rgb, f.depth);
    stage.process(f);
    ASSERT_TRUE(f.T_world_camera.has_value());
    const Eigen::Isometry3d err = truth[i].inverse() * *f.T_world_camera;
    worstT = std::max(worstT, err.translation().norm());
    worstR = std::max(worstR, Eigen::AngleAxisd(err.rotation()).angle() * 180 / M_PI);
  }
  std::cout << "[ INFO ] worst error over 25 frames: " << worstT * 1000 << " mm, " << worstR
            << " deg\n";
  EXPECT_LT(worstT, 0.005);
  EXPECT_LT(worstR, 0.3);
  EXPECT_EQ(stage.failures(), 0u);
  EXPECT_GE(stage.keyframes(), 1u);
}

TEST(RgbdOdometry, UnknownMethodKeyOrValueOutOfRangeIsAConfigErrorNamingIt) {
  for (const char* bad : {"method = orb", "max_dept = 3", "max_depth = 0", "min_depth = -1",
                          "max_rotation_deg = 0", "keyframe_translation = x"}) {
    odometry::RgbdOdometryStage stage;
    try {
      stage.configure(core::IniConfig::fromText(std::string("[O]\n") + bad, "o.ini"), "O");
      FAIL() << bad << " accepted";
    } catch (const core::ConfigError& e) {
      const std::string key = std::string(bad).substr(0, std::string(bad).find(' '));
      EXPECT_NE(std::string(e.what()).find(key), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("o.ini"), std::string::npos) << e.what();
    }
  }
}
