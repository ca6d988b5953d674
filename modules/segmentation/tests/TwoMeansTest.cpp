#include <dynslam/segmentation/TwoMeans.h>

#include <gtest/gtest.h>

#include <random>

using dynslam::segmentation::twoMeans;

TEST(TwoMeans, SplitsTwoGroupsAtTheGap) {
  std::vector<float> v = {3.0f, 1.0f, 3.2f, 1.2f, 2.8f, 0.8f, 3.0f};
  const auto r = twoMeans(v);
  ASSERT_TRUE(r.two_clusters);
  EXPECT_EQ(r.near_count, 3);
  EXPECT_EQ(r.far_count, 4);
  EXPECT_NEAR(r.near_mean, 1.0, 1e-6);
  EXPECT_NEAR(r.far_mean, 3.0, 1e-6);
}

TEST(TwoMeans, OneValueRepeatedIsOneCluster) {
  std::vector<float> v(64, 2.5f);
  const auto r = twoMeans(v);
  EXPECT_FALSE(r.two_clusters);
  EXPECT_EQ(r.near_count, 0);
  EXPECT_EQ(r.far_count, 64);
  EXPECT_DOUBLE_EQ(r.far_mean, 2.5);
  std::vector<float> empty;
  EXPECT_EQ(twoMeans(empty).far_count, 0);
}

TEST(TwoMeans, IsTheGlobalOptimumOfEveryContiguousSplit) {
  // Brute force over all 2^n partitions of a small random set: no partition has a smaller
  // within-cluster sum of squares than the one returned.
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> depth(0.5f, 6.0f);
  for (int trial = 0; trial < 20; ++trial) {
    std::vector<float> v(10);
    for (auto& x : v) x = depth(rng);
    auto copy = v;
    const auto r = twoMeans(copy);
    double best = 1e300;
    for (unsigned mask = 1; mask + 1 < (1u << v.size()); ++mask) {
      double s[2] = {0, 0}, q[2] = {0, 0};
      int c[2] = {0, 0};
      for (size_t i = 0; i < v.size(); ++i) {
        const int k = (mask >> i) & 1;
        s[k] += v[i];
        q[k] += double(v[i]) * v[i];
        ++c[k];
      }
      best = std::min(best, q[0] - s[0] * s[0] / c[0] + q[1] - s[1] * s[1] / c[1]);
    }
    double sse = 0;
    for (float x : v) {
      const double centre =
          std::abs(x - r.near_mean) < std::abs(x - r.far_mean) ? r.near_mean : r.far_mean;
      sse += (x - centre) * (x - centre);
    }
    EXPECT_NEAR(sse, best, 1e-9 * (1 + best)) << "trial " << trial;
    EXPECT_EQ(r.near_count + r.far_count, 10);
  }
}
