// ImuFactor: zero residual at the true states, analytic Jacobians equal to numeric ones.
#include "FactorJacobianCheck.h"
#include "ImuTestMotion.h"

#include <dynslam/estimator/factors/ImuFactor.h>

#include <gtest/gtest.h>

#include <random>

using namespace dynslam::estimator;
using namespace dynslam::estimator::testing;

namespace {

std::shared_ptr<ImuPreintegration> preintegrate(double t0, double duration,
                                                const Eigen::Vector3d& ba,
                                                const Eigen::Vector3d& bg) {
  const double dt = 0.005;
  auto pre = std::make_shared<ImuPreintegration>(specificForce(t0) + ba, bodyRate() + bg, ba, bg,
                                                 ImuNoise{});
  for (int k = 1; k <= int(std::lround(duration / dt)); ++k)
    pre->push(dt, specificForce(t0 + k * dt) + ba, bodyRate() + bg);
  return pre;
}

std::vector<double> poseBlock(const MotionState& s) {
  std::vector<double> b(7);
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = s.q.toRotationMatrix();
  T.translation() = s.p;
  poseToBlock(T, b.data());
  return b;
}

std::vector<double> speedBias(const MotionState& s, const Eigen::Vector3d& ba,
                              const Eigen::Vector3d& bg) {
  return {s.v.x(), s.v.y(), s.v.z(), ba.x(), ba.y(), ba.z(), bg.x(), bg.y(), bg.z()};
}

}  // namespace

TEST(ImuFactor, ResidualIsZeroAtTheTrueStates) {
  const Eigen::Vector3d ba(0.02, -0.01, 0.03), bg(0.001, 0.002, -0.001);
  const ImuFactor factor(preintegrate(2.0, 0.4, ba, bg));
  const MotionState i = motionAt(2.0), j = motionAt(2.4);
  auto pi = poseBlock(i), si = speedBias(i, ba, bg), pj = poseBlock(j), sj = speedBias(j, ba, bg);
  const double* params[] = {pi.data(), si.data(), pj.data(), sj.data(), kTestGravity.data()};
  Eigen::Matrix<double, 15, 1> r;
  ASSERT_TRUE(factor.Evaluate(params, r.data(), nullptr));
  // Whitened: a few sigma at most (the midpoint rule's error is far below the noise).
  EXPECT_LT(r.cwiseAbs().maxCoeff(), 0.05) << r.transpose();

  // A 1 cm error in p_j shows up in the position rows.
  pj[0] += 0.01;
  ASSERT_TRUE(factor.Evaluate(params, r.data(), nullptr));
  EXPECT_GT(r.head<3>().norm(), 1.0);
}

TEST(ImuFactor, AnalyticJacobiansMatchNumericDifferentiation) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1, 1);
  // Returns a vector, not an Eigen expression that would refer to a destroyed temporary.
  const auto randomVector = [&](double scale) -> Eigen::Vector3d {
    return Eigen::Vector3d(u(rng), u(rng), u(rng)) * scale;
  };
  for (int trial = 0; trial < 5; ++trial) {
    const double t0 = 0.5 + trial;
    const Eigen::Vector3d ba = randomVector(0.05), bg = randomVector(0.005);
    const ImuFactor factor(preintegrate(t0, 0.3, ba, bg));
    // States away from the truth (the Jacobians must hold anywhere), biases off the
    // linearisation point.
    MotionState i = motionAt(t0), j = motionAt(t0 + 0.3);
    i.p += randomVector(0.1);
    j.p += randomVector(0.1);
    i.q = i.q * quaternionExp(randomVector(0.1));
    j.q = j.q * quaternionExp(randomVector(0.1));
    i.v += randomVector(0.2);
    j.v += randomVector(0.2);
    const auto mismatch = compareJacobians(
        factor,
        {poseBlock(i), speedBias(i, ba + randomVector(0.01), bg + randomVector(0.001)),
         poseBlock(j), speedBias(j, ba + randomVector(0.01), bg + randomVector(0.001)),
         std::vector<double>(kTestGravity.data(), kTestGravity.data() + 3)},
        {true, false, true, false, false});
    EXPECT_LT(mismatch.max_rel_error, 2e-3) << "trial " << trial << ": " << mismatch.where;
  }
}
