#include <dynslam/estimator/factors/GyroRotationFactor.h>

#include "FactorJacobianCheck.h"
#include "FactorTestStates.h"

#include <gtest/gtest.h>

using namespace dynslam::estimator;
using namespace dynslam::estimator::testing;

TEST(GyroRotationFactor, AnalyticJacobianMatchesNumericAtRandomStates) {
  std::mt19937 rng(61);
  std::normal_distribution<double> n(0.0, 1.0);
  double worst = 0;
  for (int trial = 0; trial < 30; ++trial) {
    const Eigen::Isometry3d Ta = randomPose(rng, 10.0, M_PI);
    const Eigen::Isometry3d Tb = Ta * randomPose(rng, 1.0, 0.5);
    // The gyro disagrees with the poses by up to ~1 rad, so Jr^-1 is far from I.
    const Eigen::Quaterniond gamma(randomPose(rng, 0.0, 1.0).rotation());
    Eigen::Matrix3d A;
    for (int i = 0; i < 9; ++i) A(i) = n(rng);
    const GyroRotationFactor f(gamma, 1e-4 * (A * A.transpose() + Eigen::Matrix3d::Identity()));
    const JacobianMismatch m = compareJacobians(f, {poseBlock(Ta), poseBlock(Tb)}, {true, true});
    EXPECT_LT(m.max_rel_error, 1e-5) << "trial " << trial << ": " << m.where;
    worst = std::max(worst, m.max_rel_error);
  }
  std::printf("worst relative Jacobian error over 30 states: %.1e\n", worst);
  // Where the poses agree with the gyro (Log and Jr^-1 on their small-angle branches).
  const Eigen::Isometry3d Ta = randomPose(rng, 10.0, M_PI), H = randomPose(rng, 1.0, 0.3);
  const JacobianMismatch m = compareJacobians(
      GyroRotationFactor(Eigen::Quaterniond(H.rotation()), 1e-4 * Eigen::Matrix3d::Identity()),
      {poseBlock(Ta), poseBlock(Ta * H)}, {true, true});
  EXPECT_LT(m.max_rel_error, 1e-5) << m.where;
}

TEST(GyroRotationFactor, ResidualIsTheRotationTheGyroDidNotSeeOverItsSigma) {
  const double sigma = 0.002;  // rad
  const Eigen::Matrix3d cov = sigma * sigma * Eigen::Matrix3d::Identity();
  std::mt19937 rng(62);
  const Eigen::Isometry3d Ta = randomPose(rng, 5.0, M_PI), H = randomPose(rng, 0.5, 0.4);
  const GyroRotationFactor agree(Eigen::Quaterniond(H.rotation()), cov);
  EXPECT_LT(residualAt<3>(agree, {poseBlock(Ta), poseBlock(Ta * H)}).norm(), 1e-9)
      << "translation does not enter, only the rotation";
  // The gyro read nothing; the poses say the body turned 0.01 rad about its own x axis.
  Eigen::Isometry3d Tb = Ta;
  Tb.linear() = Ta.linear() * Eigen::AngleAxisd(0.01, Eigen::Vector3d::UnitX()).toRotationMatrix();
  const GyroRotationFactor still(Eigen::Quaterniond::Identity(), cov);
  const Eigen::Vector3d r = residualAt<3>(still, {poseBlock(Ta), poseBlock(Tb)});
  EXPECT_NEAR(r.x(), 0.01 / sigma, 1e-6);
  EXPECT_NEAR(r.tail<2>().norm(), 0.0, 1e-9);
}
