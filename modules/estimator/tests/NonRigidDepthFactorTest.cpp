// NonRigidDepthFactor: zero at the true state, the depth error whitened by sigma_d, analytic
// Jacobians equal to numeric ones.
#include <dynslam/estimator/factors/NonRigidDepthFactor.h>

#include "FactorJacobianCheck.h"
#include "FactorTestStates.h"

#include <gtest/gtest.h>

using namespace dynslam::estimator;
using namespace dynslam::estimator::testing;

TEST(NonRigidDepthFactor, ZeroAtTheTruthAndJacobiansMatchNumeric) {
  std::mt19937 rng(21);
  for (int trial = 0; trial < 20; ++trial) {
    const Eigen::Isometry3d T_wb = randomPose(rng, 5.0, M_PI), T_bc = randomExtrinsic(rng);
    const Eigen::Vector3d p_c = randomPointInView(rng, testCamera());
    const Eigen::Vector3d v_w = uniformVector(rng, 1.5);
    const double dt = std::uniform_real_distribution<double>(-1.0, 1.0)(rng);
    const Eigen::Vector3d p_w0 = T_wb * (T_bc * p_c) - dt * v_w;
    const DepthNoiseModel noise;
    const NonRigidDepthFactor atTruth(dt, p_c.z(), noise);
    std::vector<std::vector<double>> blocks = {poseBlock(T_wb), poseBlock(T_bc),
                                               {p_w0.x(), p_w0.y(), p_w0.z()},
                                               {v_w.x(), v_w.y(), v_w.z()}};
    std::vector<double*> params;
    for (auto& b : blocks) params.push_back(b.data());
    double r = 1;
    ASSERT_TRUE(atTruth.Evaluate(params.data(), &r, nullptr));
    EXPECT_NEAR(r, 0.0, 1e-9);
    const NonRigidDepthFactor off(dt, p_c.z() + 0.1, noise);
    ASSERT_TRUE(off.Evaluate(params.data(), &r, nullptr));
    EXPECT_NEAR(r, -0.1 / noise.sigma(p_c.z() + 0.1), 1e-9);
    const JacobianMismatch m = compareJacobians(off, blocks, {true, true, false, false});
    EXPECT_LT(m.max_rel_error, 1e-5) << m.where;
  }
}
