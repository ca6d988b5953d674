#include <dynslam/testing/SyntheticObservations.h>

#include <dynslam/io/ObservationConversion.h>
#include <dynslam/io/SensorSync.h>

#include <gtest/gtest.h>

#include <cmath>

using namespace dynslam::io;
using namespace dynslam::testing;
using dynslam::core::Frame;

namespace {
std::vector<Frame> run(SensorSync& sync, const std::vector<mrpt::obs::CObservation::Ptr>& obs) {
  std::vector<Frame> frames;
  for (const auto& o : obs) sync.push(o, frames);
  sync.flush(frames);
  return frames;
}
}  // namespace

TEST(SensorSync, ImuSamplesGoToTheFrameWhoseIntervalHoldsThem) {
  SensorSync sync;
  // Frames at 1.0 and 1.1; IMU every 0.025 s from 0.95. The sample stamped exactly 1.1 comes
  // after the frame in file order and must still belong to it: (t_prev, t] is closed at t.
  std::vector<mrpt::obs::CObservation::Ptr> obs;
  for (double t : {0.95, 0.975, 1.0}) obs.push_back(makeImu(t));
  obs.push_back(makeScan(1.0));
  for (double t : {1.025, 1.05, 1.075}) obs.push_back(makeImu(t));
  obs.push_back(makeScan(1.1));
  for (double t : {1.1, 1.125}) obs.push_back(makeImu(t));
  const auto frames = run(sync, obs);
  ASSERT_EQ(frames.size(), 2u);
  EXPECT_EQ(frames[0].imu.size(), 3u);  // 0.95, 0.975, 1.0 (no earlier frame)
  ASSERT_EQ(frames[1].imu.size(), 4u);  // 1.025 .. 1.1
  EXPECT_NEAR(frames[1].imu.front().t, 1.025, 1e-6);
  EXPECT_NEAR(frames[1].imu.back().t, 1.1, 1e-6);
  EXPECT_EQ(frames[1].index, 1u);
  EXPECT_TRUE(frames[1].imu.back().has_gyro);
  EXPECT_NEAR(frames[1].imu.back().acc.z(), 9.81, 1e-12);
  EXPECT_EQ(sync.counts().imu, 8u);
  EXPECT_EQ(sync.counts().rgbd, 2u);
}

TEST(SensorSync, DepthIsInMetresAndIntrinsicsCarried) {
  SensorSync sync;
  const auto frames = run(sync, {makeScan(5.0)});
  ASSERT_EQ(frames.size(), 1u);
  const Frame& f = frames[0];
  ASSERT_EQ(f.depth.type(), CV_32FC1);
  EXPECT_FLOAT_EQ(f.depth.at<float>(0, 0), 1.0f);
  EXPECT_FLOAT_EQ(f.depth.at<float>(10, 20), 1.3f);  // (1000 + 10 * 30) mm
  EXPECT_EQ(f.rgb.type(), CV_8UC3);
  EXPECT_EQ(f.intrinsics.width, 64);
  EXPECT_DOUBLE_EQ(f.intrinsics.fx, 500);
  EXPECT_EQ(f.sensor_label, "RGBD");
}

TEST(SensorSync, AccelerometerOnlyImuKeepsGyroFlagOff) {
  SensorSync sync;
  const auto frames = run(sync, {makeImu(0.5, 0, 9.8, false), makeScan(0.6)});
  ASSERT_EQ(frames.at(0).imu.size(), 1u);
  EXPECT_FALSE(frames[0].imu[0].has_gyro);
  EXPECT_TRUE(frames[0].imu[0].has_acc);
}

TEST(SensorSync, TimeGoingBackwardsIsAnErrorNamingBothTimes) {
  SensorSync sync;
  std::vector<Frame> frames;
  sync.push(makeImu(2.0), frames);
  try {
    sync.push(makeImu(1.5), frames);
    FAIL();
  } catch (const SyncError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("out-of-order"), std::string::npos) << msg;
    EXPECT_NE(msg.find("1.500000"), std::string::npos) << msg;
    EXPECT_NE(msg.find("2.000000"), std::string::npos) << msg;
    EXPECT_NE(msg.find("#1"), std::string::npos) << msg;
  }
}

