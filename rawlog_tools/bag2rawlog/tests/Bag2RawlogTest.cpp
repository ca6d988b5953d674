// bag2rawlog round trip (issue 7): a bag written here -> rawlog -> read back through dynslam::io:
// the same colour pixels, depth in metres, IMU values and GNSS fixes come out, in stamp order.
#include "TestBag.h"

#include "../../tests/RawlogTestSupport.h"

#include <dynslam/io/ObservationConversion.h>
#include <dynslam/io/RawlogSource.h>
#include <dynslam/testing/TestEnv.h>
#include <gtest/gtest.h>
#include <mrpt/obs/CObservation3DRangeScan.h>
#include <mrpt/obs/CObservationGPS.h>
#include <mrpt/obs/CObservationIMU.h>
#include <opencv2/imgcodecs.hpp>

#include <filesystem>
#include <regex>

namespace fs = std::filesystem;
using dynslam::rawlog_tools::testing::program;
using dynslam::rawlog_tools::testing::rawlogEditInfo;
using dynslam::rawlog_tools::testing::shellQuoted;
using dynslam::testing::runCommand;
using namespace bagtest;

namespace {

struct ReadBack {
  std::vector<dynslam::core::Frame> frames;
  std::vector<dynslam::core::ImuSample> imu;
  std::vector<dynslam::core::GnssFix> gnss;
  bool sorted = true;
};

ReadBack readBack(const std::string& rawlog) {
  ReadBack out;
  dynslam::io::RawlogSource source(rawlog);
  double last = 0;
  while (auto obs = source.next()) {
    const double t = mrpt::Clock::toDouble(obs->timestamp);
    if (t < last) out.sorted = false;
    last = t;
    if (auto rgbd = std::dynamic_pointer_cast<mrpt::obs::CObservation3DRangeScan>(obs)) {
      dynslam::core::Frame frame;
      dynslam::io::fillFrameFromRgbd(*rgbd, frame);
      out.frames.push_back(frame);
    } else if (auto imu = std::dynamic_pointer_cast<mrpt::obs::CObservationIMU>(obs)) {
      if (auto s = dynslam::io::imuSampleFrom(*imu)) out.imu.push_back(*s);
    } else if (auto gps = std::dynamic_pointer_cast<mrpt::obs::CObservationGPS>(obs)) {
      if (auto f = dynslam::io::gnssFixFrom(*gps)) out.gnss.push_back(*f);
    }
  }
  return out;
}

struct Conversion {
  std::string rawlog;
  dynslam::testing::CommandResult result;
};

Conversion convert(const std::string& dir, const std::string& topics,
                   const std::string& extraArgs = "") {
  const std::string bag = dir + "/test.bag";
  if (!fs::exists(bag)) writeTestBag(bag);
  Conversion c;
  c.rawlog = dir + "/out.rawlog";
  const std::string ini = dynslam::testing::writeTextFile(dir + "/topics.ini", topics);
  c.result = runCommand(program("bag2rawlog") + " --bag " + shellQuoted(bag) + " --topics " +
                        shellQuoted(ini) + " --out " + shellQuoted(c.rawlog) + " " + extraArgs);
  return c;
}

void expectSameImage(const cv::Mat& a, const cv::Mat& b, const std::string& what) {
  ASSERT_EQ(a.size(), b.size()) << what;
  ASSERT_EQ(a.type(), b.type()) << what;
  EXPECT_EQ(cv::norm(a, b, cv::NORM_INF), 0.0) << what;
}

void expectDepthMetres(const cv::Mat& metres, int frame) {
  const cv::Mat mm = expectedDepthMm(frame);
  ASSERT_EQ(metres.type(), CV_32FC1);
  ASSERT_EQ(metres.size(), mm.size());
  for (int r = 0; r < mm.rows; ++r)
    for (int c = 0; c < mm.cols; ++c)
      EXPECT_NEAR(metres.at<float>(r, c), mm.at<uint16_t>(r, c) * 0.001, 1e-6)
          << "frame " << frame << " pixel " << r << "," << c;
}

constexpr const char* kRawTopics = R"([bag2rawlog]
rgb_topic = /cam/color/image_raw
depth_topic = /cam/aligned_depth/image_raw
camera_info_topic = /cam/color/camera_info
imu_topic = /imu
gnss_topic = /gps/fix
)";

constexpr const char* kRealSenseTopics = R"([bag2rawlog]
rgb_topic = /cam/color/image_raw/compressed
depth_topic = /cam/depth_metres
fx = 5.0
fy = 5.5
cx = 3.5
cy = 2.5
accel_topic = /accel/sample
gyro_topic = /gyro/sample
imu_pose = 0.01 0.02 0.03 0 0 0 1
)";

}  // namespace

