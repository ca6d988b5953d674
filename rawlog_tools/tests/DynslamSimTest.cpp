// dynslam-sim end to end: what it writes, that MRPT's tools and our pipeline read it, and that
// the same ini gives the same bytes.
#include "RawlogTestSupport.h"

#include <dynslam/core/TrajectoryFile.h>
#include <dynslam/testing/TestEnv.h>

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

namespace fs = std::filesystem;
using dynslam::rawlog_tools::testing::program;
using dynslam::rawlog_tools::testing::rawlogEditInfo;
using dynslam::rawlog_tools::testing::shellQuoted;
using dynslam::testing::readTextFile;
using dynslam::testing::runCommand;

namespace {

/// One second of indoor_people_high: 31 frames, 201 IMU samples.
std::string simulate(const std::string& out, const std::string& extra = "") {
  const std::string ini = dynslam::testing::sourceDir() + "/params/sim/indoor_people_high.ini";
  const auto r = runCommand(program("dynslam-sim") + " --config " + shellQuoted(ini) + " --out " +
                            shellQuoted(out) + " --set Scenario.duration=1 --quiet " + extra);
  EXPECT_EQ(r.exit_code, 0) << r.output;
  return r.output;
}

size_t countLines(const std::string& text, bool skipComments) {
  std::istringstream in(text);
  size_t n = 0;
  for (std::string line; std::getline(in, line);) n += !line.empty() && !(skipComments && line[0] == '#');
  return n;
}

}  // namespace

TEST(DynslamSim, WritesRawlogGroundTruthLabelsAndContactSheet) {
  const std::string out = dynslam::testing::scratchDir("run");
  simulate(out, "--contact-sheet " + shellQuoted(out + "/sheet.png"));

  const auto info = rawlogEditInfo(out + "/sim.rawlog");
  if (info.available) {
    EXPECT_TRUE(std::regex_search(info.output, std::regex(R"(RGBD\s*/\s*31\s*/)"))) << info.output;
    EXPECT_TRUE(std::regex_search(info.output, std::regex(R"(IMU\s*/\s*201\s*/)"))) << info.output;
  }
  EXPECT_EQ(dynslam::core::readTum(out + "/groundtruth.tum").size(), 31u);
  size_t labels = 0;
  for (const auto& e : fs::directory_iterator(out + "/labels")) {
    const cv::Mat l = cv::imread(e.path().string(), cv::IMREAD_UNCHANGED);
    ASSERT_EQ(l.type(), CV_16UC1) << e.path();
    ++labels;
  }
  EXPECT_EQ(labels, 31u);
  const std::string objects = readTextFile(out + "/objects.txt");
  EXPECT_GT(countLines(objects, true), 31u) << "several people in view per frame";
  std::istringstream first(objects.substr(objects.find("\n0 ")));
  std::vector<std::string> fields;
  for (std::string f; first >> f && fields.size() < 18;) fields.push_back(f);
  EXPECT_EQ(fields.size(), 18u);
  EXPECT_EQ(countLines(readTextFile(out + "/imu_biases.txt"), true), 201u);
  const cv::Mat sheet = cv::imread(out + "/sheet.png");
  EXPECT_EQ(sheet.cols, 3 * 320);
  EXPECT_EQ(sheet.rows, 4 * 240);
}

TEST(DynslamSim, SameIniSameBytes) {
  const std::string a = dynslam::testing::scratchDir("a"), b = dynslam::testing::scratchDir("b");
  simulate(a);
  simulate(b);
  size_t compared = 0;
  for (const auto& e : fs::recursive_directory_iterator(a)) {
    if (!e.is_regular_file()) continue;
    const fs::path rel = fs::relative(e.path(), a);
    ASSERT_TRUE(fs::exists(fs::path(b) / rel)) << rel;
    EXPECT_EQ(readTextFile(e.path().string()), readTextFile((fs::path(b) / rel).string())) << rel;
    ++compared;
  }
  EXPECT_GT(compared, 60u) << "rawlog, ground truth, 31 labels, 31 colour images";
}

TEST(DynslamSim, PipelineReadsTheSimulatedRawlog) {
  const std::string out = dynslam::testing::scratchDir("run");
  simulate(out);
  const std::string ini = dynslam::testing::writeTextFile(out + "/none.ini", "[pipeline]\nstages =\n");
  const auto r = runCommand(dynslam::testing::binDir() + "/dynslam --quiet --config " + ini +
                            " --rawlog " + out + "/sim.rawlog --out " + out + "/slam");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const std::string summary = readTextFile(out + "/slam/summary.json");
  EXPECT_NE(summary.find("\"frames\": 31"), std::string::npos) << summary;
  EXPECT_NE(summary.find("\"imu_samples\": 201"), std::string::npos) << summary;
}

TEST(DynslamSim, UnknownKeyIsAnErrorNamingIt) {
  const std::string out = dynslam::testing::scratchDir("run");
  const std::string ini = dynslam::testing::sourceDir() + "/params/sim/static.ini";
  const auto r = runCommand(program("dynslam-sim") + " --config " + shellQuoted(ini) + " --out " +
                            shellQuoted(out) + " --set People.walkerz=2");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.output.find("unknown key 'walkerz' in section [People]"), std::string::npos)
      << r.output;
}
