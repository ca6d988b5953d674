// A sprite person composited into an RGB-D frame (SpriteCompositor.h): its size and place from
// the true height and the camera, the depth of a body's cross-section, and occlusion against
// nearer and farther surfaces and missing depth.
#include <dynslam/sim/SpriteCompositor.h>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

namespace dynslam::sim {
namespace {

core::CameraIntrinsics camera() {
  core::CameraIntrinsics K;
  K.fx = K.fy = 500;
  K.cx = 320;
  K.cy = 240;
  K.width = 640;
  K.height = 480;
  return K;
}

/// A 40 x 200 px person (left half blue, right half red) in a 60 x 200 crop, foot at the bottom.
SpriteFrame boxPerson() {
  SpriteFrame f;
  f.bgra = cv::Mat(200, 60, CV_8UC4, cv::Scalar(0, 0, 0, 0));
  f.bgra(cv::Rect(10, 0, 20, 200)).setTo(cv::Scalar(255, 0, 0, 255));
  f.bgra(cv::Rect(30, 0, 20, 200)).setTo(cv::Scalar(0, 0, 255, 255));
  f.foot = {30, 199};
  f.height_px = 200;
  return f;
}

/// A wall 5 m away; the camera's frame is the world's, its up is -y.
RenderOutput wall() {
  RenderOutput out;
  out.rgb = cv::Mat(480, 640, CV_8UC3, cv::Scalar(90, 90, 90));
  out.depth = cv::Mat(480, 640, CV_32FC1, cv::Scalar(5.0f));
  out.label = cv::Mat(480, 640, CV_16UC1, cv::Scalar(0));
  return out;
}

SpritePlacement threeMetresAhead() {
  SpritePlacement p;
  p.foot_world = {0, 1.0, 3.0};  // 1 m below the camera, 3 m ahead
  p.up_world = {0, -1, 0};
  p.height_m = 1.75;
  return p;
}

SpriteDraw drawInto(RenderOutput& frame, const SpritePlacement& placement) {
  return compositeSprite(boxPerson(), placement, 7, camera(), Eigen::Isometry3d::Identity(), frame);
}

TEST(SpriteCompositor, APersonStandsAtItsTrueSizeWithABodysDepth) {
  RenderOutput frame = wall();
  const SpriteDraw draw = drawInto(frame, threeMetresAhead());
  const cv::Rect drawn = cv::boundingRect(frame.label == 7);
  EXPECT_NEAR(drawn.height, 500 * 1.75 / 3, 3) << "1.75 m at 3 m";
  EXPECT_NEAR(drawn.width, 500 * 0.35 / 3, 3) << "0.35 m wide at 3 m";
  EXPECT_NEAR(drawn.br().y - 1, 240 + 500 * 1.0 / 3, 2) << "feet on the floor 1 m below the camera";
  EXPECT_NEAR(drawn.x + drawn.width / 2.0, 320, 2);
  EXPECT_EQ(draw.visible, draw.pixels);
  EXPECT_EQ(draw.visible, cv::countNonZero(frame.label == 7));
  EXPECT_EQ(draw.box, drawn) << "the amodal box is the silhouette's, not the wider crop's";
  const int row = drawn.y + drawn.height / 2, mid = drawn.x + drawn.width / 2;
  EXPECT_NEAR(frame.depth.at<float>(row, mid), 3.0 - 0.125, 0.01) << "the body's front, centre";
  EXPECT_NEAR(frame.depth.at<float>(row, drawn.x), 3.0, 0.04) << "its edge: back at the axis";
  EXPECT_EQ(frame.rgb.at<cv::Vec3b>(row, drawn.x + 3), cv::Vec3b(255, 0, 0)) << "left half blue";
  EXPECT_EQ(frame.depth.at<float>(row, drawn.x - 3), 5.0f) << "the wall beside it untouched";
}

TEST(SpriteCompositor, NearerSurfacesHideItAndMissingDepthDoesNot) {
  RenderOutput frame = wall();
  frame.depth(cv::Rect(0, 0, 320, 480)).setTo(2.0f);    // a nearer table over the left half
  frame.depth(cv::Rect(320, 0, 320, 200)).setTo(0.0f);  // no depth over the top right
  const SpriteDraw draw = drawInto(frame, threeMetresAhead());
  EXPECT_NEAR(draw.visible, draw.pixels / 2, draw.pixels / 20) << "the right half only";
  RenderOutput open = wall();
  EXPECT_EQ(draw.box, drawInto(open, threeMetresAhead()).box) << "amodal: the hidden half too";
  EXPECT_EQ(cv::countNonZero(frame.label(cv::Rect(0, 0, 320, 480)) == 7), 0);
  EXPECT_EQ(frame.depth.at<float>(300, 310), 2.0f) << "the table keeps its depth";
  EXPECT_EQ(frame.rgb.at<cv::Vec3b>(300, 310), cv::Vec3b(90, 90, 90)) << "and its colour";
  EXPECT_EQ(frame.label.at<uint16_t>(180, 330), 7) << "drawn where the frame had no depth";
  EXPECT_GT(frame.depth.at<float>(180, 330), 2.8f);
}

TEST(SpriteCompositor, MirroredWalksTheOtherWayAndBehindTheCameraDrawsNothing) {
  RenderOutput frame = wall();
  SpritePlacement p = threeMetresAhead();
  p.mirrored = true;
  drawInto(frame, p);
  const cv::Rect drawn = cv::boundingRect(frame.label == 7);
  const int row = drawn.y + drawn.height / 2;
  EXPECT_EQ(frame.rgb.at<cv::Vec3b>(row, drawn.x + 3), cv::Vec3b(0, 0, 255)) << "red on the left";

  RenderOutput untouched = wall();
  p.foot_world.z() = -3;
  const SpriteDraw behind = drawInto(untouched, p);
  EXPECT_EQ(behind.pixels, 0);
  EXPECT_EQ(cv::countNonZero(untouched.label), 0);
}

}  // namespace
}  // namespace dynslam::sim
