// Keyframe selection (KeyframeSelector.h): the first frame, too few shared features, parallax,
// the interval, in that order, and the shared count it reports for keyframes.csv.
#include <dynslam/estimator/KeyframeSelector.h>

#include <gtest/gtest.h>

using namespace dynslam::estimator;
using Reason = KeyframeSelector::Reason;

namespace {

/// n features with ids first.. at pixels shifted by dx.
std::map<std::int64_t, Eigen::Vector2d> features(int first, int n, double dx) {
  std::map<std::int64_t, Eigen::Vector2d> out;
  for (int i = 0; i < n; ++i) out[first + i] = Eigen::Vector2d(10.0 * i + dx, 100.0);
  return out;
}

}  // namespace

TEST(KeyframeSelector, DecidesByFirstSharedParallaxAndInterval) {
  KeyframeSelectorParams p;
  p.min_shared = 40;
  p.min_parallax_px = 10;
  p.max_interval_s = 0.5;
  KeyframeSelector s(p);
  int shared = -1;
  EXPECT_EQ(s.decide(0.0, features(0, 60, 0), &shared), Reason::First);
  EXPECT_EQ(shared, 0);
  s.accept(0.0, features(0, 60, 0));

  EXPECT_EQ(s.decide(0.1, features(0, 60, 2), &shared), Reason::NotKeyframe);
  EXPECT_EQ(shared, 60);
  EXPECT_EQ(s.decide(0.1, features(30, 60, 2), &shared), Reason::FewShared);
  EXPECT_EQ(shared, 30);
  EXPECT_EQ(s.decide(0.1, features(0, 60, 12), &shared), Reason::Parallax);
  EXPECT_EQ(s.decide(0.6, features(0, 60, 2), &shared), Reason::Interval);
  EXPECT_EQ(s.decide(0.1, features(0, 60, 2)), Reason::NotKeyframe) << "shared is optional";

  EXPECT_STREQ(KeyframeSelector::name(Reason::FewShared), "few_shared");
  EXPECT_STREQ(KeyframeSelector::name(Reason::NotKeyframe), "none");
}
