#include <dynslam/nav/SweptFootprint.h>

#include <gtest/gtest.h>

#include <algorithm>

namespace dynslam::nav {
namespace {

/// Distance of p from the segment a-b (2D).
double distanceToSegment(const Eigen::Vector2d& p, const Eigen::Vector2d& a,
                         const Eigen::Vector2d& b) {
  const Eigen::Vector2d d = b - a;
  const double t = d.squaredNorm() > 0 ? std::clamp((p - a).dot(d) / d.squaredNorm(), 0.0, 1.0) : 0;
  return (p - (a + t * d)).norm();
}

TEST(SweptFootprint, AtRestItIsOneRingRepeatedUpTheBody) {
  Footprint f;
  f.centre = {2, -1};
  f.radius = 0.3;
  f.top = 1.0;
  FootprintSampling s;  // 0.1 m spacing, 0.3 m steps from 0.05 m
  std::vector<Eigen::Vector3f> points;
  appendSweptFootprint(f, 1.5, s, points);  // no velocity: the horizon changes nothing
  ASSERT_FALSE(points.empty());
  std::vector<float> heights;
  for (const auto& p : points) {
    EXPECT_NEAR((p.head<2>().cast<double>() - f.centre).norm(), f.radius, 1e-5);
    heights.push_back(p.z());
  }
  std::sort(heights.begin(), heights.end());
  heights.erase(std::unique(heights.begin(), heights.end()), heights.end());
  ASSERT_EQ(heights.size(), 4u);  // 0.05, 0.35, 0.65, 0.95
  EXPECT_NEAR(heights.front(), 0.05, 1e-6);
  EXPECT_NEAR(heights.back(), 0.95, 1e-6);
  // Neighbouring points on the ring at most the spacing apart.
  EXPECT_GE(points.size() / heights.size(), static_cast<std::size_t>(2 * M_PI * 0.3 / 0.1));
}

TEST(SweptFootprint, MovingItCoversThePathItWillTakeOverTheHorizon) {
  Footprint f;
  f.centre = {0, 0};
  f.velocity = {1.0, 0.5};
  f.radius = 0.25;
  f.top = 1.8;
  FootprintSampling s;
  std::vector<Eigen::Vector3f> points;
  const double horizon = 2.0;
  appendSweptFootprint(f, horizon, s, points);
  const Eigen::Vector2d end = f.centre + f.velocity * horizon;
  double farthest = 0;
  for (const auto& p : points) {
    const Eigen::Vector2d xy = p.head<2>().cast<double>();
    EXPECT_LE(distanceToSegment(xy, f.centre, end), f.radius + 1e-5);
    EXPECT_GT(p.z(), 0.01);
    EXPECT_LE(p.z(), 1.8 + 1e-6);
    farthest = std::max(farthest, (xy - f.centre).dot(f.velocity.normalized()));
  }
  EXPECT_NEAR(farthest, (end - f.centre).norm() + f.radius, 0.01);
  // Every point of the path is within the spacing of a ring's centre: no gap to slip through.
  for (double t = 0; t <= horizon; t += 0.01) {
    const Eigen::Vector2d c = f.centre + f.velocity * t;
    double nearest = 1e9;
    for (const auto& p : points)
      nearest = std::min(nearest, std::abs((p.head<2>().cast<double>() - c).norm() - f.radius));
    EXPECT_LE(nearest, s.spacing_m) << "t = " << t;
  }
}

TEST(SweptFootprint, NoPointAboveTheHeightLimit) {
  Footprint f;
  f.top = 5.0;
  FootprintSampling s;
  s.max_height_m = 1.2;
  std::vector<Eigen::Vector3f> points;
  appendSweptFootprint(f, 0, s, points);
  for (const auto& p : points) EXPECT_LE(p.z(), 1.2 + 1e-6);
}

}  // namespace
}  // namespace dynslam::nav
