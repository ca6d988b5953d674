// Timestamp association behaves exactly like evo's sync module: tolerance edge, first index on
// ties, unsorted stamps, the offset, and the "match the shorter to the longer" rule.
#include <dynslam/evaluation/Association.h>
#include <dynslam/evaluation/EvaluationError.h>

#include <gtest/gtest.h>

namespace ev = dynslam::evaluation;
using dynslam::core::StampedPose;
using dynslam::core::Trajectory;

namespace {

/// Poses at the given stamps; x holds the index so that tests can see which pose was kept.
Trajectory trajectoryAt(const std::vector<double>& stamps) {
  Trajectory t;
  for (std::size_t i = 0; i < stamps.size(); ++i) {
    StampedPose p;
    p.t = stamps[i];
    p.T_world_body.translation().x() = static_cast<double>(i);
    t.push_back(p);
  }
  return t;
}

std::vector<double> stamps(const Trajectory& t) {
  std::vector<double> s;
  for (const auto& p : t) s.push_back(p.t);
  return s;
}

std::vector<double> evenStamps(int n, double step, double start) {
  std::vector<double> s;
  for (int i = 0; i < n; ++i) s.push_back(start + i * step);
  return s;
}

using Ids = std::vector<std::size_t>;

}  // namespace

TEST(EvalMatchingTimeIndices, ToleranceIsInclusive) {
  // Binary-exact stamps, so that the edge is exactly at max_diff.
  EXPECT_EQ(ev::matchingTimeIndices({0.5}, {0.75}, 0.25).second, Ids{0});
  EXPECT_TRUE(ev::matchingTimeIndices({0.5}, {0.75}, 0.2499999).second.empty());
  // Decimal stamps round as in evo: 1.01 - 1.0 is 0.010000000000000009 > 0.01.
  EXPECT_TRUE(ev::matchingTimeIndices({1.0}, {1.01}, 0.01).second.empty());
  EXPECT_EQ(ev::matchingTimeIndices({0.0}, {0.01}, 0.01).second, Ids{0});
}

TEST(EvalMatchingTimeIndices, TiesTakeTheFirstIndexAndNoSortingIsAssumed) {
  const auto tie = ev::matchingTimeIndices({0.005}, {0.0, 0.01}, 0.006);
  EXPECT_EQ(tie.first, Ids{0});
  EXPECT_EQ(tie.second, Ids{0});
  EXPECT_EQ(ev::matchingTimeIndices({0.0}, {1.0, 0.0, 2.0}).second, Ids{1});
  const auto dup = ev::matchingTimeIndices({1.0, 2.0}, {1.0, 1.0, 2.0});
  EXPECT_EQ(dup.first, (Ids{0, 1}));
  EXPECT_EQ(dup.second, (Ids{0, 2}));
}

TEST(EvalMatchingTimeIndices, OffsetIsAddedToTheSecondStamps) {
  const auto s1 = evenStamps(10, 0.1, 0.0);
  EXPECT_EQ(ev::matchingTimeIndices(s1, evenStamps(10, 0.1, 0.5), 0.01, -0.5).first.size(), 10u);
  EXPECT_EQ(ev::matchingTimeIndices(s1, evenStamps(10, 0.1, -0.5), 0.01, 0.5).first.size(), 10u);
  EXPECT_TRUE(ev::matchingTimeIndices(s1, evenStamps(10, 0.1, 2.0)).first.empty());
  // evo's test_max_diff: 10 stamps at 0.01 + k * 0.1 against 500 stamps every 2 ms.
  const auto dense = evenStamps(500, 2e-3, 0.0);
  EXPECT_EQ(ev::matchingTimeIndices(evenStamps(10, 0.1, 0.01), dense).first.size(), 10u);
  EXPECT_EQ(ev::matchingTimeIndices(dense, evenStamps(10, 0.1, 0.01), 1e-3).first.size(), 10u);
}

