#include <dynslam/core/Frame.h>
#include <dynslam/tracking/DepthIoU.h>
#include <dynslam/tracking/ObjectDepth.h>

#include <gtest/gtest.h>

using namespace dynslam;
using namespace dynslam::tracking;

TEST(TrackingDepthIoU, OverlapTimesDepthRatio) {
  const cv::Rect2f a(0, 0, 10, 10), b(5, 0, 10, 10);
  EXPECT_DOUBLE_EQ(boxIoU(a, a), 1.0);
  EXPECT_DOUBLE_EQ(boxIoU(a, b), 50.0 / 150.0);
  EXPECT_DOUBLE_EQ(boxIoU(a, cv::Rect2f(20, 20, 5, 5)), 0.0);
  EXPECT_DOUBLE_EQ(boxIoU(a, cv::Rect2f(0, 0, 0, 0)), 0.0);
  EXPECT_DOUBLE_EQ(depthIoU(a, 2.0, a, 4.0), 0.5);
  EXPECT_DOUBLE_EQ(depthIoU(a, 4.0, b, 2.0), 0.5 * 50.0 / 150.0);
  EXPECT_DOUBLE_EQ(depthIoU(a, 0.0, b, 2.0), 50.0 / 150.0) << "unknown depth: plain IoU";
}

TEST(TrackingObjectDepth, MedianOfTheCentralHalf) {
  // 3 m background, a person at 2 m covering the box's centre, an occluder at 1 m in one corner
  // of the central half: the median ignores the corner.
  cv::Mat depth(100, 100, CV_32FC1, cv::Scalar(3.0f));
  depth(cv::Rect(20, 20, 60, 60)).setTo(2.0f);
  depth(cv::Rect(30, 30, 10, 10)).setTo(1.0f);
  depth(cv::Rect(60, 60, 5, 5)).setTo(0.0f);  // holes are skipped
  const cv::Rect2f box(10, 10, 80, 80);       // central half: (30, 30) to (70, 70)
  EXPECT_FLOAT_EQ(medianDepthInCentralHalf(depth, box), 2.0);
  EXPECT_EQ(medianDepthInCentralHalf(cv::Mat(), box), 0.0);
  EXPECT_EQ(medianDepthInCentralHalf(cv::Mat(100, 100, CV_32FC1, cv::Scalar(0)), box), 0.0);
  // A box partly outside the image is clipped: its central half (-50..50) keeps 0..50, mostly
  // background.
  EXPECT_FLOAT_EQ(medianDepthInCentralHalf(depth, cv::Rect2f(-100, -100, 200, 200)), 3.0);
}

TEST(TrackingObjectDepth, SegmentationDepthFirstThenTheFallback) {
  core::Frame frame;
  frame.depth = cv::Mat(100, 100, CV_32FC1, cv::Scalar(3.0f));
  frame.detections.resize(2);
  frame.detections[0].box = frame.detections[1].box = cv::Rect2f(10, 10, 50, 50);
  core::ObjectMask mask;
  mask.detection = 1;
  mask.valid = true;
  mask.d_t = 2.5;
  frame.object_masks.push_back(mask);
  EXPECT_DOUBLE_EQ(measuredObjectDepth(frame, 1), 2.5);
  EXPECT_DOUBLE_EQ(measuredObjectDepth(frame, 0), 3.0) << "no mask: the box's median";
  frame.object_masks[0].valid = false;
  EXPECT_DOUBLE_EQ(measuredObjectDepth(frame, 1), 3.0) << "an invalid mask is not used";
}
