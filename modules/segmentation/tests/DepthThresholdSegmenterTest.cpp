// The thresholds of method.md section 1 on synthetic depth images made of flat planes, where
// every sample's depth is known and the formulas give exact numbers.
//
// The scene (160 x 120): a background wall, an object plane at 2.0 m over x in [40, 100),
// y >= 35, and the detection box B = (40, 20, 60, 60). The candidate box M = (55, 35, 30, 30)
// lies wholly on the object; its 64 samples form an 8 x 8 grid at columns 56, 60, 64, 68, 71,
// 75, 79, 83. The upper half of B, (40, 20, 60, 30), gets an 11 x 6 grid at rows 22, 27, 32
// (wall) and 37, 42, 47 (object), columns 42, 48, 53, 59, 64, 70, 75, 80, 86, 91, 97.
#include <dynslam/segmentation/DepthThresholdSegmenter.h>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>

using namespace dynslam;
using segmentation::DepthThresholdSegmenter;

namespace {

const cv::Rect kBox(40, 20, 60, 60);
const cv::Rect kObject(40, 35, 60, 85);
const cv::Rect kPole(55, 0, 10, 120);  // covers 3 of M's 8 sample columns, 2 of the upper half's 11

cv::Mat scene(float wall, float pole = 0) {
  cv::Mat depth(120, 160, CV_32FC1, cv::Scalar(wall));
  depth(kObject).setTo(2.0f);
  if (pole > 0) depth(kPole).setTo(pole);
  return depth;
}

// The method as method.md states it (the defaults are the shipped configuration).
DepthThresholdSegmenter theMethod() {
  return DepthThresholdSegmenter(segmentation::methodParams());
}

core::Detection detection(const cv::Rect2f& box, const std::string& category = "person") {
  core::Detection d;
  d.box = box;
  d.category = category;
  d.model = category == "car" ? core::MotionModel::Rigid : core::MotionModel::NonRigid;
  return d;
}

}  // namespace

TEST(DepthThresholdSegmenter, NoOccluderAndAFarWallTakeTheMidpointBehind) {
  const cv::Mat depth = scene(5.0f);
  const auto m = theMethod().segmentOne(depth, detection(kBox), 3);
  ASSERT_TRUE(m.valid);
  EXPECT_EQ(m.detection, 3);
  EXPECT_EQ(m.roi, kBox);
  EXPECT_DOUBLE_EQ(m.d_t, 2.0) << "all of M lies on the object: one cluster";
  EXPECT_EQ(m.d_o, 0.0) << "no occluder";
  EXPECT_DOUBLE_EQ(m.t_min, 2.0 - 0.5) << "T_min = d_t - e";
  EXPECT_DOUBLE_EQ(m.d_b, 3.5) << "33 wall samples at 5 m, 33 object samples at 2 m";
  EXPECT_DOUBLE_EQ(m.t_max, (2.0 + 3.5) / 2) << "d_b - d_t > e: T_max = (d_t + d_b) / 2";
  ASSERT_EQ(m.mask.size(), kBox.size());
  EXPECT_EQ(cv::countNonZero(m.mask), 60 * 45) << "exactly the object's pixels in the box";
}

TEST(DepthThresholdSegmenter, AnOccluderInFrontTakesTheMidpointInFront) {
  const cv::Mat depth = scene(5.0f, 1.0f);
  const auto m = theMethod().segmentOne(depth, detection(kBox), 0);
  ASSERT_TRUE(m.valid);
  EXPECT_DOUBLE_EQ(m.d_t, 2.0) << "far cluster: 40 samples at 2 m";
  EXPECT_DOUBLE_EQ(m.d_o, 1.0) << "near cluster: 24 samples on the pole";
  EXPECT_DOUBLE_EQ(m.t_min, 1.5) << "d_t - d_o > e: T_min = (d_t + d_o) / 2";
  // Upper half: 12 pole samples at 1 m, 27 wall at 5 m, 27 object at 2 m; none is 3 sigma out.
  EXPECT_NEAR(m.d_b, 201.0 / 66, 1e-12);
  EXPECT_NEAR(m.t_max, (2.0 + 201.0 / 66) / 2, 1e-12);
  EXPECT_EQ(cv::countNonZero(m.mask), 50 * 45) << "the object without the pole";
  EXPECT_EQ(cv::countNonZero(m.mask((kPole - kBox.tl()) & cv::Rect({}, kBox.size()))), 0);
}

