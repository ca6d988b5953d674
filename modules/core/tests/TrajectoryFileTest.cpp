// Reading and writing TUM, KITTI and EuRoC trajectory files, and the errors that name the file
// and the line.
#include <dynslam/core/TrajectoryFile.h>
#include <dynslam/testing/TestEnv.h>

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

namespace core = dynslam::core;
namespace dt = dynslam::testing;

namespace {

/// The message of the TrajectoryFileError thrown by `read`, or "" when none is thrown.
template <typename Read>
std::string errorOf(Read&& read) {
  try {
    read();
  } catch (const core::TrajectoryFileError& e) {
    return e.what();
  }
  return "";
}

/// Each test gets one fresh scratch folder (scratchDir() empties it on every call).
class TrajectoryFile : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = dt::scratchDir(); }
  std::string writeFile(const std::string& name, const std::string& content) const {
    const std::string path = dir_ + "/" + name;
    std::ofstream(path) << content;
    return path;
  }
  std::string dir_;
};

}  // namespace

TEST_F(TrajectoryFile, ReadsTumWithCommentsBlanksAndCommas) {
  const std::string path =
      writeFile("a.tum",
                "# timestamp tx ty tz qx qy qz qw\n"
                "\n"
                "1.5 1 2 3 0 0 0 1\n"
                "   # indented comment\n"
                "2.5,4,5,6,0,0,0,2\n"        // comma separated, quaternion of length 2
                "3.5\t7 8 9  0 0 1 0\r\n");  // tab, double blank, CRLF; 180 deg about z
  const core::Trajectory t = core::readTum(path);
  ASSERT_EQ(t.size(), 3u);
  EXPECT_EQ(t[0].t, 1.5);
  EXPECT_EQ(t[1].t, 2.5);
  EXPECT_TRUE(t[0].T_world_body.translation().isApprox(Eigen::Vector3d(1, 2, 3)));
  EXPECT_TRUE(t[1].T_world_body.translation().isApprox(Eigen::Vector3d(4, 5, 6)));
  // Quaternion (0, 0, 0, 2) is normalised to the identity rotation.
  EXPECT_NEAR((t[1].T_world_body.linear() - Eigen::Matrix3d::Identity()).norm(), 0.0, 1e-15);
  const Eigen::Matrix3d half_turn_z = Eigen::Vector3d(-1, -1, 1).asDiagonal();
  EXPECT_NEAR((t[2].T_world_body.linear() - half_turn_z).norm(), 0.0, 1e-15);
}

TEST_F(TrajectoryFile, TumQuaternionOrderIsXyzw) {
  // 90 degrees about x: q = (x, y, z, w) = (sin 45, 0, 0, cos 45).
  const double h = std::sqrt(0.5);
  std::ostringstream line;
  line.precision(17);
  line << "0 0 0 0 " << h << " 0 0 " << h << "\n";
  const core::Trajectory t = core::readTum(writeFile("x90.tum", line.str()));
  const Eigen::Vector3d y_rotated = t[0].T_world_body.linear() * Eigen::Vector3d::UnitY();
  EXPECT_NEAR((y_rotated - Eigen::Vector3d::UnitZ()).norm(), 0.0, 1e-15);
}

TEST_F(TrajectoryFile, MalformedTumLineNamesFileAndLine) {
  const std::string bad_number =
      writeFile("bad.tum", "# header\n0 0 0 0 0 0 0 1\n1 0 0 0 0 0 0 1\n2 0 0 x 0 0 0 1\n");
  const std::string msg = errorOf([&] { core::readTum(bad_number); });
  EXPECT_NE(msg.find(bad_number + ":4:"), std::string::npos) << msg;
  EXPECT_NE(msg.find("'x'"), std::string::npos) << msg;

  const std::string short_line = writeFile("short.tum", "0 0 0 0 0 0 0 1\n\n1 0 0 0 0 0 1\n");
  const std::string msg2 = errorOf([&] { core::readTum(short_line); });
  EXPECT_NE(msg2.find(short_line + ":3:"), std::string::npos) << msg2;
  EXPECT_NE(msg2.find("found 7"), std::string::npos) << msg2;

  const std::string zero_q = writeFile("zero.tum", "0 1 2 3 0 0 0 0\n");
  EXPECT_NE(errorOf([&] { core::readTum(zero_q); }).find(zero_q + ":1:"), std::string::npos);
  const std::string nan = writeFile("nan.tum", "0 nan 2 3 0 0 0 1\n");
  EXPECT_NE(errorOf([&] { core::readTum(nan); }).find(nan + ":1:"), std::string::npos);
}

TEST_F(TrajectoryFile, ReadsKittiWithIndexAsTime) {
  const std::string path = writeFile("a.kitti",
                                     "1 0 0 1.5 0 1 0 2.5 0 0 1 3.5\n"
                                     "0 -1 0 4 1 0 0 5 0 0 1 6\n"
                                     "1 0 0 7 0 1 0 8 0 0 1 9\n");
  const core::Trajectory t = core::readKitti(path);
  ASSERT_EQ(t.size(), 3u);
  EXPECT_EQ(t[0].t, 0.0);
  EXPECT_EQ(t[1].t, 1.0);
  EXPECT_EQ(t[2].t, 2.0);
  EXPECT_TRUE(t[0].T_world_body.translation().isApprox(Eigen::Vector3d(1.5, 2.5, 3.5)));
  EXPECT_EQ(t[1].T_world_body.linear()(0, 1), -1.0);
  EXPECT_EQ(t[1].T_world_body.linear()(1, 0), 1.0);
}