TEST(Bag2Rawlog, RawColourDepthMmImuAndNavSatFixComeBackUnchanged) {
  const std::string dir = dynslam::testing::scratchDir();
  const Conversion c = convert(dir, kRawTopics);
  ASSERT_EQ(c.result.exit_code, 0) << c.result.output;
  EXPECT_NE(c.result.output.find("messages done"), std::string::npos) << c.result.output;
  EXPECT_NE(c.result.output.find("1 NavSatFix messages had no fix"), std::string::npos)
      << c.result.output;
  EXPECT_TRUE(fs::is_directory(dir + "/out_Images"));

  const ReadBack back = readBack(c.rawlog);
  EXPECT_TRUE(back.sorted);
  ASSERT_EQ(back.frames.size(), static_cast<size_t>(kFrames));
  for (int i = 0; i < kFrames; ++i) {
    const auto& f = back.frames[i];
    EXPECT_NEAR(f.t, colourStamp(i), 1e-6);
    expectSameImage(f.rgb, expectedBgr(i), "colour frame " + std::to_string(i));
    expectDepthMetres(f.depth, i);
    EXPECT_DOUBLE_EQ(f.intrinsics.fx, kFx);
    EXPECT_DOUBLE_EQ(f.intrinsics.fy, kFy);
    EXPECT_DOUBLE_EQ(f.intrinsics.cx, kCx);
    EXPECT_DOUBLE_EQ(f.intrinsics.cy, kCy);
  }

  const auto stamps = imuStamps();
  ASSERT_EQ(back.imu.size(), stamps.size());
  for (size_t k = 0; k < stamps.size(); ++k) {
    const auto& s = back.imu[k];
    ASSERT_TRUE(s.has_gyro && s.has_acc);
    EXPECT_NEAR(s.t, stamps[k], 1e-6);
    const auto g = gyroAt(stamps[k]), a = accAt(stamps[k]);
    for (int i = 0; i < 3; ++i) {
      EXPECT_DOUBLE_EQ(s.gyro[i], g[i]) << "sample " << k;
      EXPECT_DOUBLE_EQ(s.acc[i], a[i]) << "sample " << k;
    }
  }

  ASSERT_EQ(back.gnss.size(), 2u);  // the NO_FIX message is not written
  const auto expected = fixes();
  for (size_t k = 0; k < 2; ++k) {
    const Fix& e = expected[k == 0 ? 0 : 2];
    EXPECT_NEAR(back.gnss[k].t, e.t, 1e-6);
    EXPECT_DOUBLE_EQ(back.gnss[k].latitude_deg, e.latitude);
    EXPECT_DOUBLE_EQ(back.gnss[k].longitude_deg, e.longitude);
    EXPECT_DOUBLE_EQ(back.gnss[k].altitude_m, e.altitude);
    EXPECT_EQ(back.gnss[k].fix_quality, 1);
  }

  const auto info = rawlogEditInfo(c.rawlog);
  if (info.available) {
    EXPECT_EQ(info.exitCode, 0) << info.output;
    std::smatch m;
    ASSERT_TRUE(std::regex_search(info.output, m, std::regex(R"(RGBD\s*/\s*(\d+))")))
        << info.output;
    EXPECT_EQ(std::stoul(m[1].str()), static_cast<unsigned long>(kFrames));
  }
}

TEST(Bag2Rawlog, CompressedColourMetreDepthAndSplitRealSenseImu) {
  const std::string dir = dynslam::testing::scratchDir();
  const Conversion c = convert(dir, kRealSenseTopics);
  ASSERT_EQ(c.result.exit_code, 0) << c.result.output;

  // Compressed images are kept byte for byte: a PNG and a JPEG, one per frame.
  for (int i = 0; i < kFrames; ++i) {
    char name[64];
    std::snprintf(
        name, sizeof name, "%.0f.%09d%s", std::floor(colourStamp(i)),
        static_cast<int>(std::lround((colourStamp(i) - std::floor(colourStamp(i))) * 1e9)),
        i % 2 ? ".jpg" : ".png");
    EXPECT_TRUE(fs::is_regular_file(dir + "/out_Images/" + name)) << name;
  }

  const ReadBack back = readBack(c.rawlog);
  EXPECT_TRUE(back.sorted);
  ASSERT_EQ(back.frames.size(), static_cast<size_t>(kFrames));
  for (int i = 0; i < kFrames; ++i) {
    // PNG frames are lossless; JPEG frames decode to what OpenCV decodes from the same bytes.
    const cv::Mat expected = cv::imdecode(compressedBytes(i), cv::IMREAD_COLOR);
    expectSameImage(back.frames[i].rgb, expected, "compressed frame " + std::to_string(i));
    if (i % 2 == 0) expectSameImage(back.frames[i].rgb, expectedBgr(i), "PNG frame");
    expectDepthMetres(back.frames[i].depth, i);
  }

  // One sample per gyro message inside the accelerometer's span, accelerometer interpolated.
  const auto accel = accelStamps();
  size_t expectedCount = 0;
  for (const double t : imuStamps())
    if (t >= accel.front() - 1e-9 && t <= accel.back() + 1e-9) ++expectedCount;
  ASSERT_EQ(back.imu.size(), expectedCount);
  for (const auto& s : back.imu) {
    const auto g = gyroAt(s.t), a = accAt(s.t);
    for (int i = 0; i < 3; ++i) {
      EXPECT_NEAR(s.gyro[i], g[i], 1e-6);
      EXPECT_NEAR(s.acc[i], a[i], 1e-6);
    }
  }
  EXPECT_TRUE(back.gnss.empty());
}

