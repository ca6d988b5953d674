#include <dynslam/estimator/factors/RigidSmoothMotionFactor.h>

#include "FactorJacobianCheck.h"
#include "FactorTestStates.h"

#include <gtest/gtest.h>

using namespace dynslam::estimator;
using namespace dynslam::estimator::testing;

namespace {

using Vector6d = Eigen::Matrix<double, 6, 1>;

RigidSmoothMotionFactor::Matrix6d randomInformation(std::mt19937& rng) {
  Eigen::Matrix<double, 6, 6> A;
  std::normal_distribution<double> n(0.0, 1.0);
  for (int i = 0; i < 36; ++i) A(i) = n(rng);
  return A * A.transpose() + 0.5 * Eigen::Matrix<double, 6, 6>::Identity();
}

}  // namespace

TEST(RigidSmoothMotionFactor, AnalyticJacobianMatchesNumericAtRandomStates) {
  std::mt19937 rng(51);
  double worst = 0;
  for (int trial = 0; trial < 30; ++trial) {
    const Eigen::Isometry3d La = randomPose(rng, 10.0, M_PI);
    const Eigen::Isometry3d H = randomPose(rng, 2.0, 0.5);
    // The second motion differs from the first by up to 1.2 rad, so Jr^-1 is far from I.
    const Eigen::Isometry3d Lb = La * H, Lc = Lb * H * randomPose(rng, 1.0, 1.2);
    const RigidSmoothMotionFactor f(randomInformation(rng));
    const JacobianMismatch m =
        compareJacobians(f, {poseBlock(La), poseBlock(Lb), poseBlock(Lc)}, {true, true, true});
    EXPECT_LT(m.max_rel_error, 1e-5) << "trial " << trial << ": " << m.where;
    worst = std::max(worst, m.max_rel_error);
  }
  std::printf("worst relative Jacobian error over 30 states: %.1e\n", worst);
  // Also at a constant motion (E = I), where Log and Jr^-1 take their small-angle branches.
  const Eigen::Isometry3d La = randomPose(rng, 10.0, M_PI), H = randomPose(rng, 2.0, 0.5);
  const JacobianMismatch m = compareJacobians(
      RigidSmoothMotionFactor(0.1, 0.05),
      {poseBlock(La), poseBlock(La * H), poseBlock(La * H * H)}, {true, true, true});
  EXPECT_LT(m.max_rel_error, 1e-5) << m.where;
}

TEST(RigidSmoothMotionFactor, ResidualIsZeroForConstantMotionAndExpectedOffIt) {
  std::mt19937 rng(52);
  const double sigmaT = 0.1, sigmaR = 0.05;
  const RigidSmoothMotionFactor f(sigmaT, sigmaR);
  for (int trial = 0; trial < 10; ++trial) {
    const Eigen::Isometry3d La = randomPose(rng, 10.0, M_PI), H = randomPose(rng, 2.0, 1.0);
    EXPECT_LT(residualAt<6>(f, {poseBlock(La), poseBlock(La * H), poseBlock(La * H * H)}).norm(),
              1e-9);
  }
  const Eigen::Isometry3d I = Eigen::Isometry3d::Identity();
  // A car moving 1 m then 1.3 m along x: the motion grew by 0.3 m.
  Eigen::Isometry3d Lb = I, Lc = I;
  Lb.translation().x() = 1.0;
  Lc.translation().x() = 2.3;
  Vector6d expected;
  expected << 0.3 / sigmaT, 0, 0, 0, 0, 0;
  EXPECT_LT((residualAt<6>(f, {poseBlock(I), poseBlock(Lb), poseBlock(Lc)}) - expected).norm(),
            1e-9);
  // Standing still, then turning 0.2 rad about z.
  Lc = I;
  Lc.linear() = Eigen::AngleAxisd(0.2, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  expected << 0, 0, 0, 0, 0, 0.2 / sigmaR;
  EXPECT_LT((residualAt<6>(f, {poseBlock(I), poseBlock(I), poseBlock(Lc)}) - expected).norm(),
            1e-9);
  // Turning 0.2 rad about z then going straight on: the motion changed by -0.2 rad.
  Lb = Lc;
  Eigen::Isometry3d Lc2 = Lb;
  expected << 0, 0, 0, 0, 0, -0.2 / sigmaR;
  EXPECT_LT((residualAt<6>(f, {poseBlock(I), poseBlock(Lb), poseBlock(Lc2)}) - expected).norm(),
            1e-9);
}

TEST(RigidSmoothMotionFactor, WhitensWithTheGivenInformation) {
  // |r|^2 = e^T Info e with e = [t_E; Log(R_E)].
  std::mt19937 rng(53);
  const RigidSmoothMotionFactor::Matrix6d info = randomInformation(rng);
  const RigidSmoothMotionFactor f(info);
  const Eigen::Isometry3d I = Eigen::Isometry3d::Identity();
  Eigen::Isometry3d Lc = I;
  Lc.translation() = Eigen::Vector3d(0.2, -0.1, 0.3);
  Lc.linear() = quaternionExp(Eigen::Vector3d(0.05, 0.1, -0.2)).toRotationMatrix();
  Vector6d e;
  e << 0.2, -0.1, 0.3, 0.05, 0.1, -0.2;
  const Vector6d r = residualAt<6>(f, {poseBlock(I), poseBlock(I), poseBlock(Lc)});
  EXPECT_NEAR(r.squaredNorm(), e.dot(info * e), 1e-9);
}
