// The two stream joins on hand-made streams: which colour image gets which depth image, and
// the accelerometer interpolated at gyro stamps, while messages arrive one by one.
#include "StreamPairing.h"

#include <gtest/gtest.h>

using namespace dynslam::rawlog_tools::bag;

namespace {
constexpr Nanoseconds kMs = 1000000;

ColourMessage colour(Nanoseconds t) {
  ColourMessage c;
  c.stamp = t;
  return c;
}
DepthMessage depth(Nanoseconds t) {
  DepthMessage d;
  d.stamp = t;
  return d;
}
}  // namespace

TEST(Bag2RawlogPairing, ColourTakesTheNearestDepthWithinTolerance) {
  RgbdPairer pairer(20 * kMs);
  pairer.addColour(colour(100 * kMs));
  pairer.addDepth(depth(95 * kMs));
  pairer.addDepth(depth(103 * kMs));
  // Not decided yet: a nearer depth image could still come.
  EXPECT_TRUE(pairer.takeReady(103 * kMs, 1000 * kMs, false).empty());
  EXPECT_EQ(pairer.oldestPending(), 100 * kMs);
  pairer.addColour(colour(200 * kMs));  // its depth is missing
  pairer.addDepth(depth(150 * kMs));
  auto ready = pairer.takeReady(200 * kMs, 1000 * kMs, false);
  ASSERT_EQ(ready.size(), 1u);
  EXPECT_EQ(ready[0].second.stamp, 103 * kMs);
  ready = pairer.takeReady(200 * kMs, 1000 * kMs, true);
  EXPECT_TRUE(ready.empty());
  EXPECT_EQ(pairer.unmatchedColour(), 1u);
  EXPECT_EQ(pairer.unmatchedDepth(), 2u);  // 95 ms and 150 ms
}

TEST(Bag2RawlogPairing, AStoppedDepthStreamDoesNotHoldColourForever) {
  RgbdPairer pairer(20 * kMs);
  pairer.addColour(colour(100 * kMs));
  EXPECT_TRUE(pairer.takeReady(500 * kMs, 1000 * kMs, false).empty());
  EXPECT_TRUE(pairer.takeReady(1200 * kMs, 1000 * kMs, false).empty());
  EXPECT_FALSE(pairer.oldestPending());
  EXPECT_EQ(pairer.unmatchedColour(), 1u);
}

TEST(Bag2RawlogImu, AccelerometerIsInterpolatedAtGyroStamps) {
  ImuCombiner imu;
  imu.addGyro({5 * kMs, {1, 2, 3}});  // before any accelerometer sample: dropped
  imu.addAccel({10 * kMs, {0, 0, 10}});
  imu.addGyro({12 * kMs, {0.1, 0.2, 0.3}});
  EXPECT_TRUE(imu.takeReady(false).empty());  // 12 ms waits for the next accel
  imu.addAccel({20 * kMs, {2, -1, 10}});
  imu.addGyro({20 * kMs, {0.4, 0.5, 0.6}});
  imu.addGyro({25 * kMs, {0.7, 0.8, 0.9}});
  const auto ready = imu.takeReady(false);
  ASSERT_EQ(ready.size(), 2u);
  EXPECT_EQ(ready[0].stamp, 12 * kMs);
  EXPECT_DOUBLE_EQ(ready[0].acc[0], 0.4);
  EXPECT_DOUBLE_EQ(ready[0].acc[1], -0.2);
  EXPECT_DOUBLE_EQ(ready[0].gyro[2], 0.3);
  EXPECT_EQ(ready[1].stamp, 20 * kMs);
  EXPECT_DOUBLE_EQ(ready[1].acc[0], 2.0);
  EXPECT_EQ(imu.oldestPending(), 25 * kMs);
  EXPECT_TRUE(imu.takeReady(true).empty());  // 25 ms is after the last accelerometer sample
  EXPECT_EQ(imu.droppedGyro(), 2u);
  imu.addGyro({24 * kMs, {0, 0, 0}});  // goes backwards
  EXPECT_EQ(imu.outOfOrder(), 1u);
}
