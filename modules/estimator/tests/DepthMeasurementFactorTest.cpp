#include <dynslam/estimator/factors/DepthMeasurementFactor.h>
#include <dynslam/estimator/factors/TransferredDepthFactor.h>

#include "FactorJacobianCheck.h"
#include "FactorTestStates.h"

#include <gtest/gtest.h>

using namespace dynslam::estimator;
using namespace dynslam::estimator::testing;

TEST(DepthMeasurementFactor, WhitensTheInverseDepthErrorWithTheDepthDependentSigma) {
  const DepthNoiseModel noise{0.002, 0.003};
  EXPECT_DOUBLE_EQ(noise.sigma(2.0), 0.002 + 0.003 * 4.0);
  const DepthMeasurementFactor f(2.0, noise);
  // sigma_lambda = sigma_d / d^2 = 0.014 / 4.
  EXPECT_NEAR(f.sigmaInverseDepth(), 0.0035, 1e-15);
  EXPECT_NEAR(residualAt<1>(f, {{0.5}})(0), 0.0, 1e-15);
  // The point at 2.5 m instead of 2 m: (0.4 - 0.5) / 0.0035.
  EXPECT_NEAR(residualAt<1>(f, {{0.4}})(0), -0.1 / 0.0035, 1e-9);
  // Far depth is trusted less: the same relative error weighs less at 5 m than at 1 m.
  const DepthMeasurementFactor near(1.0, noise), far(5.0, noise);
  EXPECT_GT(std::abs(residualAt<1>(near, {{1.0 / 1.1}})(0)),
            std::abs(residualAt<1>(far, {{1.0 / 5.5}})(0)));
}

TEST(DepthMeasurementFactor, AnalyticJacobianMatchesNumeric) {
  for (double d : {0.4, 1.0, 3.0, 7.0}) {
    const DepthMeasurementFactor f(d);
    const JacobianMismatch m = compareJacobians(f, {{1.3 / d}}, {false});
    EXPECT_LT(m.max_rel_error, 1e-6) << d << ": " << m.where;
  }
}

TEST(TransferredDepthFactor, AnalyticJacobianMatchesNumericAtRandomStates) {
  std::mt19937 rng(21);
  double worst = 0;
  for (int trial = 0; trial < 20; ++trial) {
    const StaticScene s = randomStaticScene(rng);
    // Measured 5 % off, so the check runs away from the zero of the residual.
    const TransferredDepthFactor f(testCamera(), s.pixel_i, 1.05 * s.depth_j);
    const JacobianMismatch m = compareJacobians(f, blocksOf(s), {true, true, true, false});
    EXPECT_LT(m.max_rel_error, 1e-5) << "trial " << trial << ": " << m.where;
    worst = std::max(worst, m.max_rel_error);
  }
  std::printf("worst relative Jacobian error over 20 states: %.1e\n", worst);
}

TEST(TransferredDepthFactor, ResidualIsZeroAtTheTrueStateAndMetricOffIt) {
  std::mt19937 rng(22);
  for (int trial = 0; trial < 10; ++trial) {
    const StaticScene s = randomStaticScene(rng);
    const TransferredDepthFactor f(testCamera(), s.pixel_i, s.depth_j);
    EXPECT_LT(std::abs(residualAt<1>(f, blocksOf(s))(0)), 1e-9) << trial;
  }
  // Identity poses and extrinsic; the point 3 m ahead, measured at 3 m in frame j. Frame j
  // 0.5 m further forward sees it at 2.5 m: r = (2.5 - 3) / sigma_d(3).
  const PinholeCamera cam = testCamera();
  const DepthNoiseModel noise;
  const TransferredDepthFactor f(cam, {cam.cx + 40, cam.cy - 25}, 3.0, noise);
  const Eigen::Isometry3d I = Eigen::Isometry3d::Identity();
  Eigen::Isometry3d forward = I;
  forward.translation().z() = 0.5;
  EXPECT_NEAR(residualAt<1>(f, {poseBlock(I), poseBlock(I), poseBlock(I), {1.0 / 3}})(0), 0.0,
              1e-12);
  EXPECT_NEAR(residualAt<1>(f, {poseBlock(I), poseBlock(forward), poseBlock(I), {1.0 / 3}})(0),
              -0.5 / noise.sigma(3.0), 1e-9);
}