TEST(SensorSync, RepeatedFrameTimestampIsAnError) {
  SensorSync sync;
  std::vector<Frame> frames;
  sync.push(makeScan(1.0), frames);
  EXPECT_THROW(sync.push(makeScan(1.0), frames), SyncError);
}

TEST(SensorSync, SampleArrivingAfterItsFrameWasHandedOutIsAnError) {
  SensorSync sync;
  std::vector<Frame> frames;
  sync.push(makeScan(1.0), frames);
  sync.push(makeImu(1.2), frames);  // hands out the frame at 1.0
  ASSERT_EQ(frames.size(), 1u);
  auto late = makeImu(0.9);
  late->sensorLabel = "IMU2";  // another IMU, so only the cross-sensor check can catch it
  EXPECT_THROW(sync.push(late, frames), SyncError);
}

TEST(SensorSync, NanImuSampleIsAnErrorNamingTheField) {
  SensorSync sync;
  std::vector<Frame> frames;
  auto bad = makeImu(1.0);
  bad->set(mrpt::obs::IMU_WY, std::nan(""));
  try {
    sync.push(bad, frames);
    FAIL();
  } catch (const ConversionError& e) {
    EXPECT_NE(std::string(e.what()).find("IMU_WY"), std::string::npos) << e.what();
  }
}

TEST(SensorSync, MissingDepthIsAnErrorUnlessSkipping) {
  auto noDepth = makeScan(1.0);
  noDepth->hasRangeImage = false;
  noDepth->rangeImage.resize(0, 0);
  {
    SensorSync sync;
    std::vector<Frame> frames;
    try {
      sync.push(noDepth, frames);
      FAIL();
    } catch (const ConversionError& e) {
      EXPECT_NE(std::string(e.what()).find("rangeImage"), std::string::npos) << e.what();
    }
  }
  SensorSyncOptions o;
  o.skip_frames_without_depth = true;
  SensorSync sync(o);
  const auto frames = run(sync, {noDepth, makeScan(1.1)});
  EXPECT_EQ(frames.size(), 1u);
  EXPECT_EQ(sync.counts().frames_without_depth, 1u);
}

TEST(SensorSync, GnssFixesGetEnuFromTheFirstFix) {
  SensorSync sync;
  // 0.001 deg of latitude is about 110.6 m north at 36.7 N; 0.001 deg of longitude about
  // 89.4 m east.
  const auto frames = run(sync, {makeGga(1.0, 36.7, -4.4, 50.0), makeGga(1.05, 36.701, -4.4, 50.0),
                                 makeGga(1.07, 36.7, -4.399, 52.0),
                                 makeGga(1.08, 36.7, -4.399, 52.0, 0), makeScan(1.1)});
  ASSERT_EQ(frames.size(), 1u);
  ASSERT_EQ(frames[0].gnss.size(), 3u);
  EXPECT_NEAR(frames[0].gnss[0].enu.norm(), 0.0, 1e-6);
  EXPECT_NEAR(frames[0].gnss[1].enu.y(), 110.9, 0.5);
  EXPECT_NEAR(frames[0].gnss[1].enu.x(), 0.0, 0.01);
  EXPECT_NEAR(frames[0].gnss[2].enu.x(), 89.3, 0.5);
  EXPECT_NEAR(frames[0].gnss[2].enu.z(), 2.0, 0.01);
  EXPECT_EQ(sync.counts().gnss_dropped, 1u) << "the quality-0 fix";
}

TEST(SensorSync, LabelFilterIgnoresOtherSensors) {
  SensorSyncOptions o;
  o.camera_label = "FRONT";
  SensorSync sync(o);
  const auto frames = run(sync, {makeScan(1.0, 64, 48, "REAR"), makeScan(1.1, 64, 48, "FRONT")});
  ASSERT_EQ(frames.size(), 1u);
  EXPECT_EQ(frames[0].sensor_label, "FRONT");
  EXPECT_EQ(sync.counts().other, 1u);
}

