// Mutual occlusion (method.md section 1, step 9): overlapping boxes are segmented each with its
// own thresholds; in the overlap a pixel goes to the object whose [T_min, T_max] holds its
// depth, the nearer object (smaller d_t) when both do.
#include <dynslam/segmentation/DepthThresholdSegmenter.h>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>

using namespace dynslam;
using segmentation::DepthThresholdSegmenter;

namespace {

core::Detection person(const cv::Rect& box) {
  core::Detection d;
  d.box = box;
  d.category = "person";
  return d;
}

bool inRange(const core::ObjectMask& m, float z) { return z >= m.t_min && z <= m.t_max && z > 0; }

bool owns(const core::ObjectMask& m, int u, int v) {
  return m.roi.contains({u, v}) && m.mask.at<uint8_t>(v - m.roi.y, u - m.roi.x) != 0;
}

/// Every pixel of every box ends in exactly the object the rule names: the nearest object
/// (by d_t) among those whose box holds the pixel and whose range holds its depth; none when
/// no range holds it.
void expectRuleHolds(const cv::Mat& depth, const std::vector<core::ObjectMask>& masks) {
  for (int v = 0; v < depth.rows; ++v)
    for (int u = 0; u < depth.cols; ++u) {
      int expected = -1;
      for (int k = 0; k < static_cast<int>(masks.size()); ++k)
        if (masks[k].roi.contains({u, v}) && inRange(masks[k], depth.at<float>(v, u)) &&
            (expected < 0 || masks[k].d_t < masks[expected].d_t))
          expected = k;
      for (int k = 0; k < static_cast<int>(masks.size()); ++k)
        ASSERT_EQ(owns(masks[k], u, v), k == expected) << "pixel (" << u << ", " << v << ")";
    }
}

int ownedIn(const core::ObjectMask& m, const cv::Rect& region, const cv::Mat& depth, float z) {
  int n = 0;
  for (int v = region.y; v < region.br().y; ++v)
    for (int u = region.x; u < region.br().x; ++u) n += owns(m, u, v) && depth.at<float>(v, u) == z;
  return n;
}

}  // namespace

TEST(MutualOcclusion, EachObjectKeepsTheOverlapPixelsOnlyItsRangeHolds) {
  // Person A at 2.0 m (body x in [40, 95)) in front of person B at 3.5 m (body x in [60, 130)),
  // wall at 6 m. A's body covers two of the six sample columns of B's candidate box, so B
  // sees A as an occluder.
  cv::Mat depth(120, 200, CV_32FC1, cv::Scalar(6.0f));
  depth(cv::Rect(60, 30, 70, 90)).setTo(3.5f);
  depth(cv::Rect(40, 30, 55, 90)).setTo(2.0f);
  const cv::Rect boxA(35, 20, 65, 100), boxB(70, 20, 60, 100), overlap = boxA & boxB;
  const auto masks = DepthThresholdSegmenter(segmentation::methodParams())
                         .segment(depth, {person(boxA), person(boxB)});
  ASSERT_EQ(masks.size(), 2u);
  ASSERT_TRUE(masks[0].valid && masks[1].valid);
  EXPECT_EQ(masks[0].detection, 0);
  EXPECT_EQ(masks[1].detection, 1);
  EXPECT_DOUBLE_EQ(masks[0].d_t, 2.0);
  EXPECT_DOUBLE_EQ(masks[1].d_t, 3.5) << "B's own thresholds: its far cluster";
  EXPECT_DOUBLE_EQ(masks[1].d_o, 2.0) << "A is B's occluder";
  EXPECT_DOUBLE_EQ(masks[1].t_min, 2.75);
  EXPECT_LT(masks[0].t_max, 3.5) << "A's range stops before B";
  expectRuleHolds(depth, masks);
  EXPECT_EQ(ownedIn(masks[0], overlap, depth, 2.0f), 25 * 90) << "A's body in the overlap";
  EXPECT_EQ(ownedIn(masks[1], overlap, depth, 3.5f), 5 * 90) << "B's body in the overlap";
}

TEST(MutualOcclusion, TheNearerObjectWinsPixelsBothRangesHold) {
  // B only 0.4 m behind A: within e, so neither range excludes the other's depth.
  cv::Mat depth(120, 200, CV_32FC1, cv::Scalar(6.0f));
  depth(cv::Rect(80, 30, 50, 90)).setTo(2.4f);
  depth(cv::Rect(40, 30, 40, 90)).setTo(2.0f);
  const cv::Rect boxA(35, 20, 55, 100), boxB(70, 20, 60, 100), overlap = boxA & boxB;
  const DepthThresholdSegmenter segmenter(segmentation::methodParams());
  const auto alone = segmenter.segmentOne(depth, person(boxB), 1);
  ASSERT_TRUE(alone.valid);
  EXPECT_GT(ownedIn(alone, overlap, depth, 2.0f), 0) << "alone, B takes some of A's pixels";

  const auto masks = segmenter.segment(depth, {person(boxA), person(boxB)});
  ASSERT_TRUE(masks[0].valid && masks[1].valid);
  ASSERT_LT(masks[0].d_t, masks[1].d_t);
  ASSERT_TRUE(inRange(masks[0], 2.4f) && inRange(masks[1], 2.0f)) << "the ranges overlap";
  expectRuleHolds(depth, masks);
  EXPECT_EQ(ownedIn(masks[1], overlap, depth, 2.0f), 0);
  EXPECT_EQ(ownedIn(masks[1], overlap, depth, 2.4f), 0) << "ties go to the nearer A";
  EXPECT_EQ(ownedIn(masks[0], overlap, depth, 2.0f) + ownedIn(masks[0], overlap, depth, 2.4f),
            20 * 90);
  // Outside the overlap B keeps exactly what it had alone.
  const cv::Rect onlyB(90, 20, 40, 100);
  EXPECT_EQ(cv::countNonZero(masks[1].mask(onlyB - boxB.tl())),
            cv::countNonZero(alone.mask(onlyB - boxB.tl())));
}

