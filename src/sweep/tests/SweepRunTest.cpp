// dynslam-sweep end to end on a one-second simulated rawlog (issue 7: 2 keys x 2 values give 4
// rows, and a second run does no work).
#include "sweep/SummaryJson.h"

#include <dynslam/testing/TestEnv.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <sstream>

namespace fs = std::filesystem;
using dynslam::testing::binDir;
using dynslam::testing::readTextFile;
using dynslam::testing::runCommand;

namespace {

const char* kGrid = "RgbdOdometry.min_depth=0.3,0.5;RgbdOdometry.max_depth=3,4";

/// A one-second static-room rawlog at 320x240 (31 frames), rendered once for all tests here.
const std::string& tinyRawlogDir() {
  static const std::string dir = [] {
    const std::string d = dynslam::testing::scratchDir("tiny_rawlog");
    const auto r = runCommand(binDir() + "/dynslam-sim --config " + dynslam::testing::sourceDir() +
                              "/params/sim/static.ini --out " + d +
                              " --set Scenario.duration=1 --set Scenario.width=320"
                              " --set Scenario.height=240 --quiet");
    EXPECT_EQ(r.exit_code, 0) << r.output;
    return d;
  }();
  return dir;
}

std::string sweepCommand(const std::string& out, const std::string& grid = kGrid,
                         const std::string& extra = "") {
  const std::string sim = tinyRawlogDir();
  return binDir() + "/dynslam-sweep --config " + dynslam::testing::sourceDir() +
         "/params/7scenes_rgbd_odometry.ini --grid '" + grid + "' --rawlog " + sim +
         "/sim.rawlog --gt " + sim + "/groundtruth.tum --jobs 2 --out " + out + " " + extra;
}

std::vector<std::vector<std::string>> csvRows(const std::string& path) {
  std::vector<std::vector<std::string>> rows;
  std::istringstream in(readTextFile(path));
  for (std::string line; std::getline(in, line);) {
    std::vector<std::string> fields;
    std::istringstream l(line);
    for (std::string f; std::getline(l, f, ',');) fields.push_back(f);
    rows.push_back(fields);
  }
  return rows;
}

std::map<std::string, fs::file_time_type> summaryTimes(const std::string& out) {
  std::map<std::string, fs::file_time_type> times;
  for (const auto& entry : fs::directory_iterator(out + "/jobs"))
    times[entry.path().filename().string()] = fs::last_write_time(entry.path() / "summary.json");
  return times;
}

}  // namespace

TEST(DynslamSweep, TwoKeysTwoValuesGiveFourRowsAndASecondRunDoesNothing) {
  const std::string out = dynslam::testing::scratchDir("sweep");
  const auto first = runCommand(sweepCommand(out));
  ASSERT_EQ(first.exit_code, 0) << first.output;
  EXPECT_NE(first.output.find("ran 4, skipped 0"), std::string::npos) << first.output;

  const auto rows = csvRows(out + "/results.csv");
  ASSERT_EQ(rows.size(), 5u) << "header + one row per job";
  const auto& header = rows[0];
  const auto col = [&](const std::string& name) {
    return static_cast<size_t>(std::find(header.begin(), header.end(), name) - header.begin());
  };
  for (const char* name :
       {"RgbdOdometry.min_depth", "RgbdOdometry.max_depth", "rawlog", "status", "ape_rmse",
        "ape_mean", "ape_median", "ape_std", "rpe_rmse", "rpe_mean", "fps", "reason"})
    ASSERT_LT(col(name), header.size()) << name;
  std::set<std::pair<std::string, std::string>> combos;
  for (size_t i = 1; i < rows.size(); ++i) {
    const auto& r = rows[i];
    ASSERT_GE(r.size(), col("fps") + 1);
    EXPECT_EQ(r[col("status")], "ok");
    combos.insert({r[col("RgbdOdometry.min_depth")], r[col("RgbdOdometry.max_depth")]});
    const double ape = std::stod(r[col("ape_rmse")]);
    EXPECT_GT(ape, 0.0);
    EXPECT_LT(ape, 1.0) << "the odometry of one second of a static room stays within a metre";
    EXPECT_GE(std::stod(r[col("ape_rmse")]), std::stod(r[col("ape_mean")]));
    EXPECT_GT(std::stod(r[col("rpe_rmse")]), 0.0);
    EXPECT_GT(std::stod(r[col("fps")]), 0.0);
  }
  EXPECT_EQ(combos.size(), 4u) << "every combination once";
  for (const char* key : {"RgbdOdometry.min_depth", "RgbdOdometry.max_depth"})
    EXPECT_GT(fs::file_size(out + "/plot_" + key + ".png"), 1000u) << key;

  // Second run: every job is complete, so nothing runs and no job file changes.
  const auto before = summaryTimes(out);
  ASSERT_EQ(before.size(), 4u);
  const auto second = runCommand(sweepCommand(out));
  ASSERT_EQ(second.exit_code, 0) << second.output;
  EXPECT_NE(second.output.find("ran 0, skipped 4"), std::string::npos) << second.output;
  EXPECT_EQ(summaryTimes(out), before);
  EXPECT_EQ(csvRows(out + "/results.csv").size(), 5u);

  // A job whose summary is missing (killed) or says failed is run again, and only that one.
  const std::string victim = out + "/jobs/" + before.begin()->first + "/summary.json";
  dynslam::testing::writeTextFile(victim, "{\"status\": \"interrupted\"}");
  const auto third = runCommand(sweepCommand(out));
  ASSERT_EQ(third.exit_code, 0) << third.output;
  EXPECT_NE(third.output.find("ran 1, skipped 3"), std::string::npos) << third.output;
  EXPECT_TRUE(dynslam::sweep::jobCompleted(fs::path(victim).parent_path().string()));
}

