// The `dynslam` program end to end: synthetic rawlogs written here, bad input of every kind,
// and (when ../shared is present) a real 7-Scenes conversion cut in half.
#include <dynslam/core/TrajectoryFile.h>
#include <dynslam/testing/SyntheticObservations.h>
#include <dynslam/testing/TestEnv.h>

#include <opencv2/imgcodecs.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <utility>

namespace fs = std::filesystem;
using dynslam::testing::binDir;
using dynslam::testing::readTextFile;
using dynslam::testing::runCommand;
using dynslam::testing::scratchDir;
using dynslam::testing::writeTextFile;

namespace {

const char* kOdometryIni = "[pipeline]\nstages = RgbdOdometry\n[RgbdOdometry]\nmax_depth = 6\n";

/// A 320 x 240 room sequence at 30 Hz with a 200 Hz IMU between the frames.
std::string writeRoomRawlog(const std::string& path, int frames,
                            std::vector<double>* stamps = nullptr) {
  auto k = dynslam::testing::vgaCamera();
  k.width = 320;
  k.height = 240;
  k.fx = k.fy = 262.5;
  k.cx = 159.5;
  k.cy = 119.5;
  const auto path_ = dynslam::testing::handheldPath(frames);
  std::vector<mrpt::serialization::CSerializable::Ptr> objs;
  for (int i = 0; i < frames; ++i) {
    const double t = 100.0 + i / 30.0;
    for (int j = 1; j <= 6; ++j)
      objs.push_back(dynslam::testing::makeImu(t - 1 / 30.0 + j / 200.0));
    objs.push_back(dynslam::testing::makeRoomScan(t, path_[i], k));
    if (stamps) stamps->push_back(t);
  }
  dynslam::testing::writeRawlog(path, objs);
  return path;
}

std::string dynslamCommand(const std::string& args) {
  return binDir() + "/dynslam " + args + " --quiet";
}

size_t lineCount(const std::string& path) {
  std::ifstream in(path);
  size_t n = 0;
  for (std::string line; std::getline(in, line);) n += !line.empty();
  return n;
}

}  // namespace

TEST(Runner, PlaysASyntheticRoomAndWritesTrajectoryAndSummary) {
  const std::string dir = scratchDir();
  std::vector<double> stamps;
  const auto rawlog = writeRoomRawlog(dir + "/room.rawlog", 20, &stamps);
  const auto ini = writeTextFile(dir + "/odo.ini", kOdometryIni);
  const auto r = runCommand(
      dynslamCommand("--config " + ini + " --rawlog " + rawlog + " --out " + dir + "/out"));
  ASSERT_EQ(r.exit_code, 0) << r.output;

  const auto traj = dynslam::core::readTum(dir + "/out/trajectory.tum");
  ASSERT_EQ(traj.size(), 20u);
  const auto truth = dynslam::testing::handheldPath(20);
  for (size_t i = 0; i < traj.size(); ++i) {
    EXPECT_NEAR(traj[i].t, stamps[i], 1e-6);
    EXPECT_LT((traj[i].T_world_body.translation() - truth[i].translation()).norm(), 0.01) << i;
  }
  const std::string summary = readTextFile(dir + "/out/summary.json");
  EXPECT_NE(summary.find("\"status\": \"ok\""), std::string::npos) << summary;
  EXPECT_NE(summary.find("\"frames\": 20"), std::string::npos) << summary;
  EXPECT_NE(summary.find("\"imu\": 120"), std::string::npos) << summary;
  EXPECT_NE(summary.find("\"name\": \"RgbdOdometry\""), std::string::npos) << summary;
}

TEST(Runner, TruncatedRawlogIsAnErrorAndKeepsTheTrajectorySoFar) {
  const std::string dir = scratchDir();
  const auto rawlog = writeRoomRawlog(dir + "/room.rawlog", 20);
  const std::string cut = dir + "/cut.rawlog";
  fs::copy_file(rawlog, cut);
  fs::resize_file(cut, fs::file_size(rawlog) / 2);
  const auto ini = writeTextFile(dir + "/odo.ini", kOdometryIni);
  const auto r =
      runCommand(dynslamCommand("--config " + ini + " --rawlog " + cut + " --out " + dir + "/out"));
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find(cut), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("truncated"), std::string::npos) << r.output;
  const size_t poses = lineCount(dir + "/out/trajectory.tum");
  EXPECT_GT(poses, 3u) << "the frames before the cut were estimated and written";
  EXPECT_LT(poses, 20u);
  EXPECT_NE(readTextFile(dir + "/out/summary.json").find("\"status\": \"failed\""),
            std::string::npos);
}

