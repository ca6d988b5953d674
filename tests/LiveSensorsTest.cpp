// dynslam --sensors: MRPT hwdrivers sensors on threads of their own, without hardware through
// our rawlog replay driver (CRawlogReplaySensor, at the recorded rate).
#include "runner/LiveSensors.h"

#include <dynslam/io/RawlogSource.h>
#include <dynslam/testing/SyntheticObservations.h>
#include <dynslam/testing/SyntheticRoom.h>
#include <dynslam/testing/TestEnv.h>

#include <gtest/gtest.h>

#include <mrpt/obs/CObservation.h>

#include <chrono>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

namespace {

using dynslam::testing::binDir;
using dynslam::testing::readTextFile;
using dynslam::testing::runCommand;
using dynslam::testing::sourceDir;
using dynslam::testing::writeTextFile;

const char* kOdometry = "[pipeline]\nstages = RgbdOdometry\n[RgbdOdometry]\nmax_depth = 6\n";

// A queue that holds the whole 2 s sequence: these tests compare a live run with the playback,
// which holds only when no observation is dropped however far an instrumented (sanitizer)
// build's stages fall behind the replay (LiveSensors.AFullQueueKeepsTheNewest... tests dropping).
constexpr const char* kKeepEverything = "[global]\nmax_queued_observations = 100000\n";

std::string replayIni(const std::string& path, const std::string& rawlog) {
  return writeTextFile(path, std::string(kKeepEverything) +
                                 "[REPLAY]\ndriver = CRawlogReplaySensor\nrawlog = " + rawlog +
                                 "\nprocess_rate = 500\nsensorLabel = REPLAY\n");
}

TEST(LiveSensors, ReplayedLiveGivesThePlaybackTrajectoryAndRecordsWhatCame) {
  const std::string dir = dynslam::testing::scratchDir(), sim = dir + "/sim";
  const auto render = runCommand(binDir() + "/dynslam-sim --config " + sourceDir() +
                                 "/params/sim/indoor_people_high.ini --out " + sim +
                                 " --set Scenario.duration=2 --quiet");
  ASSERT_EQ(render.exit_code, 0) << render.output;
  const std::string run = binDir() + "/dynslam --config " + sourceDir() +
                          "/params/sim_vio.ini --no-map --quiet --set Detection.objects=" + sim +
                          "/objects.txt --set Estimator.max_solver_time=100 ";
  const auto live =
      runCommand(run + "--sensors " + replayIni(dir + "/sensors.ini", sim + "/sim.rawlog") +
                 " --record " + dir + "/rec.rawlog --out " + dir + "/live");
  ASSERT_EQ(live.exit_code, 0) << live.output;
  const auto playback = runCommand(run + "--rawlog " + sim + "/sim.rawlog --out " + dir + "/play");
  ASSERT_EQ(playback.exit_code, 0) << playback.output;
  const std::string expected = readTextFile(dir + "/play/trajectory.tum");
  EXPECT_GT(expected.size(), 1000u);
  EXPECT_EQ(readTextFile(dir + "/live/trajectory.tum"), expected) << "live replay = playback";
  const auto recorded = runCommand(run + "--rawlog " + dir + "/rec.rawlog --out " + dir + "/rec");
  ASSERT_EQ(recorded.exit_code, 0) << recorded.output;
  EXPECT_EQ(readTextFile(dir + "/rec/trajectory.tum"), expected) << "--record's rawlog plays back";
}

TEST(LiveSensors, ACameraAndAnImuOnThreadsOfTheirOwnAreMergedInTimeOrder) {
  namespace fs = std::filesystem;
  const std::string dir = dynslam::testing::scratchDir(), sim = dir + "/sim";
  const auto render = runCommand(binDir() + "/dynslam-sim --config " + sourceDir() +
                                 "/params/sim/indoor_people_high.ini --out " + sim +
                                 " --set Scenario.duration=2 --quiet");
  ASSERT_EQ(render.exit_code, 0) << render.output;
  // The rawlog split into a camera's and an IMU's, each replayed by a sensor of its own.
  std::vector<mrpt::serialization::CSerializable::Ptr> camera, imu;
  dynslam::io::RawlogSource source(sim + "/sim.rawlog");
  while (auto o = source.next()) (o->sensorLabel == "IMU" ? imu : camera).push_back(o);
  ASSERT_FALSE(imu.empty());
  dynslam::testing::writeRawlog(dir + "/camera.rawlog", camera);
  dynslam::testing::writeRawlog(dir + "/imu.rawlog", imu);
  fs::create_directory_symlink(sim + "/sim_Images", dir + "/camera_Images");
  const auto sensors =
      // A hold of 0.5 s: instrumented builds (the thread sanitizer) deliver up to 0.15 s late.
      writeTextFile(
          dir + "/two.ini",
          std::string(kKeepEverything) +
              "merge_hold_s = 0.5\n[CAMERA]\ndriver = CRawlogReplaySensor\nrawlog = " + dir +
              "/camera.rawlog\nprocess_rate = 500\n[IMU]\ndriver = "
              "CRawlogReplaySensor\nrawlog = " +
              dir + "/imu.rawlog\nprocess_rate = 500\n");
  const std::string run = binDir() + "/dynslam --config " + sourceDir() +
                          "/params/sim_vio.ini --no-map --quiet --set Detection.objects=" + sim +
                          "/objects.txt --set Estimator.max_solver_time=100 ";
  const auto live = runCommand(run + "--sensors " + sensors + " --out " + dir + "/live");
  ASSERT_EQ(live.exit_code, 0) << live.output;
  const auto playback = runCommand(run + "--rawlog " + sim + "/sim.rawlog --out " + dir + "/play");
  ASSERT_EQ(playback.exit_code, 0) << playback.output;
  EXPECT_EQ(readTextFile(dir + "/live/trajectory.tum"), readTextFile(dir + "/play/trajectory.tum"));
}

TEST(LiveSensors, ABadSensorIsAnErrorNamingItsSectionAndOutputsAreKept) {
  const std::string dir = dynslam::testing::scratchDir();
  const std::string run = binDir() + "/dynslam --config " +
                          writeTextFile(dir + "/odo.ini", kOdometry) + " --no-map --quiet --out " +
                          dir + "/out --sensors ";
  auto r = runCommand(run + writeTextFile(dir + "/a.ini",
                                          "[CAM]\ndriver = CNoSuchSensor\n"
                                          "process_rate = 30\n"));
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("[CAM] of " + dir + "/a.ini: unknown driver 'CNoSuchSensor'"),
            std::string::npos)
      << r.output;
  EXPECT_NE(readTextFile(dir + "/out/summary.json").find("\"failed\""), std::string::npos);

