// tum2rawlog on a small TUM-layout folder written by the test: association, ordering, depth
// values, accelerometer-only IMU, intrinsics by folder name, ground-truth copy.
#include "RawlogTestSupport.h"

#include <dynslam/testing/TestEnv.h>
#include <gtest/gtest.h>
#include <mrpt/obs/CObservation3DRangeScan.h>
#include <mrpt/obs/CObservationIMU.h>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

namespace fs = std::filesystem;
using dynslam::rawlog_tools::testing::countByLabel;
using dynslam::rawlog_tools::testing::forEachObservation;
using dynslam::rawlog_tools::testing::program;
using dynslam::rawlog_tools::testing::rawlogEditInfo;
using dynslam::rawlog_tools::testing::shellQuoted;
using dynslam::testing::runCommand;
using namespace mrpt::obs;

namespace {

// Colour stamps and depth stamps chosen so that, with the 0.02 s rule:
//   colour 0 <-> depth 0 (5 ms), colour 1 <-> depth 1 (12 ms), colour 2 <-> depth 2 (4 ms),
//   colour 4 <-> depth 3 (5 ms); colour 3 is also within 10 ms of depth 3 but loses it to the
//   closer colour 4 (each depth used once), and depth 4 has no colour within 0.02 s.
const std::vector<std::string> kColourStamps = {"100.000000", "100.033000", "100.066000",
                                                "100.100000", "100.115000"};
const std::vector<std::string> kDepthStamps = {"100.005000", "100.045000", "100.070000",
                                               "100.110000", "100.200000"};
const std::vector<std::pair<int, int>> kExpectedPairs = {{0, 0}, {1, 1}, {2, 2}, {4, 3}};
const std::vector<std::array<double, 4>> kAccelerometer = {{99.990, 0.1, -9.8, 0.2},
                                                           {100.050, 0.2, -9.7, 0.3},
                                                           {100.120, 0.3, -9.6, 0.4},
                                                           {100.300, 0.4, -9.5, 0.5}};
constexpr int kWidth = 32, kHeight = 24;

cv::Mat colourImage(int index) {
  cv::Mat img(kHeight, kWidth, CV_8UC3);
  for (int r = 0; r < kHeight; ++r)
    for (int c = 0; c < kWidth; ++c)
      img.at<cv::Vec3b>(r, c) = cv::Vec3b(uchar(10 * index + r), uchar(c * 5), uchar(200 - index));
  return img;
}

cv::Mat depthImage(int index) {
  cv::Mat img(kHeight, kWidth, CV_16UC1);
  for (int r = 0; r < kHeight; ++r)
    for (int c = 0; c < kWidth; ++c)
      img.at<uint16_t>(r, c) = uint16_t(5000 * (index + 1) + 37 * r + c);
  img.at<uint16_t>(0, 0) = 0;  // TUM's invalid depth stays 0
  return img;
}

void writeTumFolder(const fs::path& dir) {
  fs::create_directories(dir / "rgb");
  fs::create_directories(dir / "depth");
  std::ofstream rgb(dir / "rgb.txt"), depth(dir / "depth.txt");
  rgb << "# color images\n# file: 'synthetic'\n# timestamp filename\n";
  depth << "# depth maps\n# file: 'synthetic'\n# timestamp filename\n";
  for (size_t i = 0; i < kColourStamps.size(); ++i) {
    cv::imwrite((dir / "rgb" / (kColourStamps[i] + ".png")).string(), colourImage(int(i)));
    rgb << kColourStamps[i] << " rgb/" << kColourStamps[i] << ".png\n";
  }
  for (size_t i = 0; i < kDepthStamps.size(); ++i) {
    cv::imwrite((dir / "depth" / (kDepthStamps[i] + ".png")).string(), depthImage(int(i)));
    depth << kDepthStamps[i] << " depth/" << kDepthStamps[i] << ".png\n";
  }
  std::ofstream acc(dir / "accelerometer.txt");
  acc << "# accelerometer data\n# timestamp ax ay az\n";
  for (const auto& s : kAccelerometer)
    acc << s[0] << " " << s[1] << " " << s[2] << " " << s[3] << "\n";
  std::ofstream gt(dir / "groundtruth.txt");
  gt << "# ground truth trajectory\n# timestamp tx ty tz qx qy qz qw\n"
     << "100.0000 1.0 2.0 3.0 0 0 0 1\n100.0500 1.1 2.0 3.0 0 0 0.0998 0.9950\n";
}

}  // namespace

class RawlogToolsTum : public ::testing::Test {
 protected:
  void SetUp() override {
    root_ = dynslam::testing::scratchDir();
    sequence_ = fs::path(root_) / "rgbd_dataset_freiburg1_xyz";
    writeTumFolder(sequence_);
    rawlog_ = (fs::path(root_) / "out" / "fr1.rawlog").string();
  }
  dynslam::testing::CommandResult convert(const std::string& extra = "") {
    return runCommand(program("tum2rawlog") + " --in " + shellQuoted(sequence_.string()) +
                      " --out " + shellQuoted(rawlog_) + " " + extra);
  }
  std::string root_, rawlog_;
  fs::path sequence_;
};

