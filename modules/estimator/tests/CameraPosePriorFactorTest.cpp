#include <dynslam/estimator/factors/CameraPosePriorFactor.h>

#include "FactorJacobianCheck.h"
#include "FactorTestStates.h"

#include <gtest/gtest.h>

using namespace dynslam::estimator;
using namespace dynslam::estimator::testing;

TEST(CameraPosePriorFactor, AnalyticJacobiansMatchNumericAtRandomStates) {
  std::mt19937 rng(91);
  double worst = 0;
  for (int trial = 0; trial < 30; ++trial) {
    const Eigen::Isometry3d body = randomPose(rng, 2.0, 3.0), extrinsic = randomExtrinsic(rng);
    // The prior up to ~0.8 rad from the chain, so Jr^-1 is far from I.
    const Eigen::Isometry3d prior = body * extrinsic * randomPose(rng, 0.1, 0.8);
    const CameraPosePriorFactor f(prior, 0.01, 0.02);
    const JacobianMismatch m =
        compareJacobians(f, {poseBlock(body), poseBlock(extrinsic)}, {true, true});
    EXPECT_LT(m.max_rel_error, 1e-5) << "trial " << trial << ": " << m.where;
    worst = std::max(worst, m.max_rel_error);
  }
  std::printf("worst relative Jacobian error over 30 states: %.1e\n", worst);
}

// Zero where body and extrinsic put the camera at the prior, whatever each is alone: a body
// turned one way and an extrinsic turned back hold the camera.
TEST(CameraPosePriorFactor, HoldsTheCameraNotTheBody) {
  std::mt19937 rng(92);
  const Eigen::Isometry3d body = randomPose(rng, 2.0, 3.0), extrinsic = randomExtrinsic(rng);
  const CameraPosePriorFactor f(body * extrinsic, 0.01, 0.02);
  Eigen::Isometry3d turn = Eigen::Isometry3d::Identity();
  turn.linear() = Eigen::AngleAxisd(0.05, Eigen::Vector3d(1, 2, 3).normalized()).matrix();
  turn.translation() = Eigen::Vector3d(0.01, -0.02, 0.03);
  EXPECT_LT(
      residualAt<6>(f, {poseBlock(body * turn), poseBlock(turn.inverse() * extrinsic)}).norm(),
      1e-9);
  EXPECT_GT(residualAt<6>(f, {poseBlock(body * turn), poseBlock(extrinsic)}).norm(), 1.0);
}
