#include <dynslam/estimator/factors/NonRigidConstantVelocityFactor.h>

#include "FactorJacobianCheck.h"
#include "FactorTestStates.h"

#include <gtest/gtest.h>

using namespace dynslam::estimator;
using namespace dynslam::estimator::testing;

namespace {

/// A walking point seen at keyframe n, with its state at the reference time t_n0 = t_n - dt.
struct WalkingPoint {
  Eigen::Isometry3d T_wb, T_bc;
  Eigen::Vector3d p_w0, v_w;
  double dt = 0;
  Eigen::Vector2d pixel;  ///< exact
};

WalkingPoint randomWalkingPoint(std::mt19937& rng) {
  WalkingPoint w;
  w.T_wb = randomPose(rng, 5.0, M_PI);
  w.T_bc = randomExtrinsic(rng);
  const Eigen::Vector3d p_c = randomPointInView(rng, testCamera());
  w.pixel = testCamera().project(p_c);
  w.v_w = uniformVector(rng, 1.5);
  w.dt = std::uniform_real_distribution<double>(-1.0, 1.0)(rng);
  w.p_w0 = w.T_wb * (w.T_bc * p_c) - w.dt * w.v_w;
  return w;
}

std::vector<std::vector<double>> blocksOf(const WalkingPoint& w) {
  return {poseBlock(w.T_wb), poseBlock(w.T_bc), {w.p_w0.x(), w.p_w0.y(), w.p_w0.z()},
          {w.v_w.x(), w.v_w.y(), w.v_w.z()}};
}

}  // namespace

TEST(NonRigidConstantVelocityFactor, AnalyticJacobianMatchesNumericAtRandomStates) {
  std::mt19937 rng(31);
  std::normal_distribution<double> pixelNoise(0.0, 3.0);
  double worst = 0;
  for (int trial = 0; trial < 20; ++trial) {
    const WalkingPoint w = randomWalkingPoint(rng);
    const Eigen::Vector2d observed = w.pixel + Eigen::Vector2d(pixelNoise(rng), pixelNoise(rng));
    const NonRigidConstantVelocityFactor f(testCamera(), observed, w.dt, 2.0);
    const JacobianMismatch m = compareJacobians(f, blocksOf(w), {true, true, false, false});
    EXPECT_LT(m.max_rel_error, 1e-5) << "trial " << trial << ": " << m.where;
    worst = std::max(worst, m.max_rel_error);
  }
  std::printf("worst relative Jacobian error over 20 states: %.1e\n", worst);
}

TEST(NonRigidConstantVelocityFactor, ResidualIsZeroAtTheTrueState) {
  std::mt19937 rng(32);
  for (int trial = 0; trial < 10; ++trial) {
    const WalkingPoint w = randomWalkingPoint(rng);
    const NonRigidConstantVelocityFactor f(testCamera(), w.pixel, w.dt, 2.0);
    EXPECT_LT(residualAt<2>(f, blocksOf(w)).norm(), 1e-9) << trial;
  }
}

TEST(NonRigidConstantVelocityFactor, VelocityErrorMovesThePredictionByVelocityTimesDt) {
  // Body = camera = world. A person 4 m ahead at t_n, walking right (camera x) at 1 m/s, state
  // kept 0.5 s earlier. Estimating 1.2 m/s instead puts the prediction 0.1 m further right,
  // fx * 0.1 / 4 pixels: observed - predicted = -fx * 0.025 / sigma in u.
  const PinholeCamera cam = testCamera();
  const double sigma = 2.0, dt = 0.5;
  const NonRigidConstantVelocityFactor f(cam, {cam.cx, cam.cy}, dt, sigma);
  const std::vector<double> I = poseBlock(Eigen::Isometry3d::Identity());
  const std::vector<double> p0 = {-0.5, 0.0, 4.0};
  EXPECT_LT(residualAt<2>(f, {I, I, p0, {1.0, 0.0, 0.0}}).norm(), 1e-12);
  const Eigen::Vector2d r = residualAt<2>(f, {I, I, p0, {1.2, 0.0, 0.0}});
  EXPECT_NEAR(r.x(), -cam.fx * 0.025 / sigma, 1e-9);
  EXPECT_NEAR(r.y(), 0.0, 1e-12);
  // At the reference time itself (dt = 0) the velocity is unobserved.
  const NonRigidConstantVelocityFactor atReference(cam, {cam.cx, cam.cy}, 0.0, sigma);
  EXPECT_LT(residualAt<2>(atReference, {I, I, {0.0, 0.0, 4.0}, {7.0, -3.0, 2.0}}).norm(), 1e-12);
}
