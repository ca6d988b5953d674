// Reading dynslam-sim's objects.txt: the fields of each row, comments, the frame/time index and
// errors that name the file and the line.
#include <dynslam/core/ObjectGroundTruth.h>
#include <dynslam/testing/TestEnv.h>

#include <gtest/gtest.h>

namespace core = dynslam::core;
namespace dt = dynslam::testing;

namespace {

// The header dynslam-sim writes, then two frames (the second with two objects).
const char* kObjects =
    "# dynslam-sim object ground truth: one line per frame and object at least partly in view\n"
    "# frame t id class moving tx ty tz qx qy qz qw box_x box_y box_w box_h visible_pixels "
    "visible_fraction\n"
    "0 1700000000.0333333 3 person 1 1.5 -2 0.9 0 0 0.70710678118654757 0.70710678118654757 "
    "100 50 40 120 3900 0.81000000000000005\n"
    "\n"
    "1 1700000000.0666667 3 person 1 1.52 -2 0.9 0 0 0 1 102 50 40 121 0 0\n"
    "1 1700000000.0666667 7 car 0 4 5 0 0 0 0 2 0 200 160 90 12000 1\n";

std::string errorOf(const std::string& path) {
  try {
    core::readObjectGroundTruth(path);
  } catch (const core::ObjectGroundTruthError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(ObjectGroundTruth, ReadsEveryFieldAndSkipsComments) {
  const auto path = dt::writeTextFile(dt::scratchDir() + "/objects.txt", kObjects);
  const auto rows = core::readObjectGroundTruth(path);
  ASSERT_EQ(rows.size(), 3u);
  const auto& a = rows[0];
  EXPECT_EQ(a.frame, 0u);
  EXPECT_DOUBLE_EQ(a.t, 1700000000.0333333);
  EXPECT_EQ(a.id, 3);
  EXPECT_EQ(a.category, "person");
  EXPECT_TRUE(a.moving);
  EXPECT_TRUE(a.T_world_object.translation().isApprox(Eigen::Vector3d(1.5, -2, 0.9)));
  // qz = qw = sqrt(1/2): 90 degrees about z takes x to y.
  EXPECT_TRUE((a.T_world_object.linear() * Eigen::Vector3d::UnitX())
                  .isApprox(Eigen::Vector3d::UnitY(), 1e-12));
  EXPECT_EQ(a.box, cv::Rect(100, 50, 40, 120));
  EXPECT_EQ(a.visible_pixels, 3900);
  EXPECT_DOUBLE_EQ(a.visible_fraction, 0.81);
  EXPECT_EQ(rows[2].category, "car");
  EXPECT_FALSE(rows[2].moving);
  // A quaternion of length 2 is normalised.
  EXPECT_TRUE(rows[2].T_world_object.linear().isApprox(Eigen::Matrix3d::Identity()));
}

TEST(ObjectGroundTruth, IndexFindsFramesByNumberAndByNearestStamp) {
  const auto path = dt::writeTextFile(dt::scratchDir() + "/objects.txt", kObjects);
  const core::ObjectGroundTruthIndex index(core::readObjectGroundTruth(path));
  EXPECT_EQ(index.frameCount(), 2u);
  EXPECT_EQ(index.byFrame(1).size(), 2u);
  EXPECT_TRUE(index.byFrame(5).empty());
  // A stamp that went through MRPT's 100 ns clock still finds its frame.
  const auto& second = index.atTime(1700000000.06667);
  ASSERT_EQ(second.size(), 2u);
  EXPECT_EQ(second[1].id, 7);
  EXPECT_EQ(index.atTime(1700000000.0334).front().frame, 0u);
  EXPECT_TRUE(index.atTime(1700000000.05).empty());  // halfway: beyond the 1 ms tolerance
  EXPECT_EQ(index.atTime(1700000000.05, 0.02).front().frame, 1u);
}

TEST(ObjectGroundTruth, MalformedLinesNameFileLineAndField) {
  const std::string dir = dt::scratchDir();
  const auto shortLine = dt::writeTextFile(dir + "/short.txt", "# c\n0 1.0 3 person 1 0 0 0\n");
  EXPECT_NE(errorOf(shortLine).find(shortLine + ":2: expected 18 fields"), std::string::npos)
      << errorOf(shortLine);
  const auto badNumber =
      dt::writeTextFile(dir + "/bad.txt", "0 1.0 3 person 1 0 0 x 0 0 0 1 0 0 1 1 1 1\n");
  EXPECT_NE(errorOf(badNumber).find(badNumber + ":1: field 8 ('x') is not a finite number"),
            std::string::npos)
      << errorOf(badNumber);
  const auto badMoving =
      dt::writeTextFile(dir + "/moving.txt", "0 1.0 3 person 2 0 0 0 0 0 0 1 0 0 1 1 1 1\n");
  EXPECT_NE(errorOf(badMoving).find(":1: field 5 ('2') is not 0 or 1"), std::string::npos);
  const auto badFraction =
      dt::writeTextFile(dir + "/fraction.txt", "0 1.0 3 person 1 0 0 0 0 0 0 1 0 0 1 1 1 1.5\n");
  EXPECT_NE(errorOf(badFraction).find("field 18 ('1.5')"), std::string::npos);
  EXPECT_NE(errorOf(dir + "/absent.txt").find("cannot open"), std::string::npos);
  EXPECT_NE(errorOf(dir + "/absent.txt").find(dir + "/absent.txt"), std::string::npos);
}