  r = runCommand(run + replayIni(dir + "/b.ini", dir + "/missing.rawlog"));
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("[REPLAY] of " + dir +
                          "/b.ini: sensor 'CRawlogReplaySensor' failed to "
                          "start"),
            std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("missing.rawlog"), std::string::npos) << r.output;
}

TEST(LiveSensors, ASensorThatStopsDeliveringEndsTheRunAfterTheTimeoutWithWhatCameBefore) {
  const std::string dir = dynslam::testing::scratchDir();
  const auto path = dynslam::testing::handheldPath(4);
  std::vector<mrpt::serialization::CSerializable::Ptr> objs;
  for (int i = 0; i < 4; ++i)  // the fourth frame comes 60 s after the third
    objs.push_back(dynslam::testing::makeRoomScan(i < 3 ? 10.0 + i / 30.0 : 70.0, path[i],
                                                  dynslam::testing::vgaCamera()));
  dynslam::testing::writeRawlog(dir + "/gap.rawlog", objs);
  const auto ini = writeTextFile(
      dir + "/odo.ini", "[pipeline]\nstages = RgbdOdometry\n[RgbdOdometry]\nmax_depth = 6\n");
  const auto r = runCommand(binDir() + "/dynslam --config " + ini + " --no-map --quiet --out " +
                            dir + "/out --sensor-timeout 1 --sensors " +
                            replayIni(dir + "/s.ini", dir + "/gap.rawlog"));
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("no observation from the sensors of " + dir + "/s.ini for 1 s"),
            std::string::npos)
      << r.output;
  const std::string trajectory = readTextFile(dir + "/out/trajectory.tum");
  EXPECT_GE(std::count(trajectory.begin(), trajectory.end(), '\n'), 2) << "the frames before";
}

TEST(LiveSensors, AFullQueueKeepsTheNewestObservationsAndCountsTheDropped) {
  const std::string dir = dynslam::testing::scratchDir();
  const auto path = dynslam::testing::handheldPath(10);
  std::vector<mrpt::serialization::CSerializable::Ptr> objs;
  for (int i = 0; i < 10; ++i)
    objs.push_back(
        dynslam::testing::makeRoomScan(10.0 + i / 30.0, path[i], dynslam::testing::vgaCamera()));
  dynslam::testing::writeRawlog(dir + "/ten.rawlog", objs);
  const auto ini = writeTextFile(dir + "/s.ini",
                                 "[global]\nmax_queued_observations = 3\n[REPLAY]\n"
                                 "driver = CRawlogReplaySensor\nrawlog = " +
                                     dir + "/ten.rawlog\nprocess_rate = 500\n");
  dynslam::runner::LiveSensors sensors(ini);
  // Nobody takes observations while the replay (0.3 s at the recorded rate) delivers all ten.
  std::this_thread::sleep_for(std::chrono::milliseconds(1500));
  std::vector<double> stamps;
  std::shared_ptr<mrpt::obs::CObservation> o;
  while (sensors.next(1.0, o) == dynslam::runner::LiveSensors::Wait::Observation)
    stamps.push_back(mrpt::Clock::toDouble(o->timestamp));
  ASSERT_EQ(stamps.size(), 3u);
  EXPECT_EQ(sensors.dropped(), 7u);
  EXPECT_NEAR(stamps.front(), 10.0 + 7 / 30.0, 1e-6) << "the newest three, in time order";
  EXPECT_NEAR(stamps.back(), 10.0 + 9 / 30.0, 1e-6);
}

TEST(LiveSensors, BadGlobalSettingsNameTheKeyAndTheFile) {
  const std::string dir = dynslam::testing::scratchDir();
  const auto make = [&](const std::string& global) {
    return writeTextFile(dir + "/g.ini", "[global]\n" + global +
                                             "\n[REPLAY]\ndriver = "
                                             "CRawlogReplaySensor\nrawlog = missing.rawlog\n");
  };
  const auto error = [](const std::string& ini) {
    try {
      dynslam::runner::LiveSensors sensors(ini);
    } catch (const std::exception& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  std::string e = error(make("max_queued_observations = 0"));
  EXPECT_NE(
      e.find("[global] in " + dir + "/g.ini: max_queued_observations = 0: must be in [1, 1000000]"),
      std::string::npos)
      << e;
  e = error(make("merge_hold = 0.2"));
  EXPECT_NE(e.find("unknown key 'merge_hold' in section [global] of " + dir + "/g.ini"),
            std::string::npos)
      << e;
}

}  // namespace
