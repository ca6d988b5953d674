#include <dynslam/estimator/GnssAnchor.h>
#include <dynslam/estimator/GnssFixBuffer.h>
#include <dynslam/estimator/GnssWorldAlignment.h>

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace dynslam::estimator;

namespace {

/// The world of a run that started tilted and turned: ENU -> world.
Eigen::Isometry3d trueWorldFromEnu() {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = (Eigen::AngleAxisd(0.7, Eigen::Vector3d::UnitZ()) *
                Eigen::AngleAxisd(0.1, Eigen::Vector3d::UnitX()))
                   .toRotationMatrix();
  T.translation() = Eigen::Vector3d(3.0, -2.0, 0.5);
  return T;
}

/// Feeds `n` pairs along the ENU path `enuAt(i)`, world positions with 2 cm noise.
template <class Path>
void feed(GnssWorldAlignment& a, int n, Path enuAt, std::mt19937& rng) {
  std::normal_distribution<double> noise(0.0, 0.02);
  const Eigen::Isometry3d T = trueWorldFromEnu();
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector3d enu = enuAt(i);
    a.addPair(T * enu + Eigen::Vector3d(noise(rng), noise(rng), noise(rng)), enu);
  }
}

double angleDeg(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b) {
  return Eigen::AngleAxisd(a.transpose() * b).angle() * 180 / M_PI;
}

}  // namespace

TEST(GnssWorldAlignment, WithGravityAStraightDriveAlignsOnceItSpansEnough) {
  std::mt19937 rng(3);
  const Eigen::Isometry3d T = trueWorldFromEnu();
  const Eigen::Vector3d gravityWorld = T.linear() * Eigen::Vector3d(0, 0, -9.81);
  GnssAlignmentParams params;
  params.min_span_m = 10;
  GnssWorldAlignment a(params);
  auto straight = [](int i) { return Eigen::Vector3d(0.8 * i, 0.3 * i, 0.01 * i); };
  feed(a, 12, straight, rng);  // 9.6 m long: spans 4.8 m either side of its centre
  EXPECT_FALSE(a.tryAlign(gravityWorld));
  feed(a, 20, [&](int i) { return straight(12 + i); }, rng);
  ASSERT_TRUE(a.tryAlign(gravityWorld));
  EXPECT_EQ(a.pairs(), 32u);
  EXPECT_LT(angleDeg(a.T_world_enu().linear(), T.linear()), 0.2);
  EXPECT_LT((a.T_world_enu().translation() - T.translation()).norm(), 0.05);
  EXPECT_LT(a.rmsResidual(), 0.06);
}

TEST(GnssWorldAlignment, WithoutGravityALineIsNotEnoughButATurnIs) {
  std::mt19937 rng(4);
  const Eigen::Isometry3d T = trueWorldFromEnu();
  GnssWorldAlignment a;
  feed(a, 40, [](int i) { return Eigen::Vector3d(0.5 * i, 0, 0); }, rng);
  EXPECT_FALSE(a.tryAlign(std::nullopt)) << "rotation about the line is unobservable";
  feed(a, 40, [](int i) { return Eigen::Vector3d(20.0, 0.5 * i, 0); }, rng);
  ASSERT_TRUE(a.tryAlign(std::nullopt));
  EXPECT_LT(angleDeg(a.T_world_enu().linear(), T.linear()), 0.2);
  EXPECT_LT((a.T_world_enu().translation() - T.translation()).norm(), 0.05);
}

TEST(GnssWorldAlignment, PairsWaitingForAFitStayBoundedAndStillSpanThePath) {
  std::mt19937 rng(5);
  const Eigen::Isometry3d T = trueWorldFromEnu();
  GnssAlignmentParams params;
  params.max_pairs = 50;
  GnssWorldAlignment a(params);
  // A line (no fit without gravity), far more fixes than kept.
  feed(a, 1000, [](int i) { return Eigen::Vector3d(0.05 * i, 0, 0); }, rng);
  EXPECT_FALSE(a.tryAlign(std::nullopt));
  EXPECT_LE(a.pairs(), 50u);
  EXPECT_GE(a.pairs(), 25u);
  feed(a, 40, [](int i) { return Eigen::Vector3d(50.0, 0.5 * i, 0); }, rng);
  ASSERT_TRUE(a.tryAlign(std::nullopt)) << "the thinned line and the turn still fit";
  EXPECT_LT(angleDeg(a.T_world_enu().linear(), T.linear()), 0.2);
  EXPECT_LT((a.T_world_enu().translation() - T.translation()).norm(), 0.05);
}