TEST_F(RawlogToolsTum, AssociatesWithinTwentyMillisecondsAndReportsDrops) {
  const auto r = convert();
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("associated 4 colour/depth pairs; dropped 1 colour and 1 depth"),
            std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("freiburg1"), std::string::npos) << r.output;
  const auto counts = countByLabel(rawlog_);
  EXPECT_EQ(counts.size(), 2u);
  EXPECT_EQ(counts.at("RGBD"), 4u);
  EXPECT_EQ(counts.at("IMU"), 4u);
}

TEST_F(RawlogToolsTum, WritesObservationsInTimeOrderWithRawDepthAndColour) {
  ASSERT_EQ(convert().exit_code, 0);
  // Expected sequence: acc0, rgbd(c0), rgbd(c1), acc1, rgbd(c2), rgbd(c4), acc2, acc3.
  const std::vector<std::string> expectedKinds = {"IMU",  "RGBD", "RGBD", "IMU",
                                                  "RGBD", "RGBD", "IMU",  "IMU"};
  size_t index = 0, pair = 0, acc = 0;
  double previous = 0;
  forEachObservation(rawlog_, [&](const CObservation::Ptr& o) {
    ASSERT_LT(index, expectedKinds.size());
    EXPECT_EQ(o->sensorLabel, expectedKinds[index]) << "observation " << index;
    const double t = mrpt::Clock::toDouble(o->timestamp);
    EXPECT_GE(t, previous);
    previous = t;
    if (auto imu = std::dynamic_pointer_cast<CObservationIMU>(o)) {
      const auto& s = kAccelerometer.at(acc++);
      EXPECT_NEAR(t, s[0], 1e-6);
      EXPECT_TRUE(imu->has(IMU_X_ACC));
      EXPECT_DOUBLE_EQ(imu->get(IMU_X_ACC), s[1]);
      EXPECT_DOUBLE_EQ(imu->get(IMU_Y_ACC), s[2]);
      EXPECT_DOUBLE_EQ(imu->get(IMU_Z_ACC), s[3]);
      EXPECT_FALSE(imu->has(IMU_WX));
      EXPECT_FALSE(imu->has(IMU_WY));
      EXPECT_FALSE(imu->has(IMU_WZ));
    } else {
      const auto obs = std::dynamic_pointer_cast<CObservation3DRangeScan>(o);
      ASSERT_TRUE(obs);
      const auto [colourIndex, depthIndex] = kExpectedPairs.at(pair++);
      // The observation carries the colour frame's stamp.
      EXPECT_NEAR(t, std::stod(kColourStamps[colourIndex]), 1e-6);
      EXPECT_FLOAT_EQ(obs->rangeUnits, 1.0f / 5000.0f);
      EXPECT_TRUE(obs->range_is_depth);
      const cv::Mat depth = depthImage(depthIndex);
      ASSERT_EQ(obs->rangeImage.rows(), kHeight);
      ASSERT_EQ(obs->rangeImage.cols(), kWidth);
      for (int r = 0; r < kHeight; ++r)
        for (int c = 0; c < kWidth; ++c)
          ASSERT_EQ(obs->rangeImage(r, c), depth.at<uint16_t>(r, c)) << r << "," << c;
      EXPECT_NEAR(obs->rangeImage(5, 7) * obs->rangeUnits, depth.at<uint16_t>(5, 7) / 5000.0, 1e-6);
      ASSERT_TRUE(obs->intensityImage.isExternallyStored());
      obs->load();
      EXPECT_EQ(cv::norm(obs->intensityImage.asCvMatRef(), colourImage(colourIndex), cv::NORM_INF),
                0.0);
    }
    ++index;
  });
  EXPECT_EQ(index, expectedKinds.size());
  EXPECT_EQ(pair, kExpectedPairs.size());
}

TEST_F(RawlogToolsTum, UsesFreiburg1IntrinsicsChosenByFolderName) {
  ASSERT_EQ(convert().exit_code, 0);
  forEachObservation(rawlog_, [&](const CObservation::Ptr& o) {
    const auto obs = std::dynamic_pointer_cast<CObservation3DRangeScan>(o);
    if (!obs) return;
    for (const mrpt::img::TCamera* cam : {&obs->cameraParams, &obs->cameraParamsIntensity}) {
      EXPECT_DOUBLE_EQ(cam->fx(), 517.3);
      EXPECT_DOUBLE_EQ(cam->fy(), 516.5);
      EXPECT_DOUBLE_EQ(cam->cx(), 318.6);
      EXPECT_DOUBLE_EQ(cam->cy(), 255.3);
      EXPECT_EQ(cam->ncols, unsigned(kWidth));
      EXPECT_EQ(cam->nrows, unsigned(kHeight));
    }
    EXPECT_TRUE(obs->doDepthAndIntensityCamerasCoincide());
  });
}

