// dynslam-sim end to end: what it writes, that MRPT's tools and our pipeline read it, and that
// the same ini gives the same bytes.
#include "RawlogTestSupport.h"

#include <dynslam/core/TrajectoryFile.h>
#include <dynslam/io/RawlogSource.h>
#include <dynslam/io/SensorSync.h>
#include <dynslam/sim/ScenarioOptions.h>
#include <dynslam/sim/Simulator.h>
#include <dynslam/testing/TestEnv.h>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>
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
std::string simulate(const std::string& out, const std::string& extra = "",
                     const std::string& scenario = "indoor_people_high") {
  const std::string ini = dynslam::testing::sourceDir() + "/params/sim/" + scenario + ".ini";
  const auto r = runCommand(program("dynslam-sim") + " --config " + shellQuoted(ini) + " --out " +
                            shellQuoted(out) + " --set Scenario.duration=1 --quiet " + extra);
  EXPECT_EQ(r.exit_code, 0) << r.output;
  return r.output;
}

/// Every frame the pipeline would see in `rawlog`.
std::vector<dynslam::core::Frame> framesOf(const std::string& rawlog) {
  dynslam::io::RawlogSource source(rawlog);
  dynslam::io::SensorSync sync;
  std::vector<dynslam::core::Frame> frames;
  while (auto obs = source.next()) sync.push(obs, frames);
  sync.flush(frames);
  return frames;
}

