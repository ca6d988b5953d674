#include <dynslam/rawlog_tools/TimestampAssociation.h>
#include <dynslam/rawlog_tools/Timestamps.h>
#include <gtest/gtest.h>

using namespace dynslam::rawlog_tools;

TEST(RawlogToolsAssociation, ClosestPairsWinAndEachStampIsUsedOnce) {
  // b[1] is within tolerance of a[1] (8 ms) and a[2] (2 ms): a[2] gets it, a[1] is dropped.
  const std::vector<double> a = {1.000, 1.030, 1.040, 1.500};
  const std::vector<double> b = {1.004, 1.038, 1.200};
  const Association r = associateNearest(a, b, 0.02);
  ASSERT_EQ(r.pairs.size(), 2u);
  EXPECT_EQ(r.pairs[0].first, 0u);
  EXPECT_EQ(r.pairs[0].second, 0u);
  EXPECT_EQ(r.pairs[1].first, 2u);
  EXPECT_EQ(r.pairs[1].second, 1u);
  EXPECT_EQ(r.unmatchedFirst, 2u);
  EXPECT_EQ(r.unmatchedSecond, 1u);
}

TEST(RawlogToolsAssociation, UnsortedInputAndEmptyStreams) {
  const Association r = associateNearest({3.0, 1.0, 2.0}, {2.01, 0.99, 3.0}, 0.02);
  ASSERT_EQ(r.pairs.size(), 3u);
  EXPECT_EQ(r.pairs[0].first, 1u);  // sorted by first-stream time
  EXPECT_EQ(r.pairs[0].second, 1u);
  EXPECT_EQ(r.pairs[2].first, 0u);
  EXPECT_EQ(r.pairs[2].second, 2u);
  EXPECT_TRUE(associateNearest({}, {1.0}, 0.02).pairs.empty());
  EXPECT_EQ(associateNearest({}, {1.0}, 0.02).unmatchedSecond, 1u);
}

TEST(RawlogToolsTimestamps, NanosecondStampsMapExactlyToMrptTicks) {
  constexpr int64_t kEpoch = INT64_C(116444736000000000);
  // Through a double, 1403715523912140000 ns would land on ...9121398 (fromDouble truncates).
  EXPECT_EQ(timeFromNanoseconds(INT64_C(1403715523912140000)).time_since_epoch().count(),
            INT64_C(14037155239121400) + kEpoch);
  EXPECT_EQ(timeFromNanoseconds(INT64_C(1403715523912140051)).time_since_epoch().count(),
            INT64_C(14037155239121401) + kEpoch);
  EXPECT_EQ(timeFromNanoseconds(INT64_C(1403715523912140049)).time_since_epoch().count(),
            INT64_C(14037155239121400) + kEpoch);
  EXPECT_DOUBLE_EQ(secondsFromNanoseconds(INT64_C(1403715523912140000)), 1403715523.91214);
}