TEST(Bag2Rawlog, EmbeddedImagesNeedNoImagesFolder) {
  const std::string dir = dynslam::testing::scratchDir();
  const Conversion c = convert(dir, kRawTopics, "--embed-images");
  ASSERT_EQ(c.result.exit_code, 0) << c.result.output;
  EXPECT_FALSE(fs::exists(dir + "/out_Images"));
  const ReadBack back = readBack(c.rawlog);
  ASSERT_EQ(back.frames.size(), static_cast<size_t>(kFrames));
  expectSameImage(back.frames[2].rgb, expectedBgr(2), "embedded frame 2");
}

TEST(Bag2Rawlog, CompressedDepthPngIsReadInMillimetres) {
  const std::string dir = dynslam::testing::scratchDir();
  // --set overrides topic-map keys; an empty topic is not converted.
  const Conversion c =
      convert(dir, kRawTopics,
              "--set bag2rawlog.depth_topic=/cam/depth_compressed --set bag2rawlog.imu_topic= "
              "--set bag2rawlog.gnss_topic=");
  ASSERT_EQ(c.result.exit_code, 0) << c.result.output;
  const ReadBack back = readBack(c.rawlog);
  ASSERT_EQ(back.frames.size(), static_cast<size_t>(kFrames));
  for (int i = 0; i < kFrames; ++i) expectDepthMetres(back.frames[i].depth, i);
  EXPECT_TRUE(back.imu.empty());
}

TEST(Bag2Rawlog, NmeaSentencesBecomeGgaFixes) {
  const std::string dir = dynslam::testing::scratchDir();
  const Conversion c = convert(dir, "[bag2rawlog]\nnmea_topic = /gps/nmea\n");
  ASSERT_EQ(c.result.exit_code, 0) << c.result.output;
  EXPECT_NE(c.result.output.find("1 NMEA sentences were not recognised"), std::string::npos)
      << c.result.output;
  const ReadBack back = readBack(c.rawlog);
  ASSERT_EQ(back.gnss.size(), 2u);
  const auto lines = nmeaSentences();
  for (size_t k = 0; k < 2; ++k) {
    const NmeaLine& e = lines[k == 0 ? 0 : 2];
    EXPECT_NEAR(back.gnss[k].t, e.t, 1e-6);  // the header's stamp, not the parse time
    EXPECT_NEAR(back.gnss[k].latitude_deg, e.latitude, 1e-9);
    EXPECT_NEAR(back.gnss[k].longitude_deg, e.longitude, 1e-9);
  }
  EXPECT_EQ(back.gnss[0].fix_quality, 1);
  EXPECT_EQ(back.gnss[1].fix_quality, 2);
  EXPECT_EQ(back.gnss[0].satellites, 8);
  EXPECT_NEAR(back.gnss[1].hdop, 1.1, 1e-6);
  EXPECT_NEAR(back.gnss[0].altitude_m, 519.5, 1e-9);
}

TEST(Bag2Rawlog, UnregisteredDepthIsRegisteredToColourWhenRead) {
  // The depth camera sits 0.2 m to the right of the colour camera (x in the colour optical
  // frame), same intrinsics (fx 5): a plane 1 m away appears fx * 0.2 / 1 = 1 pixel further
  // right in colour, so colour column 0 has no depth and the others see the plane.
  const std::string dir = dynslam::testing::scratchDir();
  const Conversion c = convert(dir, std::string(kRawTopics),
                               "--set bag2rawlog.depth_topic=/cam/depth_shifted "
                               "--set bag2rawlog.depth_camera_info_topic=/cam/depth/camera_info "
                               "--set 'bag2rawlog.depth_to_colour_pose=0.2 0 0 0 0 0 1'");
  ASSERT_EQ(c.result.exit_code, 0) << c.result.output;
  const ReadBack back = readBack(c.rawlog);
  ASSERT_EQ(back.frames.size(), static_cast<size_t>(kFrames));
  const cv::Mat& depth = back.frames[1].depth;
  ASSERT_EQ(depth.size(), cv::Size(kWidth, kHeight));
  for (int r = 0; r < kHeight; ++r) {
    EXPECT_EQ(depth.at<float>(r, 0), 0.0f) << "row " << r;
    for (int col = 1; col < kWidth; ++col)
      EXPECT_NEAR(depth.at<float>(r, col), 1.0, 1e-6) << r << "," << col;
  }
  expectSameImage(back.frames[1].rgb, expectedBgr(1), "colour of an unregistered pair");
}