// MRPT's convention: sensorPose places the depth sensor's frame (+X forward) on the robot and
// the colour optical frame is relativePoseIntensityWRTDepth from it. With the defaults the
// camera looks along the body's x axis: optical z = body x, optical x = -body y.
TEST(SensorSync, ExtrinsicsComeFromTheObservationsSensorPose) {
  const auto rotated = [](const Eigen::Isometry3d& T, const Eigen::Vector3d& v) {
    return Eigen::Vector3d(T.linear() * v);
  };
  {
    SensorSync sync;
    const auto frames = run(sync, {makeScan(1.0)});
    ASSERT_EQ(frames.size(), 1u);
    EXPECT_TRUE(rotated(frames[0].T_body_camera, Eigen::Vector3d::UnitZ())
                    .isApprox(Eigen::Vector3d::UnitX(), 1e-12));
    EXPECT_TRUE(rotated(frames[0].T_body_camera, Eigen::Vector3d::UnitX())
                    .isApprox(-Eigen::Vector3d::UnitY(), 1e-12));
    EXPECT_TRUE(frames[0].T_body_imu.isApprox(Eigen::Isometry3d::Identity()));
  }
  SensorSync sync;
  auto scan = makeScan(1.0);
  scan->sensorPose = mrpt::poses::CPose3D(0.1, -0.2, 0.3, 0.5, 0, 0);  // yawed 0.5 rad
  auto imu = makeImu(0.99);
  imu->sensorPose = mrpt::poses::CPose3D(0.01, 0.02, 0.03, 0, 0, M_PI);  // upside down
  const auto frames = run(sync, {imu, scan});
  ASSERT_EQ(frames.size(), 1u);
  const auto& f = frames[0];
  EXPECT_TRUE(f.T_body_camera.translation().isApprox(Eigen::Vector3d(0.1, -0.2, 0.3), 1e-12));
  EXPECT_TRUE(rotated(f.T_body_camera, Eigen::Vector3d::UnitZ())
                  .isApprox(Eigen::Vector3d(std::cos(0.5), std::sin(0.5), 0), 1e-12));
  EXPECT_TRUE(f.T_body_imu.translation().isApprox(Eigen::Vector3d(0.01, 0.02, 0.03), 1e-12));
  EXPECT_TRUE(rotated(f.T_body_imu, Eigen::Vector3d::UnitZ())
                  .isApprox(-Eigen::Vector3d::UnitZ(), 1e-12));
}

TEST(SensorSyncOptions, ReadsItsKeysAndNamesABadValue) {
  SensorSyncOptions o;
  dynslam::core::loadOptionsStrict(
      o,
      dynslam::core::IniConfig::fromText(
          "[SensorSync]\ncamera_label = FRONT\nimu_label = IMU\ngnss_label = GPS\n"
          "skip_frames_without_depth = true\n"),
      "SensorSync");
  EXPECT_EQ(o.camera_label, "FRONT");
  EXPECT_EQ(o.imu_label, "IMU");
  EXPECT_EQ(o.gnss_label, "GPS");
  EXPECT_TRUE(o.skip_frames_without_depth);
  for (const char* bad : {"skip_frames_without_depth = maybe", "camera = FRONT"}) {
    try {
      dynslam::core::loadOptionsStrict(
          o, dynslam::core::IniConfig::fromText(std::string("[SensorSync]\n") + bad, "s.ini"),
          "SensorSync");
      FAIL() << bad << " accepted";
    } catch (const dynslam::core::ConfigError& e) {
      const std::string key = std::string(bad).substr(0, std::string(bad).find(' '));
      EXPECT_NE(std::string(e.what()).find(key), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("s.ini"), std::string::npos) << e.what();
    }
  }
}
