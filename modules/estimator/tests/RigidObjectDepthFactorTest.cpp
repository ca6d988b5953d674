// RigidObjectDepthFactor: zero at the true state, the depth error whitened by sigma_d, analytic
// Jacobians equal to numeric ones (the object pose's included).
#include <dynslam/estimator/factors/RigidObjectDepthFactor.h>

#include "FactorJacobianCheck.h"
#include "FactorTestStates.h"

#include <gtest/gtest.h>

using namespace dynslam::estimator;
using namespace dynslam::estimator::testing;

TEST(RigidObjectDepthFactor, ZeroAtTheTruthAndJacobiansMatchNumeric) {
  std::mt19937 rng(23);
  for (int trial = 0; trial < 20; ++trial) {
    const Eigen::Isometry3d T_wb = randomPose(rng, 5.0, M_PI), T_bc = randomExtrinsic(rng);
    const Eigen::Isometry3d L_n = randomPose(rng, 5.0, M_PI);
    const Eigen::Vector3d p_c = randomPointInView(rng, testCamera());
    const Eigen::Vector3d m_obj = L_n.inverse() * (T_wb * (T_bc * p_c));
    const DepthNoiseModel noise;
    std::vector<std::vector<double>> blocks = {
        poseBlock(T_wb), poseBlock(T_bc), poseBlock(L_n), {m_obj.x(), m_obj.y(), m_obj.z()}};
    std::vector<double*> params;
    for (auto& b : blocks) params.push_back(b.data());
    double r = 1;
    const RigidObjectDepthFactor atTruth(p_c.z(), noise);
    ASSERT_TRUE(atTruth.Evaluate(params.data(), &r, nullptr));
    EXPECT_NEAR(r, 0.0, 1e-9);
    const RigidObjectDepthFactor off(p_c.z() + 0.1, noise);
    ASSERT_TRUE(off.Evaluate(params.data(), &r, nullptr));
    EXPECT_NEAR(r, -0.1 / noise.sigma(p_c.z() + 0.1), 1e-9);
    const JacobianMismatch m = compareJacobians(off, blocks, {true, true, true, false});
    EXPECT_LT(m.max_rel_error, 1e-5) << m.where;
  }
}
