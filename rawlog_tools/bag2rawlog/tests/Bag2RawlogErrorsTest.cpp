// bag2rawlog on bad input: each error names what is wrong, and no rawlog is left behind.
#include "TestBag.h"

#include "../../tests/RawlogTestSupport.h"

#include <dynslam/testing/TestEnv.h>
#include <gtest/gtest.h>

#include <filesystem>

namespace fs = std::filesystem;
using dynslam::rawlog_tools::testing::program;
using dynslam::rawlog_tools::testing::shellQuoted;
using dynslam::testing::runCommand;

namespace {

struct Failure {
  int exitCode;
  std::string output;
  bool rawlogLeft;
};

Failure run(const std::string& topics, const std::string& bagName = "test.bag") {
  const std::string dir = dynslam::testing::scratchDir();
  const std::string bag = dir + "/" + bagName;
  if (bagName == "test.bag") bagtest::writeTestBag(bag);
  const std::string ini = dynslam::testing::writeTextFile(dir + "/topics.ini", topics);
  const auto r = runCommand(program("bag2rawlog") + " --bag " + shellQuoted(bag) + " --topics " +
                            shellQuoted(ini) + " --out " + shellQuoted(dir + "/out.rawlog"));
  return {r.exit_code, r.output, fs::exists(dir + "/out.rawlog")};
}

}  // namespace

TEST(Bag2RawlogErrors, TopicMissingFromTheBagListsTheBagsTopics) {
  const Failure f = run("[bag2rawlog]\nimu_topic = /camera/imu\n");
  EXPECT_EQ(f.exitCode, 1) << f.output;
  EXPECT_NE(f.output.find("imu_topic /camera/imu is not in"), std::string::npos) << f.output;
  EXPECT_NE(f.output.find("/imu (sensor_msgs/Imu)"), std::string::npos) << f.output;
  EXPECT_NE(f.output.find("/cam/color/image_raw (sensor_msgs/Image)"), std::string::npos)
      << f.output;
  EXPECT_FALSE(f.rawlogLeft);
}

TEST(Bag2RawlogErrors, TopicOfTheWrongTypeNamesRoleAndType) {
  const Failure f = run("[bag2rawlog]\nimu_topic = /gps/fix\n");
  EXPECT_EQ(f.exitCode, 1) << f.output;
  EXPECT_NE(f.output.find("imu_topic /gps/fix is sensor_msgs/NavSatFix"), std::string::npos)
      << f.output;
  EXPECT_NE(f.output.find("needs sensor_msgs/Imu"), std::string::npos) << f.output;
}

TEST(Bag2RawlogErrors, UnknownKeyIsNamed) {
  const Failure f = run("[bag2rawlog]\nimu_topic = /imu\nrgb_topics = /cam/color/image_raw\n");
  EXPECT_NE(f.exitCode, 0);
  EXPECT_NE(f.output.find("rgb_topics"), std::string::npos) << f.output;
}

TEST(Bag2RawlogErrors, MissingBagIsNamed) {
  const Failure f = run("[bag2rawlog]\nimu_topic = /imu\n", "absent.bag");
  EXPECT_EQ(f.exitCode, 1);
  EXPECT_NE(f.output.find("absent.bag does not exist"), std::string::npos) << f.output;
}

TEST(Bag2RawlogErrors, UnreadableDepthEncodingIsNamed) {
  const Failure f =
      run("[bag2rawlog]\nrgb_topic = /cam/color/image_raw\ndepth_topic = /cam/depth_8bit\n"
          "camera_info_topic = /cam/color/camera_info\n");
  EXPECT_EQ(f.exitCode, 1);
  EXPECT_NE(f.output.find("depth encoding 'mono8' is not supported"), std::string::npos)
      << f.output;
  EXPECT_FALSE(f.rawlogLeft);
}

TEST(Bag2RawlogErrors, InconsistentTopicMapIsRejectedBeforeReading) {
  const Failure f =
      run("[bag2rawlog]\nrgb_topic = /cam/color/image_raw\n"
          "depth_topic = /cam/aligned_depth/image_raw\n");
  EXPECT_EQ(f.exitCode, 1);
  EXPECT_NE(f.output.find("needs camera_info_topic or fx, fy, cx, cy"), std::string::npos)
      << f.output;
  const Failure g = run("[bag2rawlog]\naccel_topic = /accel/sample\n");
  EXPECT_NE(g.output.find("accel_topic and gyro_topic go together"), std::string::npos) << g.output;
}
