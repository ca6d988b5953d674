#include <dynslam/core/Config.h>
#include <dynslam/core/StageRegistry.h>
#include <dynslam/segmentation/FloorRemovalStage.h>
#include <dynslam/segmentation/RegisterStages.h>
#include <dynslam/testing/SyntheticRoom.h>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>

#include <cmath>

using namespace dynslam;
using segmentation::FloorPlaneParams;

namespace {

constexpr double kHeight = 1.4;   // camera above the floor, m
constexpr double kPersonZ = 3.0;  // a person standing 3 m ahead
constexpr int kPersonU0 = 290, kPersonU1 = 350;

core::CameraIntrinsics intrinsics() { return dynslam::testing::vgaCamera(); }

// Up in the camera's axes (y down, z forward) when the camera pitches down by `pitch`.
Eigen::Vector3d upWhenPitched(double pitch) {
  return Eigen::Vector3d(0, -std::cos(pitch), -std::sin(pitch));
}

// The floor kHeight below the camera, a wall 6 m ahead where the floor is farther, and a person
// (a flat 0.6 m-wide panel at kPersonZ, up to 1.8 m tall) standing on the floor; depth noise
// sigma(z) = noiseZ2 z^2.
cv::Mat renderScene(double pitch, double noiseZ2, bool person = true) {
  const auto K = intrinsics();
  const Eigen::Vector3d up = upWhenPitched(pitch);
  cv::Mat depth(K.height, K.width, CV_32FC1);
  cv::RNG rng(7);
  for (int v = 0; v < K.height; ++v) {
    for (int u = 0; u < K.width; ++u) {
      const Eigen::Vector3d ray((u - K.cx) / K.fx, (v - K.cy) / K.fy, 1);
      const double down = -up.dot(ray);
      double z = down > 1e-6 ? std::min(kHeight / down, 6.0) : 6.0;
      if (person && u >= kPersonU0 && u < kPersonU1) {
        const double heightOnPanel = up.dot(kPersonZ * ray) + kHeight;
        if (kPersonZ < z && heightOnPanel >= 0 && heightOnPanel <= 1.8) z = kPersonZ;
      }
      depth.at<float>(v, u) = float(z + rng.gaussian(noiseZ2 * z * z));
    }
  }
  return depth;
}

}  // namespace

TEST(FloorPlane, FitsTheFloorSeenByAPitchedCamera) {
  const double pitch = 8 * M_PI / 180;
  const cv::Mat depth = renderScene(pitch, 0.0015);
  const auto floor = segmentation::fitFloorPlane(depth, intrinsics(), {cv::Rect(280, 0, 80, 480)},
                                                 upWhenPitched(pitch), FloorPlaneParams{});
  ASSERT_TRUE(floor.has_value());
  EXPECT_NEAR(floor->offset, kHeight, 0.01) << "the camera's height above the floor";
  EXPECT_LT(std::acos(std::min(1.0, floor->normal.dot(upWhenPitched(pitch)))) * 180 / M_PI, 0.3);
  EXPECT_GT(floor->inliers, 1000);
}

TEST(FloorPlane, NoneWithoutAFloorOrWhenTheFloorLeansAwayFromUp) {
  const auto K = intrinsics();
  const cv::Mat wall(K.height, K.width, CV_32FC1, cv::Scalar(4.0f));
  EXPECT_FALSE(segmentation::fitFloorPlane(wall, K, {}, upWhenPitched(0), FloorPlaneParams{}))
      << "a wall facing the camera is no floor";
  const double pitch = 25 * M_PI / 180;
  const cv::Mat depth = renderScene(pitch, 0);
  EXPECT_FALSE(segmentation::fitFloorPlane(depth, K, {}, upWhenPitched(0), FloorPlaneParams{}))
      << "the image's up is 25 deg off the floor's normal: beyond max_tilt_deg";
  EXPECT_TRUE(segmentation::fitFloorPlane(depth, K, {}, upWhenPitched(pitch), FloorPlaneParams{}))
      << "with the right up it is the floor";
}

TEST(FloorPlane, UpComesFromTheAccelerometerElseTheImage) {
  core::Frame frame;
  EXPECT_TRUE(segmentation::upInCamera(frame).isApprox(Eigen::Vector3d(0, -1, 0)));
  const double pitch = 12 * M_PI / 180;
  for (int i = 0; i < 5; ++i) {
    core::ImuSample s;
    s.acc = 9.81 * upWhenPitched(pitch) + Eigen::Vector3d(0.05 * (i - 2), 0, 0);
    s.has_acc = true;
    frame.imu.push_back(s);
  }
  EXPECT_LT((segmentation::upInCamera(frame) - upWhenPitched(pitch)).norm(), 1e-3)
      << "IMU and camera share axes here (both extrinsics identity)";
}

