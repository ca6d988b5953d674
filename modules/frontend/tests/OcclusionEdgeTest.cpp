// behindOcclusionEdge: a point is behind an occluding edge when a reading nearer by more than
// the gap lies within the window round it.
#include <dynslam/frontend/OcclusionEdge.h>

#include <gtest/gtest.h>

#include <limits>

using dynslam::frontend::behindOcclusionEdge;
using dynslam::frontend::OcclusionEdgeParams;

namespace {

/// A wall at `far` metres, and columns x < 100 at `near` metres in front of it.
cv::Mat wallWithNearSurface(float far, float near) {
  cv::Mat depth(120, 200, CV_32FC1, cv::Scalar(far));
  depth.colRange(0, 100).setTo(near);
  return depth;
}

OcclusionEdgeParams radius7() {
  OcclusionEdgeParams p;
  p.radius_px = 7;  // min_gap_m 0.15, gap_ratio 0.1
  return p;
}

}  // namespace

TEST(OcclusionEdge, APointWithinTheRadiusOfANearerSurfaceIsBehindItsEdge) {
  const cv::Mat depth = wallWithNearSurface(2.0f, 1.5f);
  EXPECT_TRUE(behindOcclusionEdge(depth, {106, 60}, radius7())) << "7 px from the edge";
  EXPECT_FALSE(behindOcclusionEdge(depth, {108, 60}, radius7())) << "8 px away";
  EXPECT_FALSE(behindOcclusionEdge(depth, {97, 60}, radius7())) << "on the nearer surface";
  EXPECT_FALSE(behindOcclusionEdge(depth, {106, 60}, OcclusionEdgeParams{})) << "radius 0: off";
}

TEST(OcclusionEdge, TheGapIsTheLargerOfTheMinimumAndTheRatioOfTheDepth) {
  // At 1 m the gap is max(0.15, 0.1) = 0.15 m; at 8 m max(0.15, 0.8) = 0.8 m.
  EXPECT_FALSE(behindOcclusionEdge(wallWithNearSurface(1.0f, 0.9f), {104, 60}, radius7()));
  EXPECT_TRUE(behindOcclusionEdge(wallWithNearSurface(1.0f, 0.8f), {104, 60}, radius7()));
  EXPECT_FALSE(behindOcclusionEdge(wallWithNearSurface(8.0f, 7.3f), {104, 60}, radius7()));
  EXPECT_TRUE(behindOcclusionEdge(wallWithNearSurface(8.0f, 7.1f), {104, 60}, radius7()));
}

TEST(OcclusionEdge, MissingReadingsAreNotNearer) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  for (const float missing : {0.0f, nan, -1.0f}) {
    const cv::Mat depth = wallWithNearSurface(2.0f, missing);
    EXPECT_FALSE(behindOcclusionEdge(depth, {104, 60}, radius7())) << "missing = " << missing;
    EXPECT_FALSE(behindOcclusionEdge(depth, {97, 60}, radius7())) << "no reading of its own";
  }
  EXPECT_FALSE(behindOcclusionEdge(cv::Mat(), {104, 60}, radius7())) << "no depth image";
  EXPECT_FALSE(behindOcclusionEdge(wallWithNearSurface(2.0f, 1.5f), {300, 60}, radius7()))
      << "outside the image";
}

TEST(OcclusionEdge, OnlyTheNearerReadingsTheMaskHoldsCount) {
  const cv::Mat depth = wallWithNearSurface(2.0f, 1.5f);
  cv::Mat object(depth.size(), CV_8UC1, cv::Scalar(0));
  EXPECT_FALSE(behindOcclusionEdge(depth, {104, 60}, radius7(), object)) << "not an object's";
  object.colRange(90, 100).setTo(255);
  EXPECT_TRUE(behindOcclusionEdge(depth, {104, 60}, radius7(), object));
  object.setTo(0);
  object.rowRange(0, 50).colRange(90, 100).setTo(255);
  EXPECT_FALSE(behindOcclusionEdge(depth, {104, 60}, radius7(), object)) << "10 rows above";
}

// nearDepthEdge: either side of the edge, and beside a missing reading, within the radius.
TEST(OcclusionEdge, ADepthEdgeIsNearOnEitherSideAndBesideMissingReadings) {
  const cv::Mat depth = wallWithNearSurface(2.0f, 1.5f);
  EXPECT_TRUE(dynslam::frontend::nearDepthEdge(depth, {106, 60}, radius7())) << "behind it";
  EXPECT_TRUE(dynslam::frontend::nearDepthEdge(depth, {94, 60}, radius7())) << "in front of it";
  EXPECT_FALSE(dynslam::frontend::nearDepthEdge(depth, {108, 60}, radius7())) << "8 px away";
  EXPECT_FALSE(dynslam::frontend::nearDepthEdge(depth, {91, 60}, radius7()));
  EXPECT_FALSE(dynslam::frontend::nearDepthEdge(depth, {106, 60}, OcclusionEdgeParams{}))
      << "radius 0: off";
  cv::Mat holes(120, 200, CV_32FC1, cv::Scalar(2.0f));
  holes.at<float>(60, 150) = 0;
  holes.at<float>(60, 50) = std::numeric_limits<float>::quiet_NaN();
  EXPECT_TRUE(dynslam::frontend::nearDepthEdge(holes, {145, 62}, radius7())) << "beside a hole";
  EXPECT_TRUE(dynslam::frontend::nearDepthEdge(holes, {55, 60}, radius7())) << "beside a NaN";
  EXPECT_FALSE(dynslam::frontend::nearDepthEdge(holes, {150, 60}, radius7()))
      << "no reading of its own: nothing to leave out";
  EXPECT_FALSE(dynslam::frontend::nearDepthEdge(holes, {100, 60}, radius7()));
}