TEST(Runner, SevenScenesConversionCutInHalf) {
  DYNSLAM_REQUIRE_SHARED(scenes, "data/7scenes");
  const std::string dir = scratchDir();
  const auto conv = runCommand(binDir() + "/sevenscenes2rawlog --in " + scenes + " --out " + dir +
                               "/ss.rawlog --last 59");
  ASSERT_EQ(conv.exit_code, 0) << conv.output;
  fs::copy_file(dir + "/ss.rawlog", dir + "/ss_cut.rawlog");
  fs::resize_file(dir + "/ss_cut.rawlog", fs::file_size(dir + "/ss.rawlog") / 2);
  fs::create_directory_symlink(dir + "/ss_Images", dir + "/ss_cut_Images");
  const auto ini = writeTextFile(dir + "/odo.ini", kOdometryIni);
  const auto r = runCommand(dynslamCommand("--config " + ini + " --rawlog " + dir +
                                           "/ss_cut.rawlog --out " + dir + "/out"));
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("ss_cut.rawlog"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("truncated"), std::string::npos) << r.output;
  const size_t poses = lineCount(dir + "/out/trajectory.tum");
  EXPECT_GT(poses, 10u);
  EXPECT_LT(poses, 60u);
}

TEST(Runner, OutOfOrderTimestampsAreAnErrorAndKeepTheTrajectorySoFar) {
  const std::string dir = scratchDir();
  const auto path = dynslam::testing::handheldPath(6);
  std::vector<mrpt::serialization::CSerializable::Ptr> objs;
  for (int i = 0; i < 6; ++i) {
    auto k = dynslam::testing::vgaCamera();
    const double t = i == 4 ? 10.05 : 10.0 + i * 0.1;  // frame 4 goes back in time
    objs.push_back(dynslam::testing::makeRoomScan(t, path[i], k));
  }
  dynslam::testing::writeRawlog(dir + "/bad.rawlog", objs);
  const auto ini = writeTextFile(dir + "/odo.ini", kOdometryIni);
  const auto r = runCommand(
      dynslamCommand("--config " + ini + " --rawlog " + dir + "/bad.rawlog --out " + dir + "/out"));
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("--rawlog " + dir + "/bad.rawlog: out-of-order timestamp"),
            std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("observation #4"), std::string::npos) << r.output;
  EXPECT_EQ(lineCount(dir + "/out/trajectory.tum"), 3u) << "frames 0-2 were handed out before";
}

TEST(Runner, ANanImuSampleIsAnErrorNamingTheRawlogAndTheField) {
  const std::string dir = scratchDir();
  const auto path = dynslam::testing::handheldPath(6);
  std::vector<mrpt::serialization::CSerializable::Ptr> objs;
  for (int i = 0; i < 6; ++i) {
    objs.push_back(
        dynslam::testing::makeRoomScan(10.0 + i * 0.1, path[i], dynslam::testing::vgaCamera()));
    auto imu = dynslam::testing::makeImu(10.05 + i * 0.1);
    if (i == 3) imu->set(mrpt::obs::IMU_WZ, std::nan(""));
    objs.push_back(imu);
  }
  dynslam::testing::writeRawlog(dir + "/nan.rawlog", objs);
  const auto r =
      runCommand(dynslamCommand("--config " + writeTextFile(dir + "/odo.ini", kOdometryIni) +
                                " --rawlog " + dir + "/nan.rawlog --out " + dir + "/out"));
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("--rawlog " + dir + "/nan.rawlog: "), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("field IMU_WZ is not finite"), std::string::npos) << r.output;
  EXPECT_GE(lineCount(dir + "/out/trajectory.tum"), 3u) << "the frames before the sample";
}

