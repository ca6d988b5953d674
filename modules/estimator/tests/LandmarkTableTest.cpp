// LandmarkTable::removeKeyframe: what becomes of a landmark whose anchor keyframe leaves the
// window (LandmarkReanchoring in SlidingWindow.h).
#include <dynslam/estimator/LandmarkTable.h>

#include <gtest/gtest.h>

using namespace dynslam::estimator;

namespace {

/// One landmark (id 7) anchored at keyframe 1 and seen again in keyframes 2, 3 and 4.
LandmarkTable seenFourTimes() {
  LandmarkTable table;
  for (std::int64_t kf = 1; kf <= 4; ++kf)
    table.observe(7, kf, {Eigen::Vector2d(100.0 + kf, 50.0), 2.0 + 0.1 * kf, {}}, 3.0);
  return table;
}

/// The depth the landmark's new anchor is given (the caller's estimate): 10 + that keyframe.
double depthAt(const Landmark&, std::int64_t keyframe) { return 1.0 / (10.0 + double(keyframe)); }

}  // namespace

TEST(LandmarkTable, ALandmarkWhoseAnchorLeavesKeepsItsLaterObservationsAtTheNext) {
  LandmarkTable table = seenFourTimes();
  table.removeKeyframe(1, depthAt);
  const Landmark& l = table.all().at(7);
  EXPECT_EQ(l.anchor, 2);
  EXPECT_DOUBLE_EQ(l.inverse_depth, 1.0 / 12);
  ASSERT_EQ(l.observations.size(), 3u);
  EXPECT_EQ(l.observations.begin()->first, 2);
}

TEST(LandmarkTable, ALandmarkRestartedAtItsNewestObservationDropsTheOnesThePriorHolds) {
  LandmarkTable table = seenFourTimes();
  table.removeKeyframe(1, depthAt, /*restart=*/true);
  const Landmark& l = table.all().at(7);
  EXPECT_EQ(l.anchor, 4);
  EXPECT_DOUBLE_EQ(l.inverse_depth, 1.0 / 14);
  ASSERT_EQ(l.observations.size(), 1u);
  EXPECT_DOUBLE_EQ(l.anchorObservation().pixel.x(), 104.0);
  EXPECT_DOUBLE_EQ(l.anchorObservation().depth, 2.4);
  // Seen again, it is one landmark with two observations.
  table.observe(7, 5, {Eigen::Vector2d(105.0, 50.0), 2.5, {}}, 3.0);
  EXPECT_EQ(table.all().at(7).observations.size(), 2u);
  EXPECT_EQ(table.all().at(7).anchor, 4);
}

TEST(LandmarkTable, ALandmarkSeenOnlyByTheLeavingKeyframeIsDeleted) {
  LandmarkTable table;
  table.observe(3, 1, {Eigen::Vector2d(10.0, 20.0), 1.5, {}}, 3.0);
  table.removeKeyframe(1, depthAt, true);
  EXPECT_TRUE(table.all().empty());
}