TEST(MutualOcclusion, InvalidMasksTakePartInNothing) {
  cv::Mat depth(120, 200, CV_32FC1, cv::Scalar(2.0f));
  depth(cv::Rect(70, 20, 60, 100)).setTo(0);  // no depth at all in B's box
  const auto masks = DepthThresholdSegmenter(segmentation::methodParams())
                         .segment(depth, {person({35, 20, 55, 100}), person({70, 20, 60, 100})});
  ASSERT_EQ(masks.size(), 2u);
  EXPECT_TRUE(masks[0].valid);
  EXPECT_FALSE(masks[1].valid);
  EXPECT_EQ(cv::countNonZero(masks[0].mask), 55 * 100 - 20 * 100);
}

// Two people 0.3 m apart in depth (less than e = 0.5 m), boxes overlapping: each range holds
// both people's depths. The method's rule gives the near person every overlap pixel; with
// overlap_rule closest_depth the far person keeps its own pixels there.
TEST(SegmentationMutualOcclusion, ClosestDepthKeepsAPersonJustBehindAnother) {
  cv::Mat depth(240, 320, CV_32FC1, cv::Scalar(6.0f));  // wall
  depth(cv::Rect(60, 40, 100, 180)).setTo(2.0f);        // near person
  depth(cv::Rect(160, 40, 100, 180)).setTo(2.3f);       // far person, right of it
  // The near box's candidate box (its central half) sees the near person only.
  const std::vector<core::Detection> boxes = {person({50, 30, 120, 200}),
                                              person({120, 30, 150, 200})};
  for (auto rule : {segmentation::OverlapRule::Nearer, segmentation::OverlapRule::ClosestDepth}) {
    auto p = segmentation::methodParams();
    p.overlap_rule = rule;
    const auto masks = DepthThresholdSegmenter(p).segment(depth, boxes);
    ASSERT_TRUE(masks[0].valid && masks[1].valid);
    ASSERT_TRUE(inRange(masks[0], 2.3f)) << "the case this test is about";
    const bool closest = rule == segmentation::OverlapRule::ClosestDepth;
    EXPECT_EQ(owns(masks[1], 165, 100), closest) << "far person's pixel in the overlap";
    EXPECT_EQ(owns(masks[0], 165, 100), !closest);
    EXPECT_TRUE(owns(masks[0], 130, 100)) << "near person's pixel in the overlap stays its own";
    EXPECT_FALSE(owns(masks[1], 130, 100));
  }
}

// The far person turns away from the camera: its body slants from 2.12 m at its left edge, in
// the overlap, to 2.9 m. Its pixels there are nearer the near person's d_t than its own, so
// closest_depth gives them to the near person; overlap_rule connected follows the far
// person's surface from its own pixels into the overlap, and stops at the 0.12 m step to the
// near person.
TEST(SegmentationMutualOcclusion, ConnectedFollowsEachSurfaceIntoTheOverlap) {
  cv::Mat depth(240, 320, CV_32FC1, cv::Scalar(6.0f));  // wall
  depth(cv::Rect(60, 40, 100, 180)).setTo(2.0f);        // near person
  for (int x = 160; x < 260; ++x)                       // far person, slanted
    depth(cv::Rect(x, 40, 1, 180)).setTo(2.12f + 0.0078f * (x - 160));
  const std::vector<core::Detection> boxes = {person({50, 30, 120, 200}),
                                              person({120, 30, 150, 200})};
  for (auto rule :
       {segmentation::OverlapRule::ClosestDepth, segmentation::OverlapRule::Connected}) {
    auto p = segmentation::methodParams();
    p.overlap_rule = rule;
    const auto masks = DepthThresholdSegmenter(p).segment(depth, boxes);
    ASSERT_TRUE(masks[0].valid && masks[1].valid);
    ASSERT_TRUE(inRange(masks[0], depth.at<float>(100, 162)) &&
                inRange(masks[1], depth.at<float>(100, 162)))
        << "the case this test is about";
    ASSERT_LT(std::abs(depth.at<float>(100, 162) - masks[0].d_t),
              std::abs(depth.at<float>(100, 162) - masks[1].d_t));
    const bool connected = rule == segmentation::OverlapRule::Connected;
    for (int x = 160; x < 170; ++x) {
      EXPECT_EQ(owns(masks[1], x, 100), connected) << "far person's pixel x = " << x;
      EXPECT_EQ(owns(masks[0], x, 100), !connected) << "x = " << x;
    }
    EXPECT_TRUE(owns(masks[0], 130, 100)) << "near person's pixel in the overlap stays its own";
    EXPECT_FALSE(owns(masks[1], 130, 100));
  }
}
