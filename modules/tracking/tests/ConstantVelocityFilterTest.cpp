#include <dynslam/tracking/ConstantVelocityFilter.h>

#include <gtest/gtest.h>
#include <Eigen/Cholesky>

#include <random>

using dynslam::tracking::ConstantVelocityFilter;

namespace {

TEST(ConstantVelocityFilter, FindsAWalkersVelocityFromNoisyPositions) {
  const Eigen::Vector3d v(1.2, -0.4, 0);
  const double sigma = 0.02;
  const Eigen::Matrix3d R = Eigen::Matrix3d::Identity() * sigma * sigma;
  std::mt19937 rng(3);
  std::normal_distribution<double> noise(0, sigma);
  ConstantVelocityFilter filter(Eigen::Vector3d::Zero(), R, 1.5);
  const double dt = 1.0 / 30;
  for (int k = 1; k <= 90; ++k) {
    filter.predict(dt, 0.3);
    filter.update(v * k * dt + Eigen::Vector3d(noise(rng), noise(rng), noise(rng)), R);
  }
  EXPECT_LT((filter.velocity() - v).norm(), 0.15) << filter.velocity().transpose();
  EXPECT_LT((filter.position() - v * 3.0).norm(), 0.05);
  // The error agrees with the filter's own velocity covariance (3 dof, p = 0.001).
  const Eigen::Vector3d e = filter.velocity() - v;
  EXPECT_LT(e.dot(filter.covariance().bottomRightCorner<3, 3>().ldlt().solve(e)), 16.27);
}

TEST(ConstantVelocityFilter, APredictionGrowsItsCovarianceAndMovesAlongTheVelocity) {
  const Eigen::Matrix3d R = Eigen::Matrix3d::Identity() * 0.01;
  ConstantVelocityFilter filter(Eigen::Vector3d::Zero(), R, 1.0);
  for (int k = 1; k <= 30; ++k) {
    filter.predict(0.1, 1.0);
    filter.update(Eigen::Vector3d(0.1 * k, 0, 0), R);
  }
  const double before = filter.covariance()(0, 0);
  const Eigen::Vector3d p = filter.position();
  filter.predict(1.0, 1.0);
  EXPECT_GT(filter.covariance()(0, 0), before + 0.1);
  EXPECT_NEAR(filter.position().x() - p.x(), 1.0, 0.1);
  // Far from the prediction: a large Mahalanobis distance; on it, a small one.
  EXPECT_GT(filter.mahalanobis2(filter.position() + Eigen::Vector3d(0, 5, 0), R), 20);
  EXPECT_LT(filter.mahalanobis2(filter.position(), R), 1e-9);
}

TEST(ConstantVelocityFilter, ANonPositiveStepChangesNothing) {
  ConstantVelocityFilter filter(Eigen::Vector3d(1, 2, 3), Eigen::Matrix3d::Identity(), 1.0);
  const auto P = filter.covariance();
  filter.predict(0, 1.0);
  filter.predict(-1, 1.0);
  EXPECT_EQ(filter.covariance(), P);
  EXPECT_EQ(filter.position(), Eigen::Vector3d(1, 2, 3));
}

}  // namespace
