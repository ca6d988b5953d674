#include <dynslam/estimator/factors/CalibrationPriorFactor.h>

#include "FactorJacobianCheck.h"
#include "FactorTestStates.h"

#include <gtest/gtest.h>

using namespace dynslam::estimator;
using namespace dynslam::estimator::testing;

TEST(ExtrinsicPriorFactor, AnalyticJacobianMatchesNumericAtRandomStates) {
  std::mt19937 rng(81);
  double worst = 0;
  for (int trial = 0; trial < 30; ++trial) {
    const Eigen::Isometry3d prior = randomExtrinsic(rng);
    // Up to ~0.8 rad from the prior, so Jr^-1 is far from I.
    const Eigen::Isometry3d at = prior * randomPose(rng, 0.1, 0.8);
    const ExtrinsicPriorFactor f(prior, 0.02, 0.05);
    const JacobianMismatch m = compareJacobians(f, {poseBlock(at)}, {true});
    EXPECT_LT(m.max_rel_error, 1e-5) << "trial " << trial << ": " << m.where;
    worst = std::max(worst, m.max_rel_error);
  }
  std::printf("worst relative Jacobian error over 30 states: %.1e\n", worst);
}

TEST(ExtrinsicPriorFactor, ResidualIsTheOffsetAndTheRotationFromThePriorOverTheirSigmas) {
  std::mt19937 rng(82);
  const Eigen::Isometry3d prior = randomExtrinsic(rng);
  Eigen::Isometry3d at = prior;
  at.translation() += Eigen::Vector3d(0.01, 0, -0.02);
  at.linear() = prior.rotation() * Eigen::AngleAxisd(0.03, Eigen::Vector3d::UnitY()).matrix();
  const ExtrinsicPriorFactor f(prior, 0.01, 0.015);
  const auto r = residualAt<6>(f, {poseBlock(at)});
  EXPECT_NEAR(r(0), 1.0, 1e-9);
  EXPECT_NEAR(r(2), -2.0, 1e-9);
  EXPECT_NEAR(r(4), 2.0, 1e-9);
  EXPECT_NEAR(r(3), 0.0, 1e-9);
  EXPECT_LT(residualAt<6>(f, {poseBlock(prior)}).norm(), 1e-12);
}

TEST(TimeOffsetPriorFactor, ResidualAndJacobianAreTheOffsetFromThePriorOverSigma) {
  const TimeOffsetPriorFactor f(0.01, 0.002);
  EXPECT_NEAR(residualAt<1>(f, {{0.016}})(0), 3.0, 1e-9);
  const JacobianMismatch m = compareJacobians(f, {{0.016}}, {false});
  EXPECT_LT(m.max_rel_error, 1e-6) << m.where;
}