TEST(DepthThresholdSegmenter, ANearClusterWithinEIsNoOccluderAndACloseWallIsNoBackground) {
  // A pole only 0.2 m in front and a wall only 0.3 m behind: both within e = 0.5 m.
  const cv::Mat depth = scene(2.3f, 1.8f);
  const auto m = theMethod().segmentOne(depth, detection(kBox), 0);
  ASSERT_TRUE(m.valid);
  EXPECT_DOUBLE_EQ(m.d_t, 2.0);
  EXPECT_EQ(m.d_o, 0.0) << "d_t - d_o = 0.2 <= e";
  EXPECT_DOUBLE_EQ(m.t_min, 1.5) << "T_min = d_t - e";
  EXPECT_NEAR(m.d_b, (12 * 1.8 + 27 * 2.3 + 27 * 2.0) / 66, 1e-6);
  EXPECT_DOUBLE_EQ(m.t_max, 2.5) << "d_b - d_t <= e: T_max = d_t + e";
  EXPECT_EQ(cv::countNonZero(m.mask), 60 * 60) << "pole, object and wall all lie in [1.5, 2.5]";
}

TEST(DepthThresholdSegmenter, NoDepthBehindMeansNoBackground) {
  // The wall beyond the sensor's range (0): the upper half's valid samples are all on the
  // object, so d_b = d_t and T_max = d_t + e.
  const cv::Mat depth = scene(0.0f);
  const auto m = theMethod().segmentOne(depth, detection(kBox), 0);
  ASSERT_TRUE(m.valid);
  EXPECT_DOUBLE_EQ(m.d_b, 2.0);
  EXPECT_DOUBLE_EQ(m.t_max, 2.5);
  EXPECT_EQ(cv::countNonZero(m.mask), 60 * 45) << "missing depth is never in the mask";
}

TEST(DepthThresholdSegmenter, CarsUseTheirOwnMarginAndNeverTakeMissingDepth) {
  cv::Mat depth = scene(5.0f);
  depth(cv::Rect(45, 60, 10, 10)).setTo(0);  // a hole in the depth, inside the box
  const DepthThresholdSegmenter segmenter = theMethod();
  EXPECT_EQ(segmenter.marginFor(detection(kBox, "car")), 3.0);
  EXPECT_EQ(segmenter.marginFor(detection(kBox, "person")), 0.5);
  auto truck = detection(kBox, "truck");
  truck.model = core::MotionModel::Rigid;
  EXPECT_EQ(segmenter.marginFor(truck), 3.0);
  truck.model = core::MotionModel::NonRigid;
  EXPECT_EQ(segmenter.marginFor(truck), 0.5);
  auto p = segmentation::methodParams();  // other classes take the margin of their motion model
  p.e_car = 2.0;
  p.e_person = 0.4;
  EXPECT_EQ(DepthThresholdSegmenter(p).marginFor(truck), 0.4);
  truck.model = core::MotionModel::Rigid;
  EXPECT_EQ(DepthThresholdSegmenter(p).marginFor(truck), 2.0);

  const auto m = segmenter.segmentOne(depth, detection(kBox, "car"), 0);
  ASSERT_TRUE(m.valid);
  EXPECT_DOUBLE_EQ(m.t_min, 2.0 - 3.0) << "below zero: the mask must still skip depth 0";
  EXPECT_DOUBLE_EQ(m.t_max, 2.0 + 3.0) << "d_b - d_t = 1.5 <= e = 3";
  EXPECT_EQ(cv::countNonZero(m.mask), 60 * 60 - 100);
}

