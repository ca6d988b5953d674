// euroc_imu2rawlog on ../shared/data/euroc_v102_imu (counts, first/last values, exact stamps,
// ground truth) and on corrupted csv files written by the test.
#include "RawlogTestSupport.h"

#include <dynslam/testing/TestEnv.h>
#include <gtest/gtest.h>
#include <mrpt/obs/CObservationIMU.h>

#include <Eigen/Geometry>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

namespace fs = std::filesystem;
using dynslam::rawlog_tools::testing::forEachObservation;
using dynslam::rawlog_tools::testing::program;
using dynslam::rawlog_tools::testing::rawlogEditInfo;
using dynslam::rawlog_tools::testing::shellQuoted;
using dynslam::testing::runCommand;
using namespace mrpt::obs;

namespace {

std::vector<std::vector<std::string>> csvDataLines(const std::string& file) {
  std::vector<std::vector<std::string>> rows;
  std::ifstream in(file);
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    std::vector<std::string> fields;
    std::istringstream s(line);
    for (std::string f; std::getline(s, f, ',');) fields.push_back(f);
    rows.push_back(fields);
  }
  return rows;
}

// MRPT ticks (100 ns since 1601) of a nanosecond Unix stamp.
int64_t mrptTicks(const std::string& ns) {
  return std::stoll(ns) / 100 + INT64_C(116444736000000000);
}

}  // namespace

TEST(RawlogToolsEuroc, ConvertsEveryLineWithGyroAndAccAndExactStamps) {
  DYNSLAM_REQUIRE_SHARED(dataDir, "data/euroc_v102_imu");
  const auto rows = csvDataLines(dataDir + "/imu.csv");
  ASSERT_EQ(rows.size(), 7999u);  // data lines of the shared file (8000 lines with header)
  const std::string rawlog = dynslam::testing::scratchDir() + "/v102.rawlog";
  const auto r = runCommand(
      program("euroc_imu2rawlog") + " --imu " + shellQuoted(dataDir + "/imu.csv") + " --gt " +
      shellQuoted(dataDir + "/groundtruth.csv") + " --out " + shellQuoted(rawlog));
  ASSERT_EQ(r.exit_code, 0) << r.output;

  size_t index = 0;
  auto expectSample = [&](const CObservationIMU& imu, const std::vector<std::string>& row) {
    EXPECT_EQ(imu.timestamp.time_since_epoch().count(), mrptTicks(row[0])) << "line " << index;
    const TIMUDataIndex fields[] = {IMU_WX, IMU_WY, IMU_WZ, IMU_X_ACC, IMU_Y_ACC, IMU_Z_ACC};
    for (size_t i = 0; i < 6; ++i) {
      EXPECT_TRUE(imu.has(fields[i]));
      EXPECT_DOUBLE_EQ(imu.get(fields[i]), std::stod(row[1 + i])) << "sample " << index;
    }
  };
  forEachObservation(rawlog, [&](const CObservation::Ptr& o) {
    const auto imu = std::dynamic_pointer_cast<CObservationIMU>(o);
    ASSERT_TRUE(imu);
    EXPECT_EQ(imu->sensorLabel, "IMU");
    if (index == 0 || index + 1 == rows.size()) expectSample(*imu, rows.at(index));
    ++index;
  });
  EXPECT_EQ(index, rows.size());
  // Spot values straight from the file, so a parsing slip in the test cannot hide one in the tool.
  EXPECT_EQ(rows.front()[0], "1403715523912140000");
  EXPECT_EQ(rows.back()[6], "-4.75622525");

  const auto info = rawlogEditInfo(rawlog);
  if (info.available) {
    std::smatch m;
    ASSERT_TRUE(std::regex_search(info.output, m, std::regex(R"(IMU\s*/\s*(\d+))"))) << info.output;
    EXPECT_EQ(std::stoul(m[1].str()), rows.size());
  }
}