TEST_F(RawlogToolsTum, IntrinsicFlagsOverrideAndMustComeTogether) {
  ASSERT_EQ(convert("--fx 500 --fy 501 --cx 15.5 --cy 11.5").exit_code, 0);
  size_t checked = 0;
  forEachObservation(rawlog_, [&](const CObservation::Ptr& o) {
    if (const auto obs = std::dynamic_pointer_cast<CObservation3DRangeScan>(o)) {
      EXPECT_DOUBLE_EQ(obs->cameraParams.fx(), 500.0);
      EXPECT_DOUBLE_EQ(obs->cameraParamsIntensity.cy(), 11.5);
      ++checked;
    }
  });
  EXPECT_EQ(checked, 4u);
  const auto partial = convert("--fx 500");
  EXPECT_NE(partial.exit_code, 0);
  EXPECT_NE(partial.output.find("--fx, --fy, --cx and --cy"), std::string::npos) << partial.output;
}

TEST_F(RawlogToolsTum, FallsBackToRosDefaultsForOtherFolderNames) {
  const fs::path other = fs::path(root_) / "my_recording";
  fs::rename(sequence_, other);
  sequence_ = other;
  const auto r = convert();
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("ROS default"), std::string::npos) << r.output;
  forEachObservation(rawlog_, [&](const CObservation::Ptr& o) {
    if (const auto obs = std::dynamic_pointer_cast<CObservation3DRangeScan>(o)) {
      EXPECT_DOUBLE_EQ(obs->cameraParams.fx(), 525.0);
      EXPECT_DOUBLE_EQ(obs->cameraParams.cx(), 319.5);
      EXPECT_DOUBLE_EQ(obs->cameraParams.cy(), 239.5);
    }
  });
}

TEST_F(RawlogToolsTum, CopiesGroundTruthBesideTheRawlog) {
  ASSERT_EQ(convert().exit_code, 0);
  const fs::path gt = fs::path(root_) / "out" / "fr1.gt.tum";
  ASSERT_TRUE(fs::exists(gt));
  EXPECT_EQ(dynslam::testing::readTextFile(gt),
            dynslam::testing::readTextFile((sequence_ / "groundtruth.txt").string()));
}

TEST_F(RawlogToolsTum, EmbeddedImagesStayInTheRawlog) {
  ASSERT_EQ(convert("--embed-images").exit_code, 0);
  EXPECT_FALSE(fs::exists(fs::path(root_) / "out" / "fr1_Images"));
  size_t pair = 0;
  forEachObservation(rawlog_, [&](const CObservation::Ptr& o) {
    if (const auto obs = std::dynamic_pointer_cast<CObservation3DRangeScan>(o)) {
      EXPECT_FALSE(obs->intensityImage.isExternallyStored());
      const int colourIndex = kExpectedPairs.at(pair++).first;
      EXPECT_EQ(cv::norm(obs->intensityImage.asCvMatRef(), colourImage(colourIndex), cv::NORM_INF),
                0.0);
    }
  });
  EXPECT_EQ(pair, 4u);
}

TEST_F(RawlogToolsTum, RawlogEditInfoSeesBothSensors) {
  ASSERT_EQ(convert().exit_code, 0);
  const auto info = rawlogEditInfo(rawlog_);
  if (!info.available) GTEST_SKIP() << "rawlog-edit (mrpt-apps) is not installed";
  ASSERT_EQ(info.exitCode, 0) << info.output;
  std::smatch m;
  ASSERT_TRUE(
      std::regex_search(info.output, m, std::regex(R"(Overall number of objects\s*:\s*(\d+))")));
  EXPECT_EQ(m[1].str(), "8");
  ASSERT_TRUE(std::regex_search(info.output, m, std::regex(R"(RGBD\s*/\s*(\d+))"))) << info.output;
  EXPECT_EQ(m[1].str(), "4");
  ASSERT_TRUE(std::regex_search(info.output, m, std::regex(R"(IMU\s*/\s*(\d+))"))) << info.output;
  EXPECT_EQ(m[1].str(), "4");
}

TEST_F(RawlogToolsTum, MissingDepthImageIsAnErrorNamingTheFileAndLeavesNoRawlog) {
  fs::remove(sequence_ / "depth" / (kDepthStamps[2] + ".png"));
  const auto r = convert();
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find(kDepthStamps[2] + ".png"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(rawlog_));
}

TEST_F(RawlogToolsTum, MalformedListLineIsAnErrorNamingFileAndLine) {
  std::ofstream(sequence_ / "rgb.txt", std::ios::app) << "100.5x rgb/none.png\n";
  const auto r = convert();
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find("rgb.txt line 9, column 1"), std::string::npos) << r.output;
}
