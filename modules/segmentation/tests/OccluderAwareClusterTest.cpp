// object_cluster = occluder_aware (a variant, not method.md): the near 2-means cluster is the
// object unless a nearer detection claims it. The method's far cluster takes the wall seen
// between a walker's legs for the person; this variant does not, and still treats a person
// standing in front as the occluder of the one behind.
#include <dynslam/segmentation/DepthThresholdSegmenter.h>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>

using namespace dynslam;
using segmentation::DepthThresholdParams;
using segmentation::DepthThresholdSegmenter;
using segmentation::ObjectCluster;

namespace {

core::Detection person(const cv::Rect& box) {
  core::Detection d;
  d.box = box;
  d.category = "person";
  return d;
}

DepthThresholdSegmenter segmenter(ObjectCluster c) {
  DepthThresholdParams p;
  p.object_cluster = c;
  return DepthThresholdSegmenter(p);
}

/// A walker 2 m away in front of a wall 5 m away, the wall showing between the legs over the
/// lower part of the candidate box.
cv::Mat walkerWithGap(const cv::Rect& box) {
  cv::Mat depth(240, 320, CV_32FC1, cv::Scalar(5.0f));
  depth(box).setTo(2.0f);
  depth(cv::Rect(box.x + box.width / 2 - 6, box.y + box.height / 2, 12, box.height / 2))
      .setTo(5.0f);
  return depth;
}

}  // namespace

TEST(OccluderAwareCluster, TheWallBetweenTheLegsIsNotThePerson) {
  const cv::Rect box(100, 20, 60, 200);
  const cv::Mat depth = walkerWithGap(box);
  const auto method = segmenter(ObjectCluster::Far).segment(depth, {person(box)});
  EXPECT_NEAR(method[0].d_t, 5.0, 1e-6) << "method.md's far cluster: the wall";
  const auto variant = segmenter(ObjectCluster::OccluderAware).segment(depth, {person(box)});
  ASSERT_TRUE(variant[0].valid);
  EXPECT_NEAR(variant[0].d_t, 2.0, 1e-6);
  EXPECT_EQ(variant[0].d_o, 0.0) << "no occluder";
  EXPECT_GT(cv::countNonZero(variant[0].mask), 0.9 * (box.area() - 12 * 100));
}

TEST(OccluderAwareCluster, APersonStandingInFrontIsStillTheOccluder) {
  // B 4 m away (box bottom at y 180) half hidden by A 2 m away (box bottom at y 230, nearer on
  // the floor); wall at 7 m.
  cv::Mat depth(240, 320, CV_32FC1, cv::Scalar(7.0f));
  const cv::Rect boxB(120, 40, 50, 140), boxA(90, 10, 60, 220);
  depth(boxB).setTo(4.0f);
  depth(boxA).setTo(2.0f);
  const auto masks =
      segmenter(ObjectCluster::OccluderAware).segment(depth, {person(boxA), person(boxB)});
  EXPECT_NEAR(masks[0].d_t, 2.0, 1e-6) << "A";
  EXPECT_NEAR(masks[1].d_t, 4.0, 1e-6) << "B: A's surface in its candidate box is A's";
  EXPECT_NEAR(masks[1].d_o, 2.0, 1e-6);
}
