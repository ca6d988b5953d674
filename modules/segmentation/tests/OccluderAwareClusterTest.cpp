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
  auto p = segmentation::methodParams();
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
  EXPECT_NEAR(method[0].d_alt, 2.0, 1e-6) << "the cluster not taken";
  const auto variant = segmenter(ObjectCluster::OccluderAware).segment(depth, {person(box)});
  ASSERT_TRUE(variant[0].valid);
  EXPECT_NEAR(variant[0].d_t, 2.0, 1e-6);
  EXPECT_EQ(variant[0].d_o, 0.0) << "no occluder";
  EXPECT_NEAR(variant[0].d_alt, 5.0, 1e-6);
  EXPECT_GT(cv::countNonZero(variant[0].mask), 0.9 * (box.area() - 12 * 100));
}

TEST(OccluderAwareCluster, AnExpectedDepthChoosesTheCluster) {
  // segment's expectedDepth (a track's depth) overrides both rules' choice of cluster.
  const cv::Rect box(100, 20, 60, 200);
  const cv::Mat depth = walkerWithGap(box);
  for (const auto c : {ObjectCluster::Far, ObjectCluster::OccluderAware}) {
    EXPECT_NEAR(segmenter(c).segment(depth, {person(box)}, {2.2})[0].d_t, 2.0, 1e-6);
    EXPECT_NEAR(segmenter(c).segment(depth, {person(box)}, {4.0})[0].d_t, 5.0, 1e-6);
  }
}

TEST(OccluderAwareCluster, AnExpectedDepthFarFromBothClustersFindsItsOwnSurface) {
  // expected_depth_band (not the method): a person 2.2 m away of whom only the head shows (the
  // box's top fifth), the rest hidden by an occluder at 1.2 m that fills the candidate box and
  // the wall at 5 m beside it. 2-means sees the occluder and the wall; the track's 2.2 m is
  // within 15 % of neither, and the whole box holds samples at 2.2 m: they are the object.
  const cv::Rect box(100, 20, 60, 200);
  cv::Mat depth(240, 320, CV_32FC1, cv::Scalar(5.0f));
  depth(cv::Rect(115, 20, 30, 40)).setTo(2.2f);
  depth(cv::Rect(90, 60, 80, 180)).setTo(1.2f);
  depth(cv::Rect(100, 60, 8, 160)).setTo(5.0f);
  const auto without = segmenter(ObjectCluster::OccluderAware).segment(depth, {person(box)}, {2.2});
  EXPECT_NEAR(without[0].d_t, 1.2, 0.01) << "the cluster nearer 2.2 m in ratio: the occluder";
  auto p = segmentation::methodParams();
  p.object_cluster = ObjectCluster::OccluderAware;
  p.expected_depth_band = 0.1;
  const auto with = DepthThresholdSegmenter(p).segment(depth, {person(box)}, {2.2});
  ASSERT_TRUE(with[0].valid);
  EXPECT_NEAR(with[0].d_t, 2.2, 1e-5);
  EXPECT_NEAR(with[0].d_o, 1.2, 0.01) << "the occluder in front";
  EXPECT_EQ(cv::countNonZero(with[0].mask), 30 * 40) << "the head, not the occluder or the wall";
  EXPECT_NEAR(DepthThresholdSegmenter(p).segment(depth, {person(box)}, {1.25})[0].d_t, 1.2, 0.01)
      << "a cluster within 15 %: the band is not needed";
  EXPECT_NEAR(DepthThresholdSegmenter(p).segment(depth, {person(box)}, {3.3})[0].d_t, 1.2, 0.01)
      << "nothing within 10 % of 3.3 m: the candidate box's own (only) cluster";
}