TEST(DepthThresholdSegmenter, TooFewValidDepthsInTheCandidateBoxGiveNoMask) {
  cv::Mat depth = scene(5.0f);
  depth(cv::Rect(58, 35, 27, 30)).setTo(0);  // M keeps its first sample column (x = 56) only
  const DepthThresholdSegmenter segmenter = theMethod();  // needs 25 % of 64 = 16 samples
  const auto m = segmenter.segmentOne(depth, detection(kBox), 1);
  EXPECT_FALSE(m.valid) << "8 valid samples";
  EXPECT_TRUE(m.mask.empty());
  EXPECT_EQ(m.roi, kBox);
  EXPECT_EQ(m.d_t, 0.0);

  depth(cv::Rect(58, 35, 4, 30)).setTo(2.0f);  // columns 56 and 60: 16 samples
  EXPECT_TRUE(segmenter.segmentOne(depth, detection(kBox), 1).valid);
  auto strict = segmentation::methodParams();
  strict.min_valid_fraction = 0.3;
  EXPECT_FALSE(DepthThresholdSegmenter(strict).segmentOne(depth, detection(kBox), 1).valid);
}

TEST(DepthThresholdSegmenter, ABoxPartlyOutsideTheImageIsClippedFirst) {
  cv::Mat depth(120, 160, CV_32FC1, cv::Scalar(5.0f));
  depth(cv::Rect(0, 35, 50, 85)).setTo(2.0f);  // an object cut by the image's left edge
  const auto m = theMethod().segmentOne(depth, detection({-30, 20, 90, 60}), 0);
  EXPECT_EQ(m.roi, cv::Rect(0, 20, 60, 60));
  ASSERT_TRUE(m.valid);
  EXPECT_EQ(m.mask.size(), m.roi.size());
  EXPECT_DOUBLE_EQ(m.d_t, 2.0);
  EXPECT_EQ(cv::countNonZero(m.mask), 50 * 45);

  const auto outside = theMethod().segmentOne(depth, detection({170, 0, 20, 20}), 0);
  EXPECT_FALSE(outside.valid);
  EXPECT_TRUE(outside.roi.empty());
}

TEST(DepthThresholdSegmenter, RejectsADepthImageNotInMetres) {
  const cv::Mat mm(120, 160, CV_16UC1, cv::Scalar(2000));
  EXPECT_THROW(theMethod().segmentOne(mm, detection(kBox), 0), std::invalid_argument);
  EXPECT_THROW(theMethod().segment(mm, {detection(kBox)}), std::invalid_argument);
}

TEST(DepthThresholdSegmenter, TheLargerClusterVariantTakesTheMajorityOfTheCandidateBox) {
  // A pole covering 5 of M's 8 sample columns: the method takes the far cluster (the object
  // behind); the non-default variant object_cluster = larger takes the pole.
  cv::Mat depth = scene(5.0f);
  depth(cv::Rect(55, 0, 17, 120)).setTo(1.0f);
  const auto method = theMethod().segmentOne(depth, detection(kBox), 0);
  EXPECT_DOUBLE_EQ(method.d_t, 2.0);
  EXPECT_DOUBLE_EQ(method.d_o, 1.0);
  auto p = segmentation::methodParams();
  p.object_cluster = segmentation::ObjectCluster::Larger;
  const auto larger = DepthThresholdSegmenter(p).segmentOne(depth, detection(kBox), 0);
  EXPECT_DOUBLE_EQ(larger.d_t, 1.0) << "40 samples on the pole, 24 on the object";
  EXPECT_EQ(larger.d_o, 0.0) << "nothing in front of the pole";
  EXPECT_DOUBLE_EQ(larger.t_min, 0.5);
}

