#include <dynslam/estimator/factors/GnssPositionFactor.h>

#include "FactorJacobianCheck.h"
#include "FactorTestStates.h"

#include <gtest/gtest.h>

using namespace dynslam::estimator;
using namespace dynslam::estimator::testing;

namespace {

/// Horizontal sigma from HDOP, vertical twice it, and some correlation so S is not diagonal.
Eigen::Matrix3d gnssCovariance(double sigmaHorizontal) {
  Eigen::Matrix3d c = Eigen::Vector3d(1.0, 1.0, 4.0).asDiagonal();
  c(0, 1) = c(1, 0) = 0.3;
  return sigmaHorizontal * sigmaHorizontal * c;
}

}  // namespace

TEST(GnssPositionFactor, AnalyticJacobianMatchesNumericAtRandomStates) {
  std::mt19937 rng(61);
  double worst = 0;
  for (int trial = 0; trial < 20; ++trial) {
    const Eigen::Isometry3d T = randomPose(rng, 50.0, M_PI);
    const GnssPositionFactor f(uniformVector(rng, 50.0), uniformVector(rng, 1.0),
                               gnssCovariance(0.8));
    const JacobianMismatch m = compareJacobians(f, {poseBlock(T)}, {true});
    EXPECT_LT(m.max_rel_error, 1e-5) << "trial " << trial << ": " << m.where;
    worst = std::max(worst, m.max_rel_error);
  }
  std::printf("worst relative Jacobian error over 20 states: %.1e\n", worst);
}

TEST(GnssPositionFactor, ResidualIsTheWhitenedAntennaPositionError) {
  std::mt19937 rng(62);
  const Eigen::Matrix3d cov = gnssCovariance(0.8);
  for (int trial = 0; trial < 10; ++trial) {
    const Eigen::Isometry3d T = randomPose(rng, 50.0, M_PI);
    const Eigen::Vector3d lever = uniformVector(rng, 1.0);
    const GnssPositionFactor exact(T * lever, lever, cov);
    EXPECT_LT(residualAt<3>(exact, {poseBlock(T)}).norm(), 1e-9) << trial;
    // |r|^2 is the Mahalanobis distance of the error.
    const Eigen::Vector3d e = uniformVector(rng, 2.0);
    const GnssPositionFactor off(T * lever - e, lever, cov);
    EXPECT_NEAR(residualAt<3>(off, {poseBlock(T)}).squaredNorm(), e.dot(cov.inverse() * e), 1e-9);
  }
  // Antenna 1 m above the body origin; the body rolled 90 deg about x puts it at (0, -1, 0).
  const Eigen::Matrix3d isotropic = 0.25 * Eigen::Matrix3d::Identity();  // sigma 0.5 m
  const GnssPositionFactor f(Eigen::Vector3d(0, 0, 1), Eigen::Vector3d(0, 0, 1), isotropic);
  Eigen::Isometry3d rolled = Eigen::Isometry3d::Identity();
  rolled.linear() = Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitX()).toRotationMatrix();
  EXPECT_LT((residualAt<3>(f, {poseBlock(rolled)}) - Eigen::Vector3d(0, -2, -2)).norm(), 1e-9);
  Eigen::Isometry3d shifted = Eigen::Isometry3d::Identity();
  shifted.translation().x() = 0.3;
  EXPECT_LT((residualAt<3>(f, {poseBlock(shifted)}) - Eigen::Vector3d(0.6, 0, 0)).norm(), 1e-9);
}