namespace {

/// A's surface (1.2 m) over A's box and B's own (2.4 m) where B shows, before a wall at 5 m;
/// A and B segmented with occluder_aware and the connected overlap rule, without and with
/// retry_taken_surface.
struct TakenSurface {
  std::vector<core::ObjectMask> without, with;
};
TakenSurface segmentTakenSurface(const cv::Rect& a, const cv::Rect& b, const cv::Rect& bShows,
                                 const std::vector<double>& expected, double fy, double maxHeight) {
  cv::Mat depth(240, 320, CV_32FC1, cv::Scalar(5.0f));
  depth(a).setTo(1.2f);
  depth(bShows).setTo(2.4f);
  auto p = segmentation::methodParams();
  p.object_cluster = ObjectCluster::OccluderAware;
  p.overlap_rule = segmentation::OverlapRule::Connected;
  p.max_height_person = maxHeight;
  TakenSurface out;
  out.without = DepthThresholdSegmenter(p).segment(depth, {person(a), person(b)}, expected, fy);
  p.retry_taken_surface = true;
  out.with = DepthThresholdSegmenter(p).segment(depth, {person(a), person(b)}, expected, fy);
  return out;
}

}  // namespace

TEST(OccluderAwareCluster, AMaskWhoseSurfaceAnotherTookIsCutOnWhatLiesBehindIt) {
  // retry_taken_surface (not the method): B, whose own surface (2.4 m) shows beside A (1.2 m),
  // is cut on A's surface (here because its expected depth says so, and B's box reaching lower
  // in the image says A does not stand in front; in the pipeline, a cluster choice gone wrong),
  // and the overlap step gives all of those pixels to A: it is cut again on what its box shows
  // more than e / 2 behind A's surface.
  const auto r = segmentTakenSurface({100, 20, 60, 200}, {130, 20, 60, 210}, {160, 20, 30, 200},
                                     {0, 1.2}, 0, 0);
  ASSERT_EQ(r.without.size(), 2u);
  EXPECT_EQ(cv::countNonZero(r.without[1].mask), 0);
  EXPECT_NEAR(r.without[1].d_t, 1.2, 1e-5) << "A's surface";
  ASSERT_EQ(r.with.size(), 2u);
  EXPECT_NEAR(r.with[1].d_t, 2.4, 1e-5);
  EXPECT_NEAR(r.with[1].d_o, 1.2, 1e-5) << "A in front";
  EXPECT_EQ(cv::countNonZero(r.with[1].mask), 30 * 200) << "B's own surface";
  EXPECT_EQ(cv::countNonZero(r.with[0].mask), 60 * 200) << "A keeps its own";
}

TEST(OccluderAwareCluster, AMaskLeftOnTheFlankOfTheBodyInFrontIsCutBehindIt) {
  // A's front is at 1.2 m, its flank (a strip of its box) at 1.38 m. B (expected near the
  // flank) is cut on A's front and flank; the overlap step gives it the flank only, under a
  // fifth of its pixels, and its d_t (the mask's median, as in params/sim_*.ini) becomes the
  // flank's: 15 % behind A's, beyond kSameSurface, but nearer than e / 2 to A's front. Counted
  // as A's body, B is cut again behind it: its own surface at 2.4 m.
  cv::Mat depth(240, 320, CV_32FC1, cv::Scalar(5.0f));
  const cv::Rect a(100, 20, 60, 200), b(130, 20, 60, 200);
  depth(a).setTo(1.2f);
  depth(cv::Rect(156, 20, 4, 200)).setTo(1.38f);
  depth(cv::Rect(160, 20, 30, 200)).setTo(2.4f);
  auto p = segmentation::methodParams();
  p.object_cluster = ObjectCluster::OccluderAware;
  p.overlap_rule = segmentation::OverlapRule::Connected;
  p.object_depth = segmentation::ObjectDepth::MaskMedian;
  p.retry_taken_surface = true;
  const auto masks = DepthThresholdSegmenter(p).segment(depth, {person(a), person(b)}, {0, 1.38});
  ASSERT_EQ(masks.size(), 2u);
  EXPECT_NEAR(masks[1].d_t, 2.4, 1e-5) << "B behind A";
  EXPECT_EQ(cv::countNonZero(masks[1].mask), 30 * 200) << "B's own surface";
  EXPECT_NEAR(masks[0].d_t, 1.2, 0.2) << "A";
}

