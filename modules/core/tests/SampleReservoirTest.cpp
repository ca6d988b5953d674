// SampleReservoir: exact while small, bounded and unbiased after, reproducible.
#include <dynslam/core/Median.h>
#include <dynslam/core/SampleReservoir.h>

#include <gtest/gtest.h>

using dynslam::core::SampleReservoir;

TEST(SampleReservoir, KeepsEverySampleUpToItsCapacity) {
  SampleReservoir r(5);
  EXPECT_TRUE(r.empty());
  EXPECT_EQ(r.last(), 0.0);
  for (double v : {3.0, 1.0, 4.0, 1.0, 5.0}) r.add(v);
  EXPECT_EQ(r.samples(), (std::vector<double>{3, 1, 4, 1, 5}));
  EXPECT_EQ(r.count(), 5u);
  EXPECT_EQ(r.last(), 5.0);
  EXPECT_EQ(r.max(), 5.0);
}

TEST(SampleReservoir, PastItsCapacityHoldsAUniformSubsetAndExactCountLastAndMax) {
  SampleReservoir r(1000), again(1000);
  const int n = 100000;  // 0 .. n-1 in order: a reservoir keeping only early ones would show it
  for (int i = 0; i < n; ++i) {
    const double v = i == 500 ? 1e9 : double(i);
    r.add(v);
    again.add(v);
  }
  EXPECT_EQ(r.samples().size(), 1000u);
  EXPECT_EQ(r.count(), std::size_t(n));
  EXPECT_EQ(r.last(), n - 1.0);
  EXPECT_EQ(r.max(), 1e9) << "exact, whether or not the sample is still held";
  // The median of 1000 uniform draws of 0..n-1: n/2 with a standard deviation of about
  // 0.016 n; 5 sigma.
  EXPECT_NEAR(dynslam::core::upperMedian(r.samples()), n / 2.0, 0.08 * n);
  EXPECT_EQ(r.samples(), again.samples()) << "a fixed seed: a rerun reports the same";
}