TEST(RawlogToolsEuroc, WritesBodyGroundTruthAsTumWithWxyzQuaternionReordered) {
  DYNSLAM_REQUIRE_SHARED(dataDir, "data/euroc_v102_imu");
  const auto gtRows = csvDataLines(dataDir + "/groundtruth.csv");
  const std::string rawlog = dynslam::testing::scratchDir() + "/v102.rawlog";
  ASSERT_EQ(runCommand(program("euroc_imu2rawlog") + " --imu " + shellQuoted(dataDir + "/imu.csv") +
                       " --gt " + shellQuoted(dataDir + "/groundtruth.csv") + " --out " +
                       shellQuoted(rawlog))
                .exit_code,
            0);
  std::ifstream in(fs::path(rawlog).replace_extension(".gt.tum"));
  ASSERT_TRUE(in);
  std::vector<std::array<double, 8>> poses;
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream s(line);
    std::array<double, 8> v{};
    for (double& x : v) ASSERT_TRUE(s >> x) << line;
    poses.push_back(v);
  }
  ASSERT_EQ(poses.size(), gtRows.size());
  ASSERT_EQ(poses.size(), 3340u);
  for (const size_t i : {size_t{0}, poses.size() - 1}) {
    const auto& row = gtRows[i];
    const auto& p = poses[i];
    EXPECT_NEAR(p[0], std::stoll(row[0]) * 1e-9, 1e-6);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(p[1 + k], std::stod(row[1 + k]), 1e-9);
    // csv: qw qx qy qz (columns 4..7); TUM: qx qy qz qw. Same rotation up to sign.
    const Eigen::Quaterniond expected(std::stod(row[4]), std::stod(row[5]), std::stod(row[6]),
                                      std::stod(row[7]));
    const Eigen::Quaterniond written(p[7], p[4], p[5], p[6]);
    EXPECT_NEAR(std::abs(expected.normalized().dot(written.normalized())), 1.0, 1e-9)
        << "pose " << i;
  }
  EXPECT_NEAR(poses[0][0], 1403715524.92214, 1e-6);
  EXPECT_NEAR(poses[0][5],
              -0.205215 / Eigen::Vector4d(0.161869, 0.790012, -0.205215, 0.554587).norm(), 1e-6);
}

class RawlogToolsEurocCorruptCsv : public ::testing::Test {
 protected:
  // Lines: 1 header, 2..5 data.
  dynslam::testing::CommandResult convertWithLine(int lineNumber, const std::string& line) {
    const std::string dir = dynslam::testing::scratchDir();
    std::vector<std::string> lines = {
        "#timestamp [ns],w_RS_S_x [rad s^-1],w_RS_S_y [rad s^-1],w_RS_S_z [rad s^-1],"
        "a_RS_S_x [m s^-2],a_RS_S_y [m s^-2],a_RS_S_z [m s^-2]",
        "1000000000,0.1,0.2,0.3,9.7,0.1,0.2", "1005000000,0.1,0.2,0.3,9.7,0.1,0.2",
        "1010000000,0.1,0.2,0.3,9.7,0.1,0.2", "1015000000,0.1,0.2,0.3,9.7,0.1,0.2"};
    if (lineNumber > 0) lines.at(size_t(lineNumber - 1)) = line;
    csv_ = dir + "/imu.csv";
    std::ofstream out(csv_);
    for (const auto& l : lines) out << l << "\n";
    out.close();
    rawlog_ = dir + "/bad.rawlog";
    return runCommand(program("euroc_imu2rawlog") + " --imu " + shellQuoted(csv_) + " --out " +
                      shellQuoted(rawlog_));
  }
  std::string csv_, rawlog_;
};

TEST_F(RawlogToolsEurocCorruptCsv, WellFormedFileConverts) {
  const auto r = convertWithLine(0, "");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(forEachObservation(rawlog_, [](const CObservation::Ptr&) {}), 4u);
}

TEST_F(RawlogToolsEurocCorruptCsv, NanNamesFileLineAndColumn) {
  const auto r = convertWithLine(4, "1010000000,0.1,nan,0.3,9.7,0.1,0.2");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find(csv_ + " line 4, column 3"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("not a finite number"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(rawlog_)) << "a failed conversion must not leave a rawlog";
}

TEST_F(RawlogToolsEurocCorruptCsv, TextNamesFileLineAndColumn) {
  const auto r = convertWithLine(3, "1005000000,0.1,0.2,0.3,9.7,abc,0.2");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find(csv_ + " line 3, column 6 (a_RS_S_y [m s^-2]): 'abc' is not a number"),
            std::string::npos)
      << r.output;
}

TEST_F(RawlogToolsEurocCorruptCsv, NonNumericTimestampNamesTheLine) {
  const auto r = convertWithLine(2, "10000000x0,0.1,0.2,0.3,9.7,0.1,0.2");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find("line 2, column 1"), std::string::npos) << r.output;
}

TEST_F(RawlogToolsEurocCorruptCsv, BackwardsTimeNamesTheLine) {
  const auto r = convertWithLine(5, "1001000000,0.1,0.2,0.3,9.7,0.1,0.2");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find(csv_ + " line 5: time stamp 1001000000 goes backwards"),
            std::string::npos)
      << r.output;
  EXPECT_FALSE(fs::exists(rawlog_));
}

TEST_F(RawlogToolsEurocCorruptCsv, MissingFieldNamesTheLine) {
  const auto r = convertWithLine(3, "1005000000,0.1,0.2,0.3,9.7,0.1");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find("line 3: expected 7 fields, found 6"), std::string::npos) << r.output;
}