size_t countLines(const std::string& text, bool skipComments) {
  std::istringstream in(text);
  size_t n = 0;
  for (std::string line; std::getline(in, line);)
    n += !line.empty() && !(skipComments && line[0] == '#');
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

// Indoors (people, IMU) and outdoors (cars, GNSS messages too).
TEST(DynslamSim, SameIniSameBytes) {
  for (const std::string scenario : {"indoor_people_high", "outdoor_street_high"}) {
    const std::string a = dynslam::testing::scratchDir(scenario + "_a"),
                      b = dynslam::testing::scratchDir(scenario + "_b");
    simulate(a, "", scenario);
    simulate(b, "", scenario);
    size_t compared = 0;
    for (const auto& e : fs::recursive_directory_iterator(a)) {
      if (!e.is_regular_file()) continue;
      const fs::path rel = fs::relative(e.path(), a);
      ASSERT_TRUE(fs::exists(fs::path(b) / rel)) << rel;
      EXPECT_EQ(readTextFile(e.path().string()), readTextFile((fs::path(b) / rel).string()))
          << scenario << ": " << rel;
      ++compared;
    }
    EXPECT_GT(compared, 60u) << scenario << ": rawlog, ground truth, 31 labels, 31 colour images";
  }
}

TEST(DynslamSim, PipelineReadsTheSimulatedRawlog) {
  const std::string out = dynslam::testing::scratchDir("run");
  simulate(out);
  const std::string ini =
      dynslam::testing::writeTextFile(out + "/none.ini", "[pipeline]\nstages =\n");
  const auto r = runCommand(dynslam::testing::binDir() + "/dynslam --quiet --config " + ini +
                            " --rawlog " + out + "/sim.rawlog --out " + out + "/slam");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const std::string summary = readTextFile(out + "/slam/summary.json");
  EXPECT_NE(summary.find("\"frames\": 31"), std::string::npos) << summary;
  EXPECT_NE(summary.find("\"imu_samples\": 201"), std::string::npos) << summary;
}

// sim -> rawlog -> SensorSync: the frames carry the simulator's camera and IMU extrinsics,
// stored as MRPT's sensorPose (camera: depth frame +X forward, optical frame relative to it).
TEST(DynslamSim, RawlogCarriesTheSensorExtrinsics) {
  const std::string out = dynslam::testing::scratchDir("extrinsics");
  const std::string mount =
      "--set Camera.cam_x=0.12 --set Camera.cam_y=-0.05 --set Camera.cam_z=0.08 "
      "--set Camera.cam_roll_deg=3 --set Camera.cam_pitch_deg=-7 --set Camera.cam_yaw_deg=11";
  simulate(out, mount + " --set Scenario.duration=0.2");
  const auto cfg = dynslam::core::IniConfig::fromFile(
      dynslam::testing::sourceDir() + "/params/sim/indoor_people_high.ini",
      {"Camera.cam_x=0.12", "Camera.cam_y=-0.05", "Camera.cam_z=0.08", "Camera.cam_roll_deg=3",
       "Camera.cam_pitch_deg=-7", "Camera.cam_yaw_deg=11"});
  dynslam::sim::ScenarioOptions options;
  options.load(cfg);
  const Eigen::Isometry3d expected = dynslam::sim::cameraInBody(options.camera);

  const std::vector<dynslam::core::Frame> frames = framesOf(out + "/sim.rawlog");
  ASSERT_EQ(frames.size(), 7u);
  for (const auto& f : frames) {
    EXPECT_TRUE(f.T_body_camera.isApprox(expected, 1e-9)) << "frame " << f.index << "\n"
                                                          << f.T_body_camera.matrix();
    EXPECT_TRUE(f.T_body_imu.isApprox(Eigen::Isometry3d::Identity(), 1e-12)) << f.index;
    EXPECT_FALSE(f.imu.empty());
  }
}

// [Calibration]: the frames are stamped 20 ms early against the IMU, the rawlog's camera
// sensorPose is turned 2 degrees from the rendered truth, the ground truth follows the stamps
// (the pose at the instant each names) and calibration.txt holds both sides.
TEST(DynslamSim, CalibrationErrorsChangeTheStampsAndTheBelievedExtrinsicNotTheTruth) {
  const std::string exact = dynslam::testing::scratchDir("exact"),
                    off = dynslam::testing::scratchDir("calibration_errors");
  simulate(exact, "--set Scenario.duration=0.5");
  simulate(off,
           "--set Scenario.duration=0.5 --set Calibration.time_offset_s=0.02 "
           "--set Calibration.cam_yaw_error_deg=2");
  const auto framesExact = framesOf(exact + "/sim.rawlog"),
             framesOff = framesOf(off + "/sim.rawlog");
  ASSERT_EQ(framesExact.size(), framesOff.size());
  for (size_t i = 0; i < framesOff.size(); ++i) {
    EXPECT_NEAR(framesExact[i].t - framesOff[i].t, 0.02, 1e-6) << i;
    const Eigen::AngleAxisd turn(framesOff[i].T_body_camera.rotation() *
                                 framesExact[i].T_body_camera.rotation().transpose());
    EXPECT_NEAR(turn.angle() * 180 / M_PI, 2.0, 1e-6) << i;
    EXPECT_NEAR(std::abs(turn.axis().z()), 1.0, 1e-6) << i;
  }
  // The first frame's stamp falls before the trajectory starts: no ground truth for it.
  const auto truthExact = dynslam::core::readTum(exact + "/groundtruth.tum");
  const auto truthOff = dynslam::core::readTum(off + "/groundtruth.tum");
  ASSERT_EQ(truthOff.size() + 1, truthExact.size());
  EXPECT_NEAR(truthOff.front().t, framesOff[1].t, 1e-6);
  // Same images: the pixels do not know about the stamps.
  EXPECT_EQ(readTextFile(exact + "/sim_Images/colour_000005.png"),
            readTextFile(off + "/sim_Images/colour_000005.png"));
  const std::string calibration = readTextFile(off + "/calibration.txt");
  EXPECT_NE(calibration.find("time_offset_s 0.02"), std::string::npos) << calibration;
  EXPECT_TRUE(std::regex_search(calibration, std::regex("rotation_error_deg (2|1\\.99999)")))
      << calibration;
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

// Every scenario of params/sim/ (one second of it) writes a rawlog whose counts rawlog-edit
// reports: 31 RGB-D frames, 201 IMU samples and, outdoors, 11 GNSS fixes.
struct ScenarioCounts {
  const char* ini;
  int gnss;
};

void PrintTo(const ScenarioCounts& c, std::ostream* os) { *os << c.ini; }

class DynslamSimScenario : public ::testing::TestWithParam<ScenarioCounts> {};

TEST_P(DynslamSimScenario, RawlogEditCountsOneSecond) {
  const auto& p = GetParam();
  const std::string out = dynslam::testing::scratchDir(p.ini);
  const std::string ini = dynslam::testing::sourceDir() + "/params/sim/" + p.ini + ".ini";
  const auto r = runCommand(program("dynslam-sim") + " --config " + shellQuoted(ini) + " --out " +
                            shellQuoted(out) + " --set Scenario.duration=1 --quiet");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto counts = dynslam::rawlog_tools::testing::countByLabel(out + "/sim.rawlog");
  EXPECT_EQ(counts.at("RGBD"), 31u);
  EXPECT_EQ(counts.at("IMU"), 201u);
  EXPECT_EQ(counts.count("GPS") ? counts.at("GPS") : 0u, static_cast<size_t>(p.gnss));
  const auto info = rawlogEditInfo(out + "/sim.rawlog");
  if (!info.available) GTEST_SKIP() << "rawlog-edit (Debian mrpt-apps) is not installed";
  EXPECT_EQ(info.exitCode, 0) << info.output;
  EXPECT_TRUE(std::regex_search(info.output, std::regex(R"(RGBD\s*/\s*31\s*/)"))) << info.output;
  EXPECT_TRUE(std::regex_search(info.output, std::regex(R"(IMU\s*/\s*201\s*/)"))) << info.output;
  if (p.gnss > 0) {
    EXPECT_TRUE(std::regex_search(info.output, std::regex(R"(GPS\s*/\s*11\s*/)"))) << info.output;
  }
}

INSTANTIATE_TEST_SUITE_P(
    Scenarios, DynslamSimScenario,
    ::testing::Values(ScenarioCounts{"static", 0}, ScenarioCounts{"indoor_people_low", 0},
                      ScenarioCounts{"indoor_people_high", 0}, ScenarioCounts{"corridor_people", 0},
                      ScenarioCounts{"market_crowd_low", 0}, ScenarioCounts{"market_crowd_high", 0},
                      ScenarioCounts{"outdoor_street_low", 11},
                      ScenarioCounts{"outdoor_street_high", 11}),
    [](const auto& info) { return std::string(info.param.ini); });

// The augmented 7-Scenes scenario end to end: real frames (here the first 30) in, a rawlog with
// inserted people, an IMU over the real motion and labels out.
TEST(DynslamSim, AugmentedSevenScenesPieceThroughTheProgram) {
  DYNSLAM_REQUIRE_SHARED(scenes, "data/7scenes");
  const std::string out = dynslam::testing::scratchDir("augment");
  const auto conv = runCommand(program("sevenscenes2rawlog") + " --in " + shellQuoted(scenes) +
                               " --out " + shellQuoted(out + "/real.rawlog") + " --last 29");
  ASSERT_EQ(conv.exit_code, 0) << conv.output;
  const std::string ini = dynslam::testing::sourceDir() + "/params/sim/augmented_7scenes.ini";
  const auto r = runCommand(program("dynslam-sim") + " --config " + shellQuoted(ini) + " --out " +
                            shellQuoted(out + "/run") + " --quiet --set Augment.rawlog=" +
                            shellQuoted(out + "/real.rawlog") + " --set Augment.floor_frames=10");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto counts = dynslam::rawlog_tools::testing::countByLabel(out + "/run/sim.rawlog");
  EXPECT_EQ(counts.at("RGBD"), 30u);
  EXPECT_EQ(counts.at("IMU"), 1 + 29 * 200 / 30u) << "200 Hz over the 29 frame intervals";
  EXPECT_EQ(dynslam::core::readTum(out + "/run/groundtruth.tum").size(), 30u);
  size_t withPerson = 0;
  for (const auto& e : fs::directory_iterator(out + "/run/labels"))
    withPerson += cv::countNonZero(cv::imread(e.path().string(), cv::IMREAD_UNCHANGED)) > 0;
  EXPECT_GT(withPerson, 0u) << "the inserted people are seen";
  const std::string objects = readTextFile(out + "/run/objects.txt");
  EXPECT_NE(objects.find(" person "), std::string::npos);
}

TEST(DynslamSim, InjectedFaultsReachTheRawlogAndBadValuesAreUsageErrors) {
  const std::string out = dynslam::testing::scratchDir("faults");
  // 1 s: IMU samples from 0.3 s for 0.2 s dropped (40 of 201), frames 5-7 black, 10-11 no depth.
  simulate(out, "--imu-gap 0.3:0.2 --black-frames 5:3 --no-depth 10:2");
  const std::vector<dynslam::core::Frame> frames = framesOf(out + "/sim.rawlog");
  ASSERT_EQ(frames.size(), 31u);
  size_t imu = 0;
  for (const auto& f : frames) {
    imu += f.imu.size();
    const bool black = f.index >= 5 && f.index < 8, noDepth = f.index >= 10 && f.index < 12;
    EXPECT_EQ(cv::countNonZero(f.rgb.reshape(1)) == 0, black) << "frame " << f.index;
    EXPECT_EQ(cv::countNonZero(f.depth) == 0, noDepth) << "frame " << f.index;
  }
  EXPECT_EQ(imu, 201u - 40u) << "0.2 s of 200 Hz samples dropped";

  const std::string ini = dynslam::testing::sourceDir() + "/params/sim/static.ini";
  const auto r = runCommand(program("dynslam-sim") + " --config " + shellQuoted(ini) + " --out " +
                            shellQuoted(out + "/bad") + " --imu-gap 3 --quiet");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("--imu-gap '3'"), std::string::npos) << r.output;
}