TEST(EvalAssociateByTime, ShorterTrajectoryIsMatchedAgainstTheLongerOne) {
  // Reference 2 poses, estimate 4: matching the 2 reference poses gives 2 pairs (matching the
  // 4 estimated poses instead would have given 4 pairs with repeated reference poses).
  const Trajectory ref = trajectoryAt({0.0, 1.0});
  const Trajectory est = trajectoryAt({0.0, 0.002, 1.0, 1.003});
  const auto a = ev::associateByTime(ref, est);
  EXPECT_EQ(a.max_pairs, 2u);
  EXPECT_EQ(stamps(a.first), (std::vector<double>{0.0, 1.0}));
  EXPECT_EQ(stamps(a.second), (std::vector<double>{0.0, 1.0}));
  // Same when the roles are swapped: the order of the outputs follows the inputs.
  const auto b = ev::associateByTime(est, ref);
  EXPECT_EQ(stamps(b.first), (std::vector<double>{0.0, 1.0}));
  EXPECT_EQ(stamps(b.second), (std::vector<double>{0.0, 1.0}));
}

TEST(EvalAssociateByTime, WithEqualLengthsTheSecondCountsAsShorter) {
  // Matching the second's stamps: 0 -> 0, 0.001 -> 0, 5 -> none: 2 pairs, pose 0 of the first
  // used twice. Matching the first's stamps instead would have given 1 pair.
  const auto a =
      ev::associateByTime(trajectoryAt({0.0, 1.0, 2.0}), trajectoryAt({0.0, 0.001, 5.0}));
  ASSERT_EQ(a.first.size(), 2u);
  EXPECT_EQ(stamps(a.first), (std::vector<double>{0.0, 0.0}));
  EXPECT_EQ(stamps(a.second), (std::vector<double>{0.0, 0.001}));
  EXPECT_EQ(a.max_pairs, 3u);
}

TEST(EvalAssociateByTime, OffsetAppliesToTheSecondTrajectoryWhicheverIsLonger) {
  // Second shorter: its stamps + offset are compared with the first's.
  const auto a = ev::associateByTime(trajectoryAt({0.0, 1.0, 2.0, 3.0}), trajectoryAt({10.0, 12.0}),
                                     0.01, -10.0);
  EXPECT_EQ(stamps(a.first), (std::vector<double>{0.0, 2.0}));
  EXPECT_EQ(stamps(a.second), (std::vector<double>{10.0, 12.0}));
  // Second longer: same offset, same pairs; stamps keep their own clocks.
  const auto b = ev::associateByTime(trajectoryAt({0.0, 2.0}),
                                     trajectoryAt({10.0, 11.0, 12.0, 13.0}), 0.01, -10.0);
  EXPECT_EQ(stamps(b.first), (std::vector<double>{0.0, 2.0}));
  EXPECT_EQ(stamps(b.second), (std::vector<double>{10.0, 12.0}));
}

TEST(EvalAssociateByTime, DenseAgainstSparse) {
  const auto a = ev::associateByTime(trajectoryAt(evenStamps(10, 0.1, 0.0)),
                                     trajectoryAt(evenStamps(100, 0.01, 0.0)));
  EXPECT_EQ(a.first.size(), 10u);
  EXPECT_EQ(a.second.size(), 10u);
  for (std::size_t k = 0; k < 10; ++k) EXPECT_NEAR(a.second[k].t, a.first[k].t, 1e-12);
}

TEST(EvalAssociateByTime, NoMatchThrowsNamingTolerance) {
  try {
    ev::associateByTime(trajectoryAt({0.0, 0.1}), trajectoryAt({5.0, 5.1}), 0.01, 0.0);
    FAIL() << "expected EvaluationError";
  } catch (const ev::EvaluationError& e) {
    EXPECT_NE(std::string(e.what()).find("max. time diff 0.01"), std::string::npos) << e.what();
  }
}

TEST(EvalAssociateByIndex, RequiresEqualLengths) {
  EXPECT_THROW(ev::associateByIndex(trajectoryAt({0, 1, 2}), trajectoryAt({0, 1})),
               ev::EvaluationError);
  const auto a = ev::associateByIndex(trajectoryAt({0, 1, 2}), trajectoryAt({5, 6, 7}));
  EXPECT_EQ(a.first.size(), 3u);
  EXPECT_EQ(a.second[2].t, 7.0);
}
