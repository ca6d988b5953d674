#include <dynslam/core/Config.h>
#include <dynslam/segmentation/FloorPlane.h>
#include <dynslam/segmentation/SegmentationStage.h>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>

#include <cmath>

using namespace dynslam;

namespace {

core::CameraIntrinsics camera() {
  core::CameraIntrinsics k;
  k.fx = k.fy = 300;
  k.cx = 160;
  k.cy = 120;
  k.width = 320;
  k.height = 240;
  return k;
}

/// Depth of a camera `height` m above a floor, pitched down by `pitchDeg`, facing a wall 8 m
/// away; readings beyond 10 m are missing, as a sensor's.
cv::Mat floorAndWall(double height, double pitchDeg) {
  const auto k = camera();
  const double t = pitchDeg * M_PI / 180;
  const Eigen::Vector3d up(0, -std::cos(t), -std::sin(t));     // world up, camera coordinates
  const Eigen::Vector3d forward(0, std::sin(t), std::cos(t));  // level forward
  cv::Mat depth(k.height, k.width, CV_32FC1, cv::Scalar(0.f));
  for (int v = 0; v < k.height; ++v)
    for (int u = 0; u < k.width; ++u) {
      const Eigen::Vector3d r((u - k.cx) / k.fx, (v - k.cy) / k.fy, 1.0);
      double z = 8.0 / forward.dot(r);                          // the wall
      if (up.dot(r) < 0) z = std::min(z, -height / up.dot(r));  // the floor, when nearer
      depth.at<float>(v, u) = z > 0 && z < 10 ? float(z) : 0.f;
    }
  return depth;
}

}  // namespace

TEST(FloorPlane, FindsTheFloorUnderALevelAndAPitchedCamera) {
  for (const double pitch : {0.0, 15.0}) {
    const auto floor = segmentation::fitFloorPlane(floorAndWall(0.9, pitch), camera());
    ASSERT_TRUE(floor.has_value()) << "pitch " << pitch;
    EXPECT_NEAR(floor->d, 0.9, 0.01) << "camera height, pitch " << pitch;
    const double t = pitch * M_PI / 180;
    EXPECT_NEAR(floor->n.y(), -std::cos(t), 0.01);
    EXPECT_NEAR(floor->n.z(), -std::sin(t), 0.01);
  }
}

TEST(FloorPlane, NoFloorWhenTheViewShowsNone) {
  const cv::Mat wall(240, 320, CV_32FC1, cv::Scalar(3.0f));
  EXPECT_FALSE(segmentation::fitFloorPlane(wall, camera()).has_value())
      << "a wall facing the camera is no floor";
  core::CameraIntrinsics none;
  EXPECT_FALSE(segmentation::fitFloorPlane(floorAndWall(0.9, 0), none).has_value())
      << "no intrinsics, no floor";
}

TEST(FloorPlane, ACarsMaskLosesTheRoadButKeepsTheCar) {
  cv::Mat depth = floorAndWall(0.9, 0);
  // A car 5 m away standing on the floor: rows from 0.6 m above the floor down to it.
  const cv::Rect car(100, 120 - 36, 120, 36 + 54);  // floor at 5 m: row 120 + 300 * 0.9 / 5
  depth(cv::Rect(car.x, car.y, car.width, car.height)).setTo(5.0f);
  const cv::Rect box(car.x - 10, car.y - 10, car.width + 20, car.height + 40);
  core::ObjectMask m;
  m.valid = true;
  m.roi = box;
  cv::inRange(depth(box), 2.0, 7.5, m.mask);  // e = 3 m: the road from 2 m to the wall
  const int road = cv::countNonZero(m.mask) - car.area();
  ASSERT_GT(road, 1000) << "the test needs road in the mask";
  const auto floor = segmentation::fitFloorPlane(depth, camera());
  ASSERT_TRUE(floor.has_value());
  segmentation::dropFloorPixels(m, depth, camera(), *floor, 0.1);
  const cv::Mat carInBox = m.mask(cv::Rect(car.tl() - box.tl(), car.size()));
  // The car's rows less than 0.1 m above the floor (6 rows at 5 m) go with the road.
  EXPECT_GE(cv::countNonZero(carInBox), car.area() - 6 * car.width);
  EXPECT_LE(cv::countNonZero(m.mask), car.area()) << "no road left";
}

TEST(FloorPlane, TheStageDropsTheFloorOnlyForTheMotionModelsGivenAMargin) {
  segmentation::SegmentationStage stage;
  stage.configure(core::IniConfig::fromText("[S]\nfloor_margin_rigid = 0.1\n"), "S");
  core::Frame frame;
  frame.intrinsics = camera();
  frame.depth = floorAndWall(0.9, 0);
  // Two objects 5 m away standing on the floor (row 174), 1.5 m tall.
  frame.depth(cv::Rect(60, 84, 60, 90)).setTo(5.0f);
  frame.depth(cv::Rect(200, 84, 60, 90)).setTo(5.0f);
  frame.detections.resize(2);
  frame.detections[0].box = cv::Rect2f(55, 80, 70, 120);
  frame.detections[0].category = "car";
  frame.detections[0].model = core::MotionModel::Rigid;
  frame.detections[1].box = cv::Rect2f(195, 80, 70, 120);
  frame.detections[1].category = "car";
  frame.detections[1].model = core::MotionModel::NonRigid;  // a class mapped to non-rigid
  stage.process(frame);
  ASSERT_EQ(frame.object_masks.size(), 2u);
  const auto floorRows = [&](const core::ObjectMask& m) {
    return cv::countNonZero(m.mask(cv::Rect(0, m.roi.height - 20, m.roi.width, 20)));
  };
  EXPECT_EQ(floorRows(frame.object_masks[0]), 0) << "rigid: the floor under it is dropped";
  EXPECT_GT(floorRows(frame.object_masks[1]), 0) << "non-rigid: margin 0, the floor stays";
  EXPECT_THROW(stage.configure(core::IniConfig::fromText("[S]\nfloor_margin_nonrigid = -1\n"), "S"),
               core::ConfigError);
}