// max_height_person (not the method): a box 60 px high, seen with fy = 100 px, holds nothing
// of a person at most 2.2 m tall beyond 2.2 * 100 / 60 = 3.67 m. A person at 2 m covers 5 of
// M's 8 sample columns and a wall at 5 m the rest: the method's far cluster is the wall; with
// the bound the wall's samples are background and the person is the object.
TEST(DepthThresholdSegmenter, MaxHeightLeavesTheWallBeyondTheTallestPersonOut) {
  cv::Mat depth(120, 160, CV_32FC1, cv::Scalar(5.0f));
  depth(cv::Rect(55, 0, 17, 120)).setTo(2.0f);
  auto p = segmentation::methodParams();
  EXPECT_DOUBLE_EQ(DepthThresholdSegmenter(p).segment(depth, {detection(kBox)}, {}, 100)[0].d_t,
                   5.0);
  p.max_height_person = 2.2;
  const DepthThresholdSegmenter bounded(p);
  EXPECT_NEAR(bounded.maxDepthFor(detection(kBox), 100), 2.2 * 100 / 60, 1e-9);
  const auto m = bounded.segment(depth, {detection(kBox)}, {}, 100);
  ASSERT_EQ(m.size(), 1u);
  EXPECT_DOUBLE_EQ(m[0].d_t, 2.0);
  EXPECT_LE(m[0].t_max, 2.2 * 100 / 60);
  EXPECT_EQ(cv::countNonZero(m[0].mask), 17 * 60) << "the person's pixels, none of the wall";
  EXPECT_DOUBLE_EQ(bounded.segmentOne(depth, detection(kBox), 0, 0, 100).d_t, 2.0);
  EXPECT_DOUBLE_EQ(bounded.segment(depth, {detection(kBox)})[0].d_t, 5.0) << "no fy: no bound";
  EXPECT_DOUBLE_EQ(bounded.segment(depth, {detection(kBox, "car")}, {}, 100)[0].d_t, 5.0)
      << "cars are not bounded";
  const auto wallOnly = bounded.segment(depth, {detection({100, 20, 40, 60})}, {}, 100);
  EXPECT_TRUE(wallOnly[0].valid) << "nothing at a possible depth: every sample stays";
  EXPECT_DOUBLE_EQ(wallOnly[0].d_t, 5.0);
}

// object_depth = mask_median (not the method): d_t is the median depth of the final mask, not
// the mean of the candidate box's cluster. A person-sized box on one body whose upper 60 % is
// at 2.0 m and lower 40 % at 2.4 m (a leg stepping back): M's rows 20-59 hold 2.0 m down to
// row 47, so 2-means splits 2.0 / 2.4, and the method's far cluster says 2.4 m; all of the
// box is within e of it, and most of the mask is at 2.0 m.
TEST(DepthThresholdSegmenter, MaskMedianDepthIsTheMedianOfTheFinalMask) {
  cv::Mat depth(120, 160, CV_32FC1, cv::Scalar(0.0f));
  const cv::Rect box(40, 0, 40, 80);
  depth(cv::Rect(40, 0, 40, 48)).setTo(2.0f);
  depth(cv::Rect(40, 48, 40, 32)).setTo(2.4f);
  auto p = segmentation::methodParams();
  const auto method = DepthThresholdSegmenter(p).segment(depth, {detection(box)});
  ASSERT_EQ(method.size(), 1u);
  EXPECT_NEAR(method[0].d_t, 2.4, 1e-6) << "the far cluster's mean";
  p.object_depth = segmentation::ObjectDepth::MaskMedian;
  const auto median = DepthThresholdSegmenter(p).segment(depth, {detection(box)});
  ASSERT_EQ(median.size(), 1u);
  EXPECT_EQ(cv::countNonZero(median[0].mask), 40 * 80) << "the mask itself is the method's";
  EXPECT_NEAR(median[0].d_t, 2.0, 1e-6) << "60 % of the mask is at 2.0 m";
  EXPECT_EQ(median[0].t_min, method[0].t_min) << "the thresholds stay the method's";
  EXPECT_EQ(median[0].t_max, method[0].t_max);
}

TEST(DepthThresholdSegmenter, MaskMedianDepthSkipsPixelsWithoutDepthAndEmptyMasks) {
  cv::Mat depth(10, 10, CV_32FC1, cv::Scalar(3.0f));
  depth(cv::Rect(0, 0, 10, 4)).setTo(1.0f);
  depth(cv::Rect(0, 8, 10, 2)).setTo(0.0f);  // no depth: never counted
  core::ObjectMask m;
  m.roi = cv::Rect(0, 0, 10, 10);
  m.mask = cv::Mat(10, 10, CV_8UC1, cv::Scalar(255));
  m.valid = true;
  EXPECT_EQ(segmentation::maskMedianDepth(m, depth, 1), 3.0f)
      << "40 px at 1 m, 40 at 3 m: upper median";
  m.mask(cv::Rect(0, 4, 10, 6)).setTo(0);
  EXPECT_EQ(segmentation::maskMedianDepth(m, depth, 1), 1.0f);
  m.mask.setTo(0);
  EXPECT_EQ(segmentation::maskMedianDepth(m, depth, 1), 0.0) << "empty: 0, the caller keeps d_t";
  m.valid = false;
  EXPECT_EQ(segmentation::maskMedianDepth(m, depth, 1), 0.0);
}