TEST(Runner, ConfigurationErrorsNameWhatIsWrong) {
  const std::string dir = scratchDir();
  const auto rawlog = writeRoomRawlog(dir + "/room.rawlog", 2);
  const auto run = [&](const std::string& ini, const std::string& extra = "") {
    return runCommand(dynslamCommand("--config " + writeTextFile(dir + "/c.ini", ini) +
                                     " --rawlog " + rawlog + " --out " + dir + "/out " + extra));
  };
  auto r = run("[pipeline]\nstages = RgbdOdometry, Teleporter\n");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.output.find("unknown stage class 'Teleporter'"), std::string::npos) << r.output;

  r = run("[pipeline]\nstages = RgbdOdometry\n[RgbdOdometry]\nmax_dpeth = 3\n");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.output.find("unknown key 'max_dpeth' in section [RgbdOdometry]"), std::string::npos)
      << r.output;

  r = run(kOdometryIni, "--set RgbdOdometry.methd=icp");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.output.find("'methd'"), std::string::npos) << r.output;

  r = run(std::string(kOdometryIni) + "[RgbdOdometri]\nmethod = icp\n");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.output.find("unknown section [RgbdOdometri]"), std::string::npos) << r.output;

  r = run(kOdometryIni, "--set RgbdOdometry.method=icp");
  EXPECT_EQ(r.exit_code, 0) << "a valid override works: " << r.output;
}

TEST(Runner, MissingFilesAreNamed) {
  const std::string dir = scratchDir();
  const auto ini = writeTextFile(dir + "/odo.ini", kOdometryIni);
  auto r = runCommand(
      dynslamCommand("--config " + ini + " --rawlog " + dir + "/nope.rawlog --out " + dir + "/o"));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.output.find(dir + "/nope.rawlog"), std::string::npos) << r.output;
  r = runCommand(dynslamCommand("--config " + dir + "/nope.ini --rawlog x --out " + dir + "/o"));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.output.find(dir + "/nope.ini"), std::string::npos) << r.output;
}

TEST(Runner, WithoutAnEstimatorSaysSo) {
  const std::string dir = scratchDir();
  const auto rawlog = writeRoomRawlog(dir + "/room.rawlog", 3);
  const auto ini = writeTextFile(dir + "/none.ini", "[pipeline]\nstages =\n");
  const auto r = runCommand(
      dynslamCommand("--config " + ini + " --rawlog " + rawlog + " --out " + dir + "/out"));
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("no pose estimator"), std::string::npos) << r.output;
  EXPECT_EQ(lineCount(dir + "/out/trajectory.tum"), 0u);
  EXPECT_NE(readTextFile(dir + "/out/summary.json").find("\"frames\": 3"), std::string::npos);
}

TEST(Runner, UsageErrorsExitWithTwo) {
  EXPECT_EQ(runCommand(binDir() + "/dynslam").exit_code, 2);
  EXPECT_EQ(runCommand(binDir() + "/dynslam --config a --rawlog b --out c --bogus").exit_code, 2);
  const auto help = runCommand(binDir() + "/dynslam --help");
  EXPECT_EQ(help.exit_code, 0);
  EXPECT_NE(help.output.find("--set"), std::string::npos);
}

