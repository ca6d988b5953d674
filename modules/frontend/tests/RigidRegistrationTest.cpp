// Contract of the registration (method.md section 4): the Kabsch/Horn solution recovers an exact
// motion, and the 4-point RANSAC finds a known (R, t) and exactly its inliers with 40 % of the
// pairs moved elsewhere.
#include <dynslam/frontend/RigidRegistration.h>

#include <gtest/gtest.h>

#include <random>

namespace dynslam::frontend {
namespace {

RigidMotion knownMotion() {
  const Eigen::Matrix3d R =
      (Eigen::AngleAxisd(0.3, Eigen::Vector3d(1, 2, 3).normalized())).toRotationMatrix();
  return {R, Eigen::Vector3d(0.4, -0.2, 0.15)};
}

TEST(RigidRegistration, KabschRecoversAnExactMotion) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1, 1);
  const RigidMotion m = knownMotion();
  std::vector<Eigen::Vector3d> p, q;
  for (int i = 0; i < 10; ++i) {
    p.emplace_back(u(rng), u(rng), 3 + u(rng));
    q.push_back(m.apply(p.back()));
  }
  const RigidMotion e = kabsch(p, q);
  EXPECT_LT((e.R - m.R).norm(), 1e-9);
  EXPECT_LT((e.t - m.t).norm(), 1e-9);
  EXPECT_NEAR(e.R.determinant(), 1.0, 1e-12);
  EXPECT_THROW(kabsch({p[0], p[1]}, {q[0], q[1]}), std::invalid_argument);
}

TEST(RigidRegistration, WeightedKabschFollowsTheWeights) {
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> u(-1, 1);
  const RigidMotion m = knownMotion();
  std::vector<Eigen::Vector3d> p, q;
  for (int i = 0; i < 12; ++i) {
    p.emplace_back(u(rng), u(rng), 3 + u(rng));
    q.push_back(m.apply(p.back()));
  }
  // Equal weights: the same solution as the unweighted one.
  const RigidMotion plain = kabsch(p, q), equal = kabsch(p, q, {}, std::vector<double>(12, 2.0));
  EXPECT_LT((plain.R - equal.R).norm(), 1e-9);
  EXPECT_LT((plain.t - equal.t).norm(), 1e-9);
  // One pair displaced by 20 cm: with a tiny weight it hardly moves the solution.
  q[3] += Eigen::Vector3d(0.2, 0, 0);
  std::vector<double> w(12, 1.0);
  w[3] = 1e-6;
  const RigidMotion weighted = kabsch(p, q, {}, w), unweighted = kabsch(p, q);
  EXPECT_LT((weighted.t - m.t).norm(), 1e-5);
  EXPECT_GT((unweighted.t - m.t).norm(), 1e-3);
  EXPECT_THROW(kabsch(p, q, {}, std::vector<double>(5, 1.0)), std::invalid_argument);
}

TEST(RigidRegistration, RansacRecoversMotionAndInliersWithFortyPercentOutliers) {
  std::mt19937 gen(7);
  std::uniform_real_distribution<double> u(-1, 1);
  std::normal_distribution<double> noise(0, 0.003);  // 3 mm: well inside tau = 3 cm
  const RigidMotion m = knownMotion();
  std::vector<Eigen::Vector3d> p, q;
  std::vector<int> truthInliers;
  for (int i = 0; i < 100; ++i) {
    p.emplace_back(u(gen), u(gen), 3 + u(gen));
    if (i % 5 < 2) {  // 40 %: displaced by 10-60 cm in a random direction
      const Eigen::Vector3d d = Eigen::Vector3d(u(gen), u(gen), u(gen)).normalized();
      q.push_back(m.apply(p.back()) + (0.1 + 0.5 * (u(gen) + 1) / 2) * d);
    } else {
      q.push_back(m.apply(p.back()) + Eigen::Vector3d(noise(gen), noise(gen), noise(gen)));
      truthInliers.push_back(i);
    }
  }
  RansacParams params;  // 4 pairs, 100 iterations, tau 0.03 m
  std::mt19937 rng(1);
  const auto r = registerRansac(p, q, params, rng);
  ASSERT_TRUE(r);
  EXPECT_EQ(r->inliers, truthInliers);
  EXPECT_LT(rotationAngleDeg(r->motion.R.transpose() * m.R), 0.2);
  EXPECT_LT((r->motion.t - m.t).norm(), 0.005);

  // Same seed, same answer.
  std::mt19937 rng2(1);
  const auto again = registerRansac(p, q, params, rng2);
  ASSERT_TRUE(again);
  EXPECT_EQ(again->inliers, r->inliers);
  EXPECT_EQ(again->motion.t, r->motion.t);
}

TEST(RigidRegistration, TooFewPairsGiveNoRegistration) {
  std::mt19937 rng(1);
  const std::vector<Eigen::Vector3d> p{{0, 0, 1}, {1, 0, 1}, {0, 1, 1}};
  EXPECT_FALSE(registerRansac(p, p, RansacParams{}, rng));
  // An extra hypothesis is enough when it explains 3 pairs.
  const auto r = registerRansac(p, p, RansacParams{}, rng, {}, {RigidMotion{}});
  ASSERT_TRUE(r);
  EXPECT_EQ(r->inliers.size(), 3u);
}

}  // namespace
}  // namespace dynslam::frontend