TEST(DynslamSweep, BadInputStopsWithAClearMessage) {
  const std::string out = dynslam::testing::scratchDir("bad");
  auto r = runCommand(sweepCommand(out, "RgbdOdometry.min_depth=0.3;RgbdOdometry.max_depth"));
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("--grid part 'RgbdOdometry.max_depth'"), std::string::npos) << r.output;

  r = runCommand(sweepCommand(out, "RgbdOdometry.min_depht=0.3,0.5"));
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("unknown key 'min_depht' in section [RgbdOdometry]"), std::string::npos)
      << r.output;
  EXPECT_FALSE(fs::exists(out + "/jobs")) << "no job ran after the check failed";

  r = runCommand(binDir() + "/dynslam-sweep --config " + dynslam::testing::sourceDir() +
                 "/params/7scenes_rgbd_odometry.ini --grid 'RgbdOdometry.min_depth=0.3' --rawlog " +
                 out + "/absent.rawlog --out " + out);
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("--rawlog '" + out + "/absent.rawlog' does not exist"), std::string::npos)
      << r.output;
}

TEST(DynslamSweep, AFailingJobIsARowWithItsReasonAndRunsAgainNextTime) {
  const std::string out = dynslam::testing::scratchDir("failing");
  const std::string grid = "RgbdOdometry.method=rgbd_icp,no_such_method";
  auto r = runCommand(sweepCommand(out, grid));
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("FAILED sim__RgbdOdometry.method=no_such_method"), std::string::npos)
      << r.output;
  const auto rows = csvRows(out + "/results.csv");
  ASSERT_EQ(rows.size(), 3u);
  const std::string csv = readTextFile(out + "/results.csv");
  EXPECT_NE(csv.find(",failed,"), std::string::npos) << csv;
  EXPECT_NE(csv.find("no_such_method"), std::string::npos) << csv;
  r = runCommand(sweepCommand(out, grid));
  EXPECT_NE(r.output.find("ran 1, skipped 1"), std::string::npos) << r.output;
}

TEST(DynslamSweep, EmittedJobListRunsElsewhereAndIsCollectedLater) {
  const std::string out = dynslam::testing::scratchDir("emit");
  auto r = runCommand(sweepCommand(out, kGrid, "--emit slurm"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_FALSE(fs::exists(out + "/jobs")) << "--emit runs nothing";
  const std::string list = readTextFile(out + "/jobs.txt");
  EXPECT_EQ(std::count(list.begin(), list.end(), '\n'), 4);
  EXPECT_NE(readTextFile(out + "/sweep.slurm").find("#SBATCH --array=0-3%2"), std::string::npos);

  // What one array task (or one GNU parallel slot) does: its line, through a shell.
  const std::string line2 =
      list.substr(list.find('\n') + 1, list.find('\n', list.find('\n') + 1) - list.find('\n') - 1);
  dynslam::testing::writeTextFile(out + "/task.sh", line2 + "\n");
  r = runCommand("sh " + out + "/task.sh");
  ASSERT_EQ(r.exit_code, 0) << r.output;

  r = runCommand(sweepCommand(out, kGrid, "--collect"));
  EXPECT_EQ(r.exit_code, 1) << "three jobs have not run: " << r.output;
  const auto rows = csvRows(out + "/results.csv");
  ASSERT_EQ(rows.size(), 5u);
  int ok = 0;
  for (size_t i = 1; i < rows.size(); ++i) ok += std::count(rows[i].begin(), rows[i].end(), "ok");
  EXPECT_EQ(ok, 1);
  EXPECT_NE(readTextFile(out + "/results.csv").find("not run yet"), std::string::npos);
}