TEST_F(TrajectoryFile, MalformedKittiLineNamesFileAndLine) {
  const std::string eleven = writeFile("eleven.kitti",
                                       "1 0 0 0 0 1 0 0 0 0 1 0\n"
                                       "1 0 0 0 0 1 0 0 0 0 1\n");
  const std::string msg = errorOf([&] { core::readKitti(eleven); });
  EXPECT_NE(msg.find(eleven + ":2:"), std::string::npos) << msg;
  EXPECT_NE(msg.find("expected 12 fields"), std::string::npos) << msg;

  const std::string word = writeFile("word.kitti",
                                     "1 0 0 0 0 1 0 0 0 0 1 0\n"
                                     "1 0 0 0 0 1 0 0 0 0 1 0\n"
                                     "1 0 0 0 0 1 0 0 0 0 one 0\n");
  const std::string msg2 = errorOf([&] { core::readKitti(word); });
  EXPECT_NE(msg2.find(word + ":3:"), std::string::npos) << msg2;
  EXPECT_NE(msg2.find("field 11"), std::string::npos) << msg2;
}

TEST_F(TrajectoryFile, ReadsEurocCsv) {
  const std::string path = writeFile(
      "gt.csv",
      "#timestamp, p_RS_R_x [m], p_RS_R_y [m], p_RS_R_z [m], q_RS_w [], q_RS_x [], q_RS_y [], "
      "q_RS_z [], v_x, v_y, v_z\n"
      "1403715524907143168,0.5,2.0,0.97,0,1,0,0,0.1,0.2,0.3\n"
      "1403715524912143104, 0.6, 2.1, 0.98, 1, 0, 0, 0\n");
  const core::Trajectory t = core::readEurocCsv(path);
  ASSERT_EQ(t.size(), 2u);
  EXPECT_EQ(t[0].t, 1403715524907143168.0 / 1e9);  // evo: ns as double, divided by 1e9
  EXPECT_NEAR(t[1].t - t[0].t, 0.005, 1e-6);
  EXPECT_TRUE(t[0].T_world_body.translation().isApprox(Eigen::Vector3d(0.5, 2.0, 0.97)));
  // q = (w, x, y, z) = (0, 1, 0, 0): half turn about x.
  const Eigen::Matrix3d half_turn_x = Eigen::Vector3d(1, -1, -1).asDiagonal();
  EXPECT_NEAR((t[0].T_world_body.linear() - half_turn_x).norm(), 0.0, 1e-15);
  EXPECT_NEAR((t[1].T_world_body.linear() - Eigen::Matrix3d::Identity()).norm(), 0.0, 1e-15);

  const std::string bad = writeFile("bad.csv", "#t\n1,2,3,4,5,6,7,8\n1,2,3,4,5,6,7\n");
  const std::string msg = errorOf([&] { core::readEurocCsv(bad); });
  EXPECT_NE(msg.find(bad + ":3:"), std::string::npos) << msg;
}

TEST_F(TrajectoryFile, MissingOrEmptyFileIsNamed) {
  const std::string missing = dir_ + "/does_not_exist.txt";
  for (auto format : {core::TrajectoryFormat::Tum, core::TrajectoryFormat::Kitti,
                      core::TrajectoryFormat::Euroc}) {
    const std::string msg = errorOf([&] { core::readTrajectory(missing, format); });
    EXPECT_NE(msg.find(missing), std::string::npos) << msg;
  }
  const std::string empty = writeFile("empty.tum", "# only a comment\n\n");
  const std::string msg = errorOf([&] { core::readTum(empty); });
  EXPECT_NE(msg.find(empty), std::string::npos) << msg;
  EXPECT_NE(msg.find("no poses"), std::string::npos) << msg;
}

TEST_F(TrajectoryFile, WriteTumRoundTripsAtFullPrecision) {
  core::Trajectory t(2);
  t[0].t = 1305031102.1604071;
  t[0].T_world_body.translation() = Eigen::Vector3d(1.0 / 3.0, -2.5e-7, 1e5 + 0.1);
  // A rotation whose quaternion has w < 0 as Eigen extracts it would be written with w >= 0.
  t[1].t = 1305031102.2;
  t[1].T_world_body.linear() =
      Eigen::AngleAxisd(3.0, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  const std::string path = dir_ + "/out.tum";
  core::writeTum(path, t);
  const core::Trajectory back = core::readTum(path);
  ASSERT_EQ(back.size(), 2u);
  EXPECT_EQ(back[0].t, t[0].t);
  EXPECT_EQ(back[0].T_world_body.translation(), t[0].T_world_body.translation());
  EXPECT_NEAR((back[1].T_world_body.linear() - t[1].T_world_body.linear()).norm(), 0.0, 1e-15);

  std::ostringstream line;
  core::appendTumLine(line, t[1]);
  std::istringstream fields(line.str());
  double v[8];
  for (double& x : v) fields >> x;
  EXPECT_GE(v[7], 0.0);  // qw
  EXPECT_NEAR(std::sqrt(v[4] * v[4] + v[5] * v[5] + v[6] * v[6] + v[7] * v[7]), 1.0, 1e-15);

  EXPECT_THROW(core::writeTum(dir_ + "/no/such/dir/x.tum", t), core::TrajectoryFileError);
}

TEST_F(TrajectoryFile, ParsesFormatNames) {
  EXPECT_EQ(core::parseTrajectoryFormat("tum"), core::TrajectoryFormat::Tum);
  EXPECT_EQ(core::parseTrajectoryFormat("kitti"), core::TrajectoryFormat::Kitti);
  EXPECT_EQ(core::parseTrajectoryFormat("euroc"), core::TrajectoryFormat::Euroc);
  EXPECT_THROW(core::parseTrajectoryFormat("TUM "), std::invalid_argument);
}
