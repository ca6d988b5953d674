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

TEST(RgbdOdometry, UnknownMethodIsAConfigError) {
  odometry::RgbdOdometryStage stage;
  EXPECT_THROW(stage.configure(core::IniConfig::fromText("[O]\nmethod = orb\n"), "O"),
               core::ConfigError);
  EXPECT_THROW(stage.configure(core::IniConfig::fromText("[O]\nmax_dept = 3\n"), "O"),
               core::ConfigError);
}