namespace {

// A depth-threshold mask of the person's box: everything within 0.5 m of its depth, which takes
// the floor around its feet too; `floorPixels`: how many of its pixels are floor (`exact` is
// the scene without noise, `exactFloor` the floor alone).
core::ObjectMask personBoxMask(const cv::Mat& depth, const cv::Mat& exact,
                               const cv::Mat& exactFloor, int& floorPixels) {
  core::ObjectMask m;
  m.roi = cv::Rect(kPersonU0 - 20, 100, kPersonU1 - kPersonU0 + 40, 380);
  m.mask = cv::Mat(m.roi.size(), CV_8UC1, cv::Scalar(0));
  for (int y = 0; y < m.roi.height; ++y)
    for (int x = 0; x < m.roi.width; ++x) {
      const float z = depth.at<float>(m.roi.y + y, m.roi.x + x);
      if (std::abs(z - kPersonZ) > 0.5) continue;
      m.mask.at<uint8_t>(y, x) = 255;
      floorPixels += exact.at<float>(m.roi.y + y, m.roi.x + x) ==
                     exactFloor.at<float>(m.roi.y + y, m.roi.x + x);
    }
  return m;
}

}  // namespace

TEST(FloorRemovalStage, CutsTheFloorAtAPersonsFeetAndKeepsThePerson) {
  core::StageRegistry registry;
  segmentation::registerStages(registry);
  auto stage = registry.create("FloorRemoval");
  stage->configure(core::IniConfig::fromText(""), "FloorRemoval");

  const double pitch = 8 * M_PI / 180;
  core::Frame frame;
  frame.intrinsics = intrinsics();
  frame.depth = renderScene(pitch, 0.0015);
  const cv::Mat exact = renderScene(pitch, 0);
  const cv::Mat exactFloor = renderScene(pitch, 0, false);
  core::ImuSample s;
  s.acc = 9.81 * upWhenPitched(pitch);
  s.has_acc = true;
  frame.imu.push_back(s);
  int floorBefore = 0;
  const core::ObjectMask m = personBoxMask(frame.depth, exact, exactFloor, floorBefore);
  ASSERT_GT(floorBefore, 500) << "the scene must put floor into the mask";
  frame.object_masks.push_back(m);
  const cv::Mat before = m.mask.clone();

  stage->process(frame);

  int floorLeft = 0, personLost = 0, person = 0;
  const auto& after = frame.object_masks[0].mask;
  const Eigen::Vector3d up = upWhenPitched(pitch);
  for (int y = 0; y < m.roi.height; ++y)
    for (int x = 0; x < m.roi.width; ++x) {
      if (!before.at<uint8_t>(y, x)) continue;
      const int u = m.roi.x + x, v = m.roi.y + y;
      const bool onFloor = exact.at<float>(v, u) == exactFloor.at<float>(v, u);
      const Eigen::Vector3d ray((u - frame.intrinsics.cx) / frame.intrinsics.fx,
                                (v - frame.intrinsics.cy) / frame.intrinsics.fy, 1);
      const double height = up.dot(exact.at<float>(v, u) * ray) + kHeight;
      if (onFloor) floorLeft += after.at<uint8_t>(y, x) != 0;
      if (!onFloor && height > 0.15) {  // the person, above the depth noise's reach of the floor
        ++person;
        personLost += after.at<uint8_t>(y, x) == 0;
      }
    }
  EXPECT_LT(floorLeft, floorBefore / 10) << "of " << floorBefore << " floor pixels in the mask";
  EXPECT_EQ(personLost, 0) << "of " << person;
  const auto stats = stage->statistics();
  ASSERT_EQ(stats.size(), 3u);
  EXPECT_EQ(stats[1].first, "floor_frames");
  EXPECT_EQ(stats[1].second, 1);
  EXPECT_GT(stats[2].second, 0.0);
}

TEST(FloorRemovalStage, ReadsItsKeysAndNamesBadValues) {
  segmentation::FloorRemovalStage stage;
  stage.configure(core::IniConfig::fromText("[F]\nmargin_m = 0.05\n"
                                            "max_tilt_deg = 15\nmin_inliers = 40\n"
                                            "sample_stride_px = 4\niterations = 50\n"
                                            "inlier_m = 0.03\ndepth_sigma_z2 = 0.002\n"
                                            "max_depth_m = 5\n"),
                  "F");
  EXPECT_EQ(stage.options().margin_m, 0.05);
  EXPECT_EQ(stage.options().plane.max_tilt_deg, 15.0);
  EXPECT_EQ(stage.options().plane.min_inliers, 40);
  EXPECT_EQ(stage.options().plane.sample_stride_px, 4);
  EXPECT_EQ(stage.options().plane.iterations, 50);
  EXPECT_EQ(stage.options().plane.inlier_m, 0.03);
  EXPECT_EQ(stage.options().plane.depth_sigma_z2, 0.002);
  EXPECT_EQ(stage.options().plane.max_depth_m, 5.0);
  EXPECT_THROW(stage.configure(core::IniConfig::fromText("[F]\nmargin = 1\n"), "F"),
               core::ConfigError);
  try {
    stage.configure(core::IniConfig::fromText("[F]\nmax_tilt_deg = 95\n", "f.ini"), "F");
    FAIL() << "max_tilt_deg = 95 accepted";
  } catch (const core::ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("max_tilt_deg"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("f.ini"), std::string::npos) << e.what();
  }
  core::Frame noMasks;
  EXPECT_NO_THROW(stage.process(noMasks)) << "nothing to cut, no depth needed";
}
