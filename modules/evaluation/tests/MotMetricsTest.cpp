#include <dynslam/evaluation/EvaluationError.h>
#include <dynslam/evaluation/MotMetrics.h>

#include <gtest/gtest.h>

using namespace dynslam::evaluation;

namespace {

MotTruthBox truth(int id, double x, bool counted = true) {
  return {id, cv::Rect2d(x, 0, 10, 10), counted};
}
MotHypothesisBox hyp(int id, double x) { return {id, cv::Rect2d(x, 0, 10, 10)}; }

}  // namespace

TEST(EvaluationMotMetrics, PerfectTracking) {
  std::vector<MotFrame> frames;
  for (int k = 0; k < 5; ++k)
    frames.push_back({{truth(1, k), truth(2, 50 + k)}, {hyp(7, k), hyp(8, 50 + k)}});
  const MotResult r = evaluateMot(frames);
  EXPECT_EQ(r.truth_boxes, 10u);
  EXPECT_EQ(r.matches, 10u);
  EXPECT_DOUBLE_EQ(r.mota, 1.0);
  EXPECT_DOUBLE_EQ(r.motp, 1.0);
  EXPECT_DOUBLE_EQ(r.idf1, 1.0);
  EXPECT_EQ(r.id_switches, 0u);
  EXPECT_EQ(r.truth_ids, 2u);
  EXPECT_EQ(r.hypothesis_ids, 2u);
}

TEST(EvaluationMotMetrics, AnIdSwitch) {
  // Truth 1 is tracked by hypothesis 10 for three frames, then by 11 for two.
  std::vector<MotFrame> frames;
  for (int k = 0; k < 5; ++k) frames.push_back({{truth(1, 0)}, {hyp(k < 3 ? 10 : 11, 0)}});
  const MotResult r = evaluateMot(frames);
  EXPECT_EQ(r.id_switches, 1u);
  EXPECT_DOUBLE_EQ(r.mota, 1.0 - 1.0 / 5);
  EXPECT_EQ(r.idtp, 3u);  // truth 1 <-> hypothesis 10
  EXPECT_EQ(r.idfn, 2u);
  EXPECT_EQ(r.idfp, 2u);
  EXPECT_DOUBLE_EQ(r.idf1, 6.0 / 10);
  EXPECT_EQ(r.hypothesis_ids, 2u);
}

TEST(EvaluationMotMetrics, MissesFalsePositivesAndAFragmentation) {
  // Four frames of truth 1; the tracker misses it in frame 1 and adds a box on nothing in
  // frame 2; a box shifted by 5 px (IoU 1/3 < 0.5) in frame 3 is a miss plus a false positive.
  std::vector<MotFrame> frames = {
      {{truth(1, 0)}, {hyp(4, 0)}},
      {{truth(1, 0)}, {}},
      {{truth(1, 0)}, {hyp(4, 0), hyp(9, 100)}},
      {{truth(1, 0)}, {hyp(4, 5)}},
  };
  const MotResult r = evaluateMot(frames);
  EXPECT_EQ(r.matches, 2u);
  EXPECT_EQ(r.misses, 2u);
  EXPECT_EQ(r.false_positives, 2u);
  EXPECT_EQ(r.fragmentations, 1u);
  EXPECT_EQ(r.id_switches, 0u);
  EXPECT_DOUBLE_EQ(r.mota, 1.0 - 4.0 / 4);
  EXPECT_EQ(r.idtp, 2u);
  EXPECT_DOUBLE_EQ(r.idf1, 4.0 / (4 + 4));
}

TEST(EvaluationMotMetrics, ContinuityKeepsAnEstablishedPair) {
  // Frame 0: hypothesis 1 on truth A. Frame 1: B appears 2 px right of A; hypothesis 1 now sits
  // on B exactly (IoU 2/3 with A) and hypothesis 2 on A. The best IoU total would swap A's
  // identity; CLEAR-MOT keeps A-1 as it still overlaps enough.
  std::vector<MotFrame> frames = {
      {{truth(100, 0)}, {hyp(1, 0)}},
      {{truth(100, 0), truth(200, 2)}, {hyp(1, 2), hyp(2, 0)}},
  };
  const MotResult r = evaluateMot(frames);
  EXPECT_EQ(r.matches, 3u);
  EXPECT_EQ(r.id_switches, 0u);
  EXPECT_NEAR(r.motp, (1 + 2 * (80.0 / 120)) / 3, 1e-12);
}

TEST(EvaluationMotMetrics, DontCareTruthsAreNeitherDemandedNorFalse) {
  // Truth 2 is hidden (not counted) in frames 1-2: the tracker's coasting box on it is ignored
  // in frame 1, and missing it in frame 2 is no miss.
  std::vector<MotFrame> frames = {
      {{truth(1, 0), truth(2, 50)}, {hyp(1, 0), hyp(2, 50)}},
      {{truth(1, 0), truth(2, 50, false)}, {hyp(1, 0), hyp(2, 50)}},
      {{truth(1, 0), truth(2, 50, false)}, {hyp(1, 0)}},
      {{truth(1, 0), truth(2, 50)}, {hyp(1, 0), hyp(2, 50)}},
  };
  const MotResult r = evaluateMot(frames);
  EXPECT_EQ(r.truth_boxes, 6u);
  EXPECT_EQ(r.matches, 6u);
  EXPECT_EQ(r.ignored_hypotheses, 1u);
  EXPECT_EQ(r.false_positives, 0u);
  EXPECT_EQ(r.misses, 0u);
  EXPECT_DOUBLE_EQ(r.mota, 1.0);
  EXPECT_EQ(r.hypothesis_boxes, 6u);
  EXPECT_DOUBLE_EQ(r.idf1, 1.0);
}

TEST(EvaluationMotMetrics, IdentityPairsTheLongestSharedStretch) {
  // Truth 1 is followed by hypothesis 5 for 2 frames and 6 for 4; truth 2 by 6 for 1 frame and
  // 7 for 3. The best one-to-one pairing is 1-6 (4) and 2-7 (3): IDTP 7 of 10.
  std::vector<MotFrame> frames;
  const int first[] = {5, 5, 6, 6, 6, 6}, second[] = {6, 7, 7, 7};
  for (int k = 0; k < 6; ++k) {
    MotFrame f{{truth(1, 0)}, {hyp(first[k], 0)}};
    if (k < 4) {
      f.truth.push_back(truth(2, 50));
      f.hypotheses.push_back(hyp(second[k], 50));
    }
    frames.push_back(f);
  }
  const MotResult r = evaluateMot(frames);
  EXPECT_EQ(r.idtp, 7u);
  EXPECT_DOUBLE_EQ(r.idf1, 14.0 / 20);
  EXPECT_EQ(r.id_switches, 2u);
  EXPECT_EQ(r.hypothesis_ids, 3u);
}

TEST(EvaluationMotMetrics, RejectsUndefinedInput) {
  EXPECT_THROW(evaluateMot({}), EvaluationError);
  EXPECT_THROW(evaluateMot({{{truth(1, 0, false)}, {}}}), EvaluationError);
  MotOptions bad;
  bad.min_iou = 0;
  EXPECT_THROW(evaluateMot({{{truth(1, 0)}, {}}}, bad), EvaluationError);
}
