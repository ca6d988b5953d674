// With dynamic_handling = full and an IMU, the object factors (r_D, r_O, r_om) start once the
// IMU initialization succeeds ([Estimator] object_factors_wait_for_imu, default on; not in
// method.md): in the visual-only start-up window the objects' motion models pulled the camera
// (docs/notes/estimator.md, 2026-11-28 (object_factors_wait_for_imu)). keyframes.csv says, per
// keyframe, whether the window was visual-inertial and how many non-rigid features and rigid
// objects it held.
#include <dynslam/testing/TestEnv.h>

#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

using dynslam::testing::binDir;
using dynslam::testing::readTextFile;
using dynslam::testing::runCommand;
using dynslam::testing::sourceDir;

namespace {

struct KeyframeRow {
  int nonrigid = 0, rigid_objects = 0;
  bool visual_inertial = false;
};

std::vector<KeyframeRow> readKeyframes(const std::string& csv) {
  std::vector<KeyframeRow> rows;
  std::istringstream in(csv);
  std::string line;
  std::getline(in, line);  // header: frame,t_s,reason,static,shared,nonrigid,rigid_objects,...
  while (std::getline(in, line)) {
    std::vector<std::string> cells;
    std::istringstream fields(line);
    for (std::string cell; std::getline(fields, cell, ',');) cells.push_back(cell);
    if (cells.size() < 11) continue;
    rows.push_back({std::stoi(cells[5]), std::stoi(cells[6]), cells[10] == "1"});
  }
  return rows;
}

}  // namespace

TEST(ObjectFactorsWaitForImu, NoObjectFactorsBeforeTheImuIsInitialized) {
  const std::string dir = dynslam::testing::scratchDir();
  const std::string sim = dir + "/sim";
  const auto render = runCommand(binDir() + "/dynslam-sim --config " + sourceDir() +
                                 "/params/sim/indoor_people_low.ini --out " + sim +
                                 " --set Scenario.seed=2 --set Scenario.duration=3 --quiet");
  ASSERT_EQ(render.exit_code, 0) << render.output;
  const auto runFull = [&](const std::string& out, const std::string& wait) {
    return runCommand(binDir() + "/dynslam --config " + sourceDir() + "/params/sim_vio.ini" +
                      " --rawlog " + sim + "/sim.rawlog --out " + out +
                      " --set Detection.objects=" + sim + "/objects.txt --set Detection.seed=2" +
                      " --set Estimator.dynamic_handling=full" +
                      " --set Estimator.object_factors_wait_for_imu=" + wait + " --no-map --quiet");
  };
  for (const std::string wait : {"true", "false"}) {
    const std::string out = dir + "/out_" + wait;
    const auto run = runFull(out, wait);
    ASSERT_EQ(run.exit_code, 0) << run.output;
    const auto rows = readKeyframes(readTextFile(out + "/keyframes.csv"));
    int before = 0, objectsBefore = 0, objectsAfter = 0;
    for (const auto& r : rows) {
      (r.visual_inertial ? objectsAfter : objectsBefore) += r.nonrigid + r.rigid_objects;
      before += !r.visual_inertial;
    }
    ASSERT_GT(before, 3) << "the visual-only start-up spans keyframes";
    ASSERT_LT(before, int(rows.size())) << "the IMU initializes within 3 s";
    EXPECT_GT(objectsAfter, 0) << "full uses the object factors once visual-inertial";
    if (wait == "true")
      EXPECT_EQ(objectsBefore, 0) << "none while the window is visual-only";
    else
      EXPECT_GT(objectsBefore, 0) << "with the key off they start at once (people walk in view)";
  }
}
