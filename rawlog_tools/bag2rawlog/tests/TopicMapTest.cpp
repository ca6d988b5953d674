// The topic map: the example inis in params/bag2rawlog load strictly and are consistent;
// poses parse in TUM order.
#include "TopicMap.h"

#include <dynslam/core/Config.h>
#include <dynslam/rawlog_tools/ConversionError.h>
#include <dynslam/testing/TestEnv.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

namespace fs = std::filesystem;
using dynslam::rawlog_tools::ConversionError;
using namespace dynslam::rawlog_tools::bag;

TEST(Bag2RawlogTopicMap, ExampleTopicMapsLoadStrictlyAndValidate) {
  const fs::path dir = fs::path(dynslam::testing::sourceDir()) / "params" / "bag2rawlog";
  size_t files = 0;
  for (const auto& entry : fs::directory_iterator(dir)) {
    if (entry.path().extension() != ".ini") continue;
    ++files;
    const auto cfg = dynslam::core::IniConfig::fromFile(entry.path().string());
    dynslam::core::rejectUnknownSections(cfg, {kSection});
    TopicMap topics;
    ASSERT_NO_THROW(dynslam::core::loadOptionsStrict(topics, cfg, kSection)) << entry.path();
    EXPECT_NO_THROW(topics.validate(entry.path().string()));
    EXPECT_TRUE(topics.hasRgbd()) << entry.path();
    EXPECT_FALSE(topics.camera_info_topic.empty()) << entry.path();
  }
  EXPECT_GE(files, 2u);
}

TEST(Bag2RawlogTopicMap, EveryKeyIsKnownToTheStrictLoader) {
  const auto keys = dynslam::core::knownKeys(TopicMap{});
  for (const char* key : {"rgb_topic", "depth_topic", "camera_info_topic", "imu_topic",
                          "accel_topic", "gyro_topic", "gnss_topic", "camera_pose", "fx"})
    EXPECT_NE(std::find(keys.begin(), keys.end(), key), keys.end()) << key;
}

TEST(Bag2RawlogTopicMap, PosesParseInTumOrderAndBadOnesAreNamed) {
  EXPECT_FALSE(parsePose("  ", "imu_pose"));
  const auto T = parsePose("1 2 3 0 0 0.7071067811865476 0.7071067811865476", "camera_pose");
  ASSERT_TRUE(T);
  EXPECT_NEAR(T->translation().y(), 2.0, 1e-12);
  // 90 degrees about z: x goes to y.
  EXPECT_NEAR((T->linear() * Eigen::Vector3d::UnitX()).y(), 1.0, 1e-9);
  try {
    parsePose("1 2 3 0 0 0", "imu_pose");
    FAIL() << "6 numbers accepted";
  } catch (const ConversionError& e) {
    EXPECT_NE(std::string(e.what()).find("imu_pose"), std::string::npos) << e.what();
  }
  EXPECT_THROW(parsePose("0 0 0 0 0 0 2", "imu_pose"), ConversionError);  // not unit
}

TEST(Bag2RawlogTopicMap, ValuesOutOfRangeAndUnmetNeedsAreRefusedNamingTheKeys) {
  const auto loadError = [](const std::string& ini) {
    TopicMap topics;
    try {
      dynslam::core::loadOptionsStrict(topics, dynslam::core::IniConfig::fromText(ini, "map.ini"),
                                       kSection);
    } catch (const std::exception& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  const std::string unmet = loadError("[bag2rawlog]\ndepth_to_colour_pose = 0 0 0 0 0 0 1\n");
  EXPECT_NE(unmet.find("depth_to_colour_pose is set, but it acts only with "
                       "depth_camera_info_topic"),
            std::string::npos)
      << unmet;
  const std::string range = loadError("[bag2rawlog]\nrgbd_max_dt = 0\n");
  EXPECT_NE(range.find("[bag2rawlog] in map.ini: rgbd_max_dt = 0: must be > 0"),
            std::string::npos)
      << range;
  TopicMap inCode;
  inCode.imu_topic = "/imu";
  inCode.reorder_window = -1;
  try {
    inCode.validate("code");
    FAIL() << "reorder_window = -1 accepted";
  } catch (const ConversionError& e) {
    EXPECT_NE(std::string(e.what()).find("reorder_window = -1"), std::string::npos) << e.what();
  }
}