TEST(OccluderAwareCluster, AHiddenPersonsHeadAboveItsOccluderIsFoundBehindItsSurface) {
  // Only the head of B (2.4 m) shows, above A (1.2 m), which fills B's candidate box: B's
  // 2-means sees A's surface alone, the overlap step gives it to A, and B is cut again on the
  // points of its whole box behind A's surface and nearer than a 2.2 m person could fill its
  // 220 px box at fy = 300 px (3 m): the head, not the wall (5 m).
  const auto r =
      segmentTakenSurface({90, 60, 100, 180}, {110, 20, 60, 220}, {125, 20, 30, 40}, {}, 300, 2.2);
  ASSERT_EQ(r.without.size(), 2u);
  EXPECT_NEAR(r.without[1].d_t, 1.2, 1e-5) << "A's surface";
  EXPECT_EQ(cv::countNonZero(r.without[1].mask), 0);
  ASSERT_EQ(r.with.size(), 2u);
  EXPECT_NEAR(r.with[1].d_t, 2.4, 1e-5);
  EXPECT_NEAR(r.with[1].d_o, 1.2, 1e-5);
  EXPECT_EQ(cv::countNonZero(r.with[1].mask), 30 * 40) << "the head";
  EXPECT_NEAR(r.with[0].d_t, 1.2, 1e-5) << "A unchanged";
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

namespace {

/// A wall 6 m away with the given people (box, body columns, depth) drawn in order (later in
/// front); every box reaches the image's bottom edge, as people close to the camera do.
struct Body {
  cv::Rect box;
  int bodyX0, bodyX1;
  float depth;
};
cv::Mat peopleCutOffAtTheBottom(const std::vector<Body>& people) {
  cv::Mat depth(240, 320, CV_32FC1, cv::Scalar(6.0f));
  for (const auto& p : people)
    depth(cv::Rect(p.bodyX0, p.box.y, p.bodyX1 - p.bodyX0, p.box.height)).setTo(p.depth);
  return depth;
}

/// occluder_aware masks of the two people `a` and `b`, in that order.
std::vector<core::ObjectMask> segmentPair(const cv::Mat& depth, const Body& a, const Body& b) {
  return segmenter(ObjectCluster::OccluderAware).segment(depth, {person(a.box), person(b.box)});
}

}  // namespace

TEST(OccluderAwareCluster, APersonInFrontIsTheOccluderAlsoWhenBothAreCutOffAtTheBottom) {
  // Both boxes end at the image's bottom edge, so their bottoms cannot tell which stands in
  // front; A's surface continues outside B's box and B's near samples all lie in A's box.
  const Body a{{60, 0, 120, 240}, 60, 180, 1.2f}, b{{140, 40, 80, 200}, 140, 220, 2.5f};
  const cv::Mat depth = peopleCutOffAtTheBottom({b, a});
  const auto masks = segmentPair(depth, a, b);
  EXPECT_NEAR(masks[0].d_t, 1.2, 1e-6) << "A";
  EXPECT_NEAR(masks[1].d_t, 2.5, 1e-6) << "B, behind A";
  EXPECT_NEAR(masks[1].d_o, 1.2, 1e-6);
}

TEST(OccluderAwareCluster, PeopleSideBySideAtOneDepthKeepTheirOwnDepth) {
  // A (wall between the legs in its candidate box) and B beside it at the same depth, B's box
  // overlapping A's candidate box: A's near samples are mostly outside B's box, so B is not
  // A's occluder and A is not taken for the wall.
  const Body a{{40, 0, 100, 240}, 50, 110, 1.5f}, b{{100, 0, 100, 240}, 150, 190, 1.5f};
  cv::Mat depth = peopleCutOffAtTheBottom({a, b});
  depth(cv::Rect(75, 120, 10, 120)).setTo(6.0f);  // between A's legs
  const auto masks = segmentPair(depth, a, b);
  EXPECT_NEAR(masks[0].d_t, 1.5, 1e-6) << "A";
  EXPECT_EQ(masks[0].d_o, 0.0) << "A has no occluder";
}

TEST(OccluderAwareCluster, BehindAnOccluderThePersonIsNotBlurredWithTheWall) {
  // B 3 m away, half hidden by A 1 m away, the wall 4.2 m away showing beside B in B's
  // candidate box: the far cluster mixes B and the wall; split again, B is its near part.
  const Body a{{60, 0, 120, 240}, 60, 180, 1.0f}, b{{140, 40, 80, 200}, 185, 215, 3.0f};
  cv::Mat depth = peopleCutOffAtTheBottom({b, a});
  depth.setTo(4.2f, depth == 6.0f);
  const auto masks = segmentPair(depth, a, b);
  EXPECT_NEAR(masks[1].d_t, 3.0, 1e-6) << "B";
  EXPECT_NEAR(masks[1].d_o, 1.0, 1e-6) << "A";
}

TEST(OccluderAwareCluster, AnOccluderHidingTheWholeCandidateBoxLeavesThePersonBesideIt) {
  // A 1 m away covers all of B's candidate box but for a gap under its arm, where the wall
  // shows; B, 2.5 m away, shows only beside A. The candidate's far cluster is that bit of wall;
  // B's depth is found in B's box outside A's.
  const Body a{{100, 0, 140, 240}, 100, 240, 1.0f}, b{{150, 40, 100, 200}, 150, 250, 2.5f};
  cv::Mat depth = peopleCutOffAtTheBottom({b, a});
  depth(cv::Rect(198, 100, 8, 40)).setTo(6.0f);  // under A's arm
  const auto masks = segmentPair(depth, a, b);
  EXPECT_NEAR(masks[1].d_t, 2.5, 1e-6) << "B";
  EXPECT_NEAR(masks[1].d_o, 1.0, 1e-6) << "A";
  EXPECT_GT(cv::countNonZero(masks[1].mask), 0);
}

TEST(OccluderAwareCluster, APersonBesideWhoseBoxCoversTheCandidateBoxIsNoOccluder) {
  // A and B side by side at 1.5 m, B's box covering A's candidate box and reaching outside A's;
  // the wall shows between A's legs. A's own surface shows in A's box outside B's, so B does
  // not hide A, and A is not taken for the wall.
  const Body a{{120, 0, 80, 240}, 120, 200, 1.5f}, b{{140, 0, 120, 240}, 140, 260, 1.5f};
  cv::Mat depth = peopleCutOffAtTheBottom({a, b});
  depth(cv::Rect(157, 150, 6, 90)).setTo(6.0f);  // between A's legs
  const auto masks = segmentPair(depth, a, b);
  EXPECT_NEAR(masks[0].d_t, 1.5, 1e-6) << "A";
  EXPECT_EQ(masks[0].d_o, 0.0) << "A has no occluder";
}

TEST(OccluderAwareCluster, ABoxEndingAFewPixelsAboveTheBottomEdgeCountsAsCutOff) {
  // A, 1 m away, is cut off by the bottom edge, but a detector's box for it ends 3 px above the
  // edge (GroundTruthDetector's jitter); B, 1.7 m away and mostly hidden behind A, has a box
  // reaching the edge. Lower in the image does not mean nearer here: A is not B's to hide.
  const Body a{{100, 0, 80, 237}, 100, 180, 1.0f}, b{{150, 30, 80, 210}, 150, 230, 1.7f};
  cv::Mat depth = peopleCutOffAtTheBottom({b, a});
  depth(cv::Rect(137, 120, 6, 120)).setTo(6.0f);  // between A's legs
  const auto masks = segmentPair(depth, a, b);
  EXPECT_NEAR(masks[0].d_t, 1.0, 1e-6) << "A";
  EXPECT_EQ(masks[0].d_o, 0.0) << "A has no occluder";
}

TEST(OccluderAwareCluster, APersonWhoseCandidateBoxLiesInsideTheOthersBoxIsInFrontWhenTaller) {
  // A 1.2 m away, its box reaching the top edge, stands before B 2.4 m away, whose box (top at
  // y 30) holds all of A's candidate box: B shows only in the strips beside A (the left one
  // reaching into B's candidate box). Both boxes end at the bottom edge, so neither the bottoms
  // nor A's surface outside B's box tell which is in front.
  const Body front{{160, 0, 50, 240}, 160, 210, 1.2f}, hidden{{120, 30, 110, 210}, 120, 230, 2.4f};
  const cv::Mat depth = peopleCutOffAtTheBottom({hidden, front});
  const auto masks = segmentPair(depth, front, hidden);
  EXPECT_NEAR(masks[0].d_t, 1.2, 1e-6) << "A";
  EXPECT_EQ(masks[0].d_o, 0.0) << "A has no occluder";
  EXPECT_NEAR(masks[1].d_t, 2.4, 1e-6) << "B, whose box reaches less high, is behind A";
  EXPECT_NEAR(masks[1].d_o, 1.2, 1e-6);
}

TEST(OccluderAwareCluster, ATrackDepthOnTheOccludersSurfaceDoesNotUndoTheOccluder) {
  // B's track followed A's surface (1.25 m): of B's clusters the one nearer that depth is A's,
  // but A was seen standing in front (its surface continues outside B's box), so B keeps the
  // surface behind it.
  const Body a{{60, 0, 120, 240}, 60, 180, 1.2f}, b{{140, 40, 80, 200}, 140, 220, 2.5f};
  const cv::Mat depth = peopleCutOffAtTheBottom({b, a});
  const auto masks = segmenter(ObjectCluster::OccluderAware)
                         .segment(depth, {person(a.box), person(b.box)}, {1.2, 1.25});
  EXPECT_NEAR(masks[0].d_t, 1.2, 1e-6) << "A";
  EXPECT_NEAR(masks[1].d_t, 2.5, 1e-6) << "B";
  EXPECT_NEAR(masks[1].d_o, 1.2, 1e-6);
}

TEST(OccluderAwareCluster, TwoPeopleHidingAPersonTogetherAreItsOccludersWithJointOccluders) {
  // C (2.4 m) stands between and behind A (1.2 m) and B (1.3 m); each covers about half of C's
  // candidate box, C shows in the gap between them. All boxes reach the bottom edge, so the
  // bottoms say nothing, and neither A nor B alone holds 90 % of C's near samples: C takes
  // their surface as its own. joint_occluders (not the method) tests A and B together.
  const Body a{{60, 50, 105, 190}, 60, 165, 1.2f}, b{{180, 55, 100, 185}, 180, 280, 1.3f},
      c{{120, 30, 100, 210}, 120, 220, 2.4f};
  const cv::Mat depth = peopleCutOffAtTheBottom({c, a, b});
  const std::vector<core::Detection> boxes = {person(a.box), person(b.box), person(c.box)};
  auto p = segmentation::methodParams();
  p.object_cluster = ObjectCluster::OccluderAware;
  const auto without = DepthThresholdSegmenter(p).segment(depth, boxes);
  ASSERT_EQ(without.size(), 3u);
  EXPECT_LT(without[2].d_t, 1.35) << "C on A's and B's surface";
  p.joint_occluders = true;
  const auto with = DepthThresholdSegmenter(p).segment(depth, boxes);
  ASSERT_EQ(with.size(), 3u);
  EXPECT_NEAR(with[2].d_t, 2.4, 1e-5) << "C behind A and B";
  EXPECT_GT(with[2].d_o, 1.15);
  EXPECT_LT(with[2].d_o, 1.35);
  EXPECT_NEAR(with[0].d_t, 1.2, 1e-5) << "A unchanged";
  EXPECT_NEAR(with[1].d_t, 1.3, 1e-5) << "B unchanged";
}

TEST(OccluderAwareCluster, JointOccludersDoNotHideAPersonStandingBetweenThemAtTheirDepth) {
  // A, B and C side by side at 1.5 m, C's box overlapping both of theirs, the wall between C's
  // legs: C's surface shows in C's box outside A's and B's boxes, so they do not hide it.
  const Body a{{40, 0, 100, 240}, 40, 120, 1.5f}, b{{200, 0, 100, 240}, 220, 300, 1.5f},
      c{{100, 0, 120, 240}, 120, 220, 1.5f};
  cv::Mat depth = peopleCutOffAtTheBottom({a, b, c});
  depth(cv::Rect(165, 150, 10, 90)).setTo(6.0f);  // between C's legs
  auto p = segmentation::methodParams();
  p.object_cluster = ObjectCluster::OccluderAware;
  p.joint_occluders = true;
  const auto masks =
      DepthThresholdSegmenter(p).segment(depth, {person(a.box), person(b.box), person(c.box)});
  ASSERT_EQ(masks.size(), 3u);
  EXPECT_NEAR(masks[2].d_t, 1.5, 1e-6) << "C";
  EXPECT_EQ(masks[2].d_o, 0.0) << "C has no occluder";
}