TEST(GnssFixBuffer, InterpolatesBetweenBracketingFixesAndWaitsForTheNext) {
  GnssFixBuffer b(0.5);
  b.add(1.0, Eigen::Vector3d(0, 0, 0), 0.8);
  b.add(1.1, Eigen::Vector3d(0.8, 0, 0), 1.2);
  EXPECT_FALSE(b.at(0.9)) << "before the first fix";
  EXPECT_FALSE(b.at(1.15)) << "the later fix has not come yet";
  EXPECT_FALSE(b.covers(1.15));
  ASSERT_TRUE(b.at(1.025));
  EXPECT_NEAR(b.at(1.025)->enu.x(), 0.2, 1e-12);
  EXPECT_NEAR(b.at(1.1)->enu.x(), 0.8, 1e-12) << "exactly at a fix";
  EXPECT_EQ(b.at(1.025)->hdop, 1.2) << "the worse of the two";
  b.add(1.05, Eigen::Vector3d(9, 9, 9));  // out of order: ignored
  EXPECT_NEAR(b.at(1.05)->enu.x(), 0.4, 1e-12);
  b.add(2.0, Eigen::Vector3d(5, 0, 0));  // 0.9 s dropout
  EXPECT_TRUE(b.covers(1.5));
  EXPECT_FALSE(b.at(1.5)) << "no interpolation across a dropout";
  b.dropBefore(1.5);
  EXPECT_EQ(b.size(), 2u) << "keeps the fix before 1.5 for interpolating after it";
}


// A drive of 20 m east then north at 5 m/s with fixes at 10 Hz and keyframes at 3 Hz, the world
// rotated and shifted from ENU: before the alignment no targets, after it each keyframe's target
// is the antenna's true world position, with the HDOP-scaled covariance in world axes.
TEST(GnssAnchor, TargetsFollowOnceTheFixesAreAligned) {
  const Eigen::Isometry3d T = trueWorldFromEnu();
  auto enuAt = [](double t) {
    return t < 4 ? Eigen::Vector3d(5 * t, 0, 0) : Eigen::Vector3d(20, 5 * (t - 4), 0);
  };
  GnssAnchorParams params;
  params.uere_horizontal_m = 0.05;
  GnssAnchor anchor(params);
  const Eigen::Vector3d gravity = T.linear() * Eigen::Vector3d(0, 0, -9.81);
  auto antennaAt = [&](double t) -> std::optional<Eigen::Vector3d> { return T * enuAt(t); };
  std::vector<GnssTarget> targets;
  double fixT = 0, keyframeT = 0;
  for (double t = 0; t < 8; t += 0.01) {
    std::vector<dynslam::core::GnssFix> fixes;
    if (t >= fixT) {
      dynslam::core::GnssFix f;
      f.t = fixT;
      f.enu = enuAt(fixT);
      f.hdop = 0.8;
      fixes.push_back(f);
      fixT += 0.1;
    }
    anchor.addFixes(fixes);
    if (t >= keyframeT) {
      anchor.keyframeAdded(keyframeT);
      keyframeT += 1.0 / 3;
    }
    for (const auto& target : anchor.resolve(antennaAt, gravity)) {
      EXPECT_TRUE(anchor.aligned());
      EXPECT_LT((target.world - T * enuAt(target.t)).norm(), 1e-6) << "t = " << target.t;
      EXPECT_NEAR(target.covariance.trace(), 0.04 * 0.04 * 6, 1e-9);  // 2 x horizontal + 4 x
      targets.push_back(target);
    }
  }
  ASSERT_TRUE(anchor.aligned());
  EXPECT_GT(targets.size(), 10u);
  EXPECT_GT(targets.front().t, 1.0) << "the first targets waited for a 5 m span";
}
