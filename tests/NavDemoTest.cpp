// dynslam-nav-demo (issue 54 items 2-3): the closed loop runs with the simulator's obstacles and
// with the SLAM system in the loop, writes what it promises, and names what is wrong in a bad
// scenario. The figures over seeds are bench/nav.sh's.
#include "nav_demo/StaticFootprint.h"

#include <dynslam/sim/Mesh.h>
#include <dynslam/testing/TestEnv.h>

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

namespace {

namespace fs = std::filesystem;
using dynslam::testing::binDir;
using dynslam::testing::readTextFile;
using dynslam::testing::runCommand;
using dynslam::testing::sourceDir;

double jsonNumber(const std::string& json, const std::string& key) {
  const auto at = json.find("\"" + key + "\": ");
  if (at == std::string::npos) return std::nan("");
  const std::string rest = json.substr(at + key.size() + 4);
  if (rest.rfind("true", 0) == 0) return 1;
  if (rest.rfind("false", 0) == 0) return 0;
  return std::stod(rest);
}

std::size_t lines(const std::string& path) {
  std::ifstream in(path);
  std::size_t n = 0;
  for (std::string line; std::getline(in, line);)
    if (!line.empty() && line[0] != '#') ++n;
  return n;
}

std::string demo(const std::string& out, const std::string& args) {
  return binDir() + "/dynslam-nav-demo --config " + sourceDir() +
         "/params/nav/room_people.ini --out " + out + " --no-video --quiet " + args;
}

TEST(NavDemo, WithTheSimulatorsObstaclesTheRobotCrossesTheRoom) {
  const std::string out = dynslam::testing::scratchDir();
  const auto run = runCommand(demo(out,
                                   "--obstacles ground_truth --set 'NavDemo.goals=2.0 0' "
                                   "--set NavDemo.goal_time_limit_s=30"));
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const std::string json = readTextFile(out + "/nav.json");
  EXPECT_EQ(jsonNumber(json, "goals_reached"), 1) << json;
  // Every contact counted is listed (the figures over seeds are the bench's, not a test's).
  EXPECT_EQ(lines(out + "/contacts.csv") - 1, jsonNumber(json, "collisions_people") +
                                                  jsonNumber(json, "contacts_people_robot_still") +
                                                  jsonNumber(json, "collisions_static") +
                                                  jsonNumber(json, "contacts_static_robot_still"))
      << json;
  EXPECT_LT(jsonNumber(json, "final_distance_m"), 0.3 + 0.35) << json;  // it stops within
  for (const char* file :
       {"trajectory_true.tum", "trajectory_estimated.tum", "people.csv", "contacts.csv", "top.png"})
    EXPECT_TRUE(fs::exists(out + "/" + file)) << file;
  EXPECT_GT(lines(out + "/trajectory_true.tum"), 100u);
  EXPECT_FALSE(fs::exists(out + "/top.avi"));  // --no-video
}

TEST(NavDemo, TheSlamSystemRunsInTheLoop) {
  const std::string out = dynslam::testing::scratchDir();
  const auto run = runCommand(demo(out,
                                   "--set 'NavDemo.goals=2.0 0' "
                                   "--set NavDemo.goal_time_limit_s=5"));
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const std::string json = readTextFile(out + "/nav.json");
  EXPECT_GT(jsonNumber(json, "frames"), 150) << json;
  // The SLAM system posed the robot in the loop, as closely as on a recorded sequence.
  EXPECT_GT(lines(out + "/trajectory_estimated.tum"), 100u);
  EXPECT_LT(jsonNumber(json, "position_error_rmse_m"), 0.05) << json;
  EXPECT_LT(jsonNumber(json, "adapter_pose_call_median_us"), 1000) << json;
}

TEST(NavDemo, ABadScenarioNamesWhatIsWrong) {
  const std::string out = dynslam::testing::scratchDir();
  struct Case {
    std::string args, named;
  };
  for (const auto& c :
       {Case{"--set NavDemo.goals=1", "goals"}, Case{"--set NavDemo.bogus=1", "bogus"},
        Case{"--obstacles both", "obstacles"}, Case{"--set NavDemo.start=0", "start"},
        Case{"--set Scenario.seeed=2", "seeed"}}) {
    const auto run = runCommand(demo(out, c.args));
    EXPECT_EQ(run.exit_code, 1) << c.args << "\n" << run.output;
    EXPECT_NE(run.output.find(c.named), std::string::npos) << c.args << "\n" << run.output;
  }
  const auto missing =
      runCommand(binDir() + "/dynslam-nav-demo --config /nonexistent/nav.ini --out " + out);
  EXPECT_EQ(missing.exit_code, 1);
  EXPECT_NE(missing.output.find("/nonexistent/nav.ini"), std::string::npos) << missing.output;
}

TEST(StaticFootprint, DistanceToAWallSeenFromAbove) {
  dynslam::sim::Mesh mesh;
  // A floor (left out: below the band) and a 2 m wall along y = 1.
  dynslam::sim::addQuad(mesh, {-2, -2, 0}, {4, 0, 0}, {0, 4, 0}, 0, 0);
  dynslam::sim::addQuad(mesh, {-2, 1, 0}, {4, 0, 0}, {0, 0, 2}, 0, 0);
  const dynslam::navdemo::StaticFootprint statics(mesh, 0.05, 2.0);
  EXPECT_NEAR(statics.distance({0, 0}), 1.0, 0.04);
  EXPECT_NEAR(statics.distance({0.5, -1.5}), 2.5, 0.04);
  EXPECT_LT(statics.distance({0, 1}), 0.03);
}

}  // namespace