TEST(Runner, MrptKinectAndRtkRawlogsStreamThroughThePipeline) {
  DYNSLAM_REQUIRE_SHARED(rgbd, "data/mrpt/tests_rgbd.rawlog");
  DYNSLAM_REQUIRE_SHARED(rtk, "data/mrpt/test_rtk_path.rawlog");
  const std::string dir = scratchDir();
  const auto ini = writeTextFile(dir + "/none.ini", "[pipeline]\nstages =\n");
  auto r =
      runCommand(dynslamCommand("--config " + ini + " --rawlog " + rgbd + " --out " + dir + "/k"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  std::string summary = readTextFile(dir + "/k/summary.json");
  EXPECT_NE(summary.find("\"mrpt::obs::CObservation3DRangeScan\": 1"), std::string::npos)
      << summary;
  EXPECT_NE(summary.find("\"frames\": 1"), std::string::npos) << summary;

  r = runCommand(dynslamCommand("--config " + ini + " --rawlog " + rtk + " --out " + dir +
                                "/g --set SensorSync.gnss_label=GPS_RTK_REAR"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  summary = readTextFile(dir + "/g/summary.json");
  EXPECT_NE(summary.find("\"mrpt::obs::CObservationGPS\": 691"), std::string::npos) << summary;
  EXPECT_NE(summary.find("\"gnss\": 77"), std::string::npos) << "the rear receiver" << summary;
  EXPECT_NE(summary.find("\"frames\": 0"), std::string::npos) << summary;
}

TEST(Runner, FramesOptionWritesAnAnnotatedPngPerFrame) {
  const std::string dir = scratchDir();
  const auto rawlog = writeRoomRawlog(dir + "/room.rawlog", 5);
  const auto ini = writeTextFile(dir + "/odo.ini", kOdometryIni);
  const auto r = runCommand(dynslamCommand("--config " + ini + " --rawlog " + rawlog + " --out " +
                                           dir + "/out --frames " + dir + "/frames"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  for (int i = 0; i < 5; ++i) {
    const std::string png = dir + "/frames/00000" + std::to_string(i) + ".png";
    const cv::Mat img = cv::imread(png);
    ASSERT_FALSE(img.empty()) << png;
    EXPECT_EQ(img.size(), cv::Size(320, 240)) << png;
  }
}

TEST(Runner, RealtimePlaysAtCameraRateAndReportsTheDetectorThreadsRate) {
  const std::string dir = scratchDir();
  const auto rawlog = writeRoomRawlog(dir + "/room.rawlog", 15);  // 0.47 s of stream at 30 Hz
  const auto ini = writeTextFile(
      dir + "/rt.ini",
      "[pipeline]\nstages = Detection, Segmentation, Tracking, Segmentation:PredictedBoxes\n"
      "[Detection]\ndetector = hog\nmode = realtime\n[PredictedBoxes]\nboxes = predicted_tracks\n");
  const auto r = runCommand(dynslamCommand("--config " + ini + " --rawlog " + rawlog + " --out " +
                                           dir + "/out --realtime"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const std::string summary = readTextFile(dir + "/out/summary.json");
  EXPECT_NE(summary.find("\"realtime\": {"), std::string::npos) << summary;
  EXPECT_NE(summary.find("\"camera_interval_ms\": 33.3"), std::string::npos) << summary;
  EXPECT_NE(summary.find("\"detector_hz\""), std::string::npos) << summary;
  EXPECT_NE(summary.find("\"name\": \"PredictedBoxes\""), std::string::npos) << summary;
  const auto wall = summary.find("\"wall_time_s\": ");
  ASSERT_NE(wall, std::string::npos);
  EXPECT_GE(std::stod(summary.substr(wall + 15)), 14 / 30.0) << "paced at the stamps' rate";
}

// SIGTERM (kill, a job scheduler's time limit) ends a run as Ctrl-C does: the frames so far in
// complete outputs, status "interrupted", exit 128 + the signal.
TEST(Runner, SigtermAndCtrlCEndTheRunWithTheOutputsSoFar) {
  const std::string dir = scratchDir();
  const auto rawlog = writeRoomRawlog(dir + "/room.rawlog", 90);  // 3 s of stream at 30 Hz
  const auto ini = writeTextFile(dir + "/odo.ini", kOdometryIni);
  for (const auto& [signal, code] : {std::pair{"TERM", 143}, std::pair{"INT", 130}}) {
    const std::string out = dir + "/out_" + signal;
    // Paced at the stamps' rate (--realtime), signalled once 5 poses are written.
    const auto r = runCommand(
        "sh -c '" +
        dynslamCommand("--config " + ini + " --rawlog " + rawlog + " --out " + out +
                       " --realtime --no-map") +
        " & p=$!; for i in $(seq 200); do [ $(cat " + out +
        "/trajectory.tum 2>/dev/null | wc -l) -ge 5 ] && break; sleep 0.05; done; kill -" + signal +
        " $p; wait $p; echo exit $?'");
    EXPECT_NE(r.output.find("exit " + std::to_string(code)), std::string::npos) << r.output;
    EXPECT_NE(r.output.find(signal == std::string("TERM") ? "interrupted (SIGTERM)"
                                                          : "interrupted (Ctrl-C)"),
              std::string::npos)
        << r.output;
    const size_t lines = lineCount(out + "/trajectory.tum");
    EXPECT_GE(lines, 5u);
    EXPECT_LT(lines, 90u) << "stopped before the end";
    EXPECT_EQ(dynslam::core::readTum(out + "/trajectory.tum").size(), lines) << "every line whole";
    const std::string summary = readTextFile(out + "/summary.json");
    EXPECT_NE(summary.find("\"status\": \"interrupted\""), std::string::npos) << summary;
  }
}

namespace {

/// Every line of a CSV log has the header's number of fields and ends with a newline.
void expectWholeCsvRows(const std::string& path) {
  const std::string text = readTextFile(path);
  ASSERT_FALSE(text.empty()) << path;
  EXPECT_EQ(text.back(), '\n') << path << ": the last row was cut";
  std::istringstream lines(text);
  std::string header, row;
  std::getline(lines, header);
  const auto fields = [](const std::string& line) {
    return std::count(line.begin(), line.end(), ',');
  };
  for (size_t n = 2; std::getline(lines, row); ++n)
    EXPECT_EQ(fields(row), fields(header)) << path << " line " << n << ": " << row;
}

}  // namespace

// kill -9 at a random frame (no handler runs): every pose and log row written before it is
// whole, and summary.json is absent rather than a stale or half-written one.
TEST(Runner, KillNineLeavesWholeLinesAndNoSummary) {
  const std::string dir = scratchDir();
  const auto rawlog = writeRoomRawlog(dir + "/room.rawlog", 90);
  const auto ini = writeTextFile(dir + "/vo.ini",
                                 "[pipeline]\nstages = FeatureTracking, Estimator\n"
                                 "[Estimator]\ndynamic_handling = none\ngyro_rotation_sigma = 0\n");
  const unsigned seed = std::random_device{}();
  const int killAt = 3 + int(std::mt19937(seed)() % 50);  // poses written before the kill
  SCOPED_TRACE("kill -9 after " + std::to_string(killAt) + " poses (seed " + std::to_string(seed) +
               ")");
  const std::string out = dir + "/out";
  fs::create_directories(out);
  writeTextFile(out + "/summary.json", "{\"status\": \"ok\", \"from\": \"an earlier run\"}\n");
  const auto r = runCommand("sh -c '" +
                            dynslamCommand("--config " + ini + " --rawlog " + rawlog + " --out " +
                                           out + " --realtime --no-map") +
                            " & p=$!; for i in $(seq 400); do [ $(cat " + out +
                            "/trajectory.tum 2>/dev/null | wc -l) -ge " + std::to_string(killAt) +
                            " ] && break; sleep 0.02; done; kill -9 $p; wait $p; echo exit $?'");
  EXPECT_NE(r.output.find("exit 137"), std::string::npos) << r.output;
  const size_t lines = lineCount(out + "/trajectory.tum");
  EXPECT_GE(lines, size_t(killAt));
  EXPECT_LT(lines, 90u) << "killed before the end";
  EXPECT_EQ(dynslam::core::readTum(out + "/trajectory.tum").size(), lines) << "every line whole";
  EXPECT_EQ(readTextFile(out + "/trajectory.tum").back(), '\n');
  expectWholeCsvRows(out + "/timing.csv");
  expectWholeCsvRows(out + "/keyframes.csv");
  EXPECT_FALSE(fs::exists(out + "/summary.json")) << "the earlier run's summary was kept";
}

// [SensorSync] max_observation_mb bounds what one field of an observation may claim: over it, the
// run fails naming the rawlog and the key, before the field is allocated.
TEST(Runner, AnObservationOverTheSizeLimitIsAnErrorNamingTheRawlogAndTheKey) {
  const std::string dir = scratchDir();
  const auto rawlog = writeRoomRawlog(dir + "/room.rawlog", 5);  // 320 x 240: 230 KB of colour
  const auto ini = writeTextFile(dir + "/odo.ini", kOdometryIni);
  const auto r = runCommand(dynslamCommand("--config " + ini + " --rawlog " + rawlog + " --out " +
                                           dir + "/out --set SensorSync.max_observation_mb=0.1"));
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find(rawlog), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("[SensorSync] max_observation_mb"), std::string::npos) << r.output;
  EXPECT_NE(readTextFile(dir + "/out/summary.json").find("\"status\": \"failed\""),
            std::string::npos);
}

TEST(Runner, FeatureTrackingAndTheEstimatorFollowTheSyntheticRoom) {
  const std::string dir = scratchDir();
  const auto rawlog = writeRoomRawlog(dir + "/room.rawlog", 40);
  const auto ini = writeTextFile(dir + "/vo.ini",
                                 "[pipeline]\nstages = FeatureTracking, Estimator\n"
                                 "[Estimator]\ndynamic_handling = none\n"
                                 // The rawlog's IMU samples are placeholders, not this path's
                                 // motion: the method's start-up leaves them out (no gyro factor).
                                 "gyro_rotation_sigma = 0\n");
  const auto r = runCommand(
      dynslamCommand("--config " + ini + " --rawlog " + rawlog + " --out " + dir + "/out"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto traj = dynslam::core::readTum(dir + "/out/trajectory.tum");
  ASSERT_EQ(traj.size(), 40u);
  // The estimator's world is the first body frame, not the first camera frame: compare the
  // motion relative to the first pose.
  const auto truth = dynslam::testing::handheldPath(40);
  double worst = 0;
  for (size_t i = 0; i < traj.size(); ++i) {
    const auto estimated = traj[0].T_world_body.inverse() * traj[i].T_world_body;
    const auto expected = truth[0].inverse() * truth[i];
    worst = std::max(worst, (estimated.translation() - expected.translation()).norm());
  }
  // Measured 0.025 m over a 0.43 m path with the default feature tracking (0.033 m with the
  // method's: 150 features, a 15 px window; 320x240 images, few corners on the room texture);
  // dense RGB-D odometry, which uses every pixel, stays under 0.01 m here.
  EXPECT_LT(worst, 0.05) << "worst position error over 40 frames, m";
  const std::string summary = readTextFile(dir + "/out/summary.json");
  EXPECT_NE(summary.find("\"solve_ms_median\""), std::string::npos) << summary;
}

TEST(Runner, PrintConfigWritesEveryKeyAtTheValueARunWouldUse) {
  const auto ini = dynslam::testing::sourceDir() + "/params/7scenes_vo.ini";
  const auto r = runCommand(binDir() + "/dynslam --config " + ini +
                            " --set FeatureTracking.quality_level=0.02 --print-config 2>&1");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  // The ini's value, an override, and a default the ini leaves out, each in its section.
  const auto tracking = r.output.find("[FeatureTracking]");
  const auto estimator = r.output.find("[Estimator]");
  ASSERT_NE(tracking, std::string::npos) << r.output;
  ASSERT_NE(estimator, std::string::npos) << r.output;
  const auto at = [&](const std::string& line) { return r.output.find("\n" + line); };
  EXPECT_GT(at("klt_window_px = 15"), tracking) << r.output;
  EXPECT_GT(at("quality_level = 0.02"), tracking) << r.output;
  EXPECT_GT(at("window_size = 10"), estimator) << r.output;
  EXPECT_NE(r.output.find("[SensorSync]"), std::string::npos) << r.output;
  // What it prints is an ini a run reads back (keys with empty values included).
  const auto printed = writeTextFile(scratchDir() + "/printed.ini",
                                     r.output.substr(r.output.find("# The configuration")));
  const auto again = runCommand(binDir() + "/dynslam --config " + printed + " --print-config 2>&1");
  EXPECT_EQ(again.exit_code, 0) << again.output;

  const auto bad = runCommand(binDir() + "/dynslam --config " + ini +
                              " --set FeatureTracking.max_featres=3 --print-config 2>&1");
  EXPECT_EQ(bad.exit_code, 1);
  EXPECT_NE(bad.output.find("unknown key 'max_featres'"), std::string::npos) << bad.output;
}
