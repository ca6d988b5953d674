// The factors inside a real Ceres problem with PoseManifold: small problems built from exact
// measurements, started off the truth, must come back to it. Checks what the Jacobian tests
// cannot: that the block layout, the 7-column Jacobians and the manifold fit together in a solve.
#include <dynslam/estimator/factors/DepthMeasurementFactor.h>
#include <dynslam/estimator/factors/RigidObjectReprojectionFactor.h>
#include <dynslam/estimator/factors/RigidSmoothMotionFactor.h>
#include <dynslam/estimator/factors/StaticReprojectionFactor.h>

#include "FactorTestStates.h"

#include <ceres/loss_function.h>
#include <ceres/problem.h>
#include <ceres/solver.h>

#include <gtest/gtest.h>

#include <array>
#include <cstdio>

using namespace dynslam::estimator;
using namespace dynslam::estimator::testing;

namespace {

double positionError(const std::vector<double>& block, const Eigen::Isometry3d& truth) {
  return (poseFromBlock(block.data()).translation() - truth.translation()).norm();
}

double angleError(const std::vector<double>& block, const Eigen::Isometry3d& truth) {
  return Eigen::AngleAxisd(poseFromBlock(block.data()).rotation().transpose() * truth.rotation())
      .angle();
}

ceres::Solver::Summary solve(ceres::Problem& problem) {
  ceres::Solver::Options options;
  options.max_num_iterations = 50;
  options.function_tolerance = 1e-14;
  options.gradient_tolerance = 1e-14;
  options.parameter_tolerance = 1e-14;
  ceres::Solver::Summary summary;
  ceres::Solve(options, &problem, &summary);
  std::printf("%s\n", summary.BriefReport().c_str());
  return summary;
}

}  // namespace

TEST(FactorSolve, StaticFeaturesWithDepthRecoverTheSecondKeyframeAndTheInverseDepths) {
  std::mt19937 rng(71);
  const PinholeCamera cam = testCamera();
  const Eigen::Isometry3d T_wbi = randomPose(rng, 3.0, M_PI);
  const Eigen::Isometry3d T_bc = randomExtrinsic(rng);
  const Eigen::Isometry3d T_wbj = T_wbi * randomPose(rng, 0.4, 0.2);

  std::vector<double> pose_i = poseBlock(T_wbi), extrinsic = poseBlock(T_bc);
  // Start 10 cm and about 3 deg away.
  std::vector<double> pose_j = poseBlock(T_wbj * randomPose(rng, 0.1, 0.05));
  ceres::Problem problem;
  problem.AddParameterBlock(pose_i.data(), kPoseSize, new PoseManifold);
  problem.AddParameterBlock(pose_j.data(), kPoseSize, new PoseManifold);
  problem.AddParameterBlock(extrinsic.data(), kPoseSize, new PoseManifold);
  problem.SetParameterBlockConstant(pose_i.data());  // the gauge
  problem.SetParameterBlockConstant(extrinsic.data());
  double timeOffset = 0.0;  // no offset, held
  problem.AddParameterBlock(&timeOffset, 1);
  problem.SetParameterBlockConstant(&timeOffset);

  std::vector<std::array<double, 1>> lambdas;
  std::vector<double> trueLambdas;
  lambdas.reserve(40);
  while (lambdas.size() < 40) {
    const Eigen::Vector3d p_ci = randomPointInView(rng, cam);
    const Eigen::Vector3d p_cj = T_bc.inverse() * T_wbj.inverse() * T_wbi * T_bc * p_ci;
    if (p_cj.z() < 0.5) continue;
    trueLambdas.push_back(1.0 / p_ci.z());
    lambdas.push_back({1.1 / p_ci.z()});  // 10 % off
    double* lambda = lambdas.back().data();
    problem.AddResidualBlock(
        new StaticReprojectionFactor(cam, cam.project(p_ci), cam.project(p_cj), 1.5),
        new ceres::HuberLoss(1.0), pose_i.data(), pose_j.data(), extrinsic.data(), lambda,
        &timeOffset);
    problem.AddResidualBlock(new DepthMeasurementFactor(p_ci.z()), nullptr, lambda);
    problem.SetParameterLowerBound(lambda, 0, 1e-3);
  }
  const ceres::Solver::Summary summary = solve(problem);
  ASSERT_TRUE(summary.IsSolutionUsable()) << summary.BriefReport();
  EXPECT_LT(summary.final_cost, 1e-12);
  EXPECT_LT(positionError(pose_j, T_wbj), 1e-6);
  EXPECT_LT(angleError(pose_j, T_wbj), 1e-7);
  for (size_t k = 0; k < lambdas.size(); ++k) EXPECT_NEAR(lambdas[k][0], trueLambdas[k], 1e-7);
}

namespace {

/// A robot creeping forward (body poses) while a car 6-8 m ahead drives across with a constant
/// motion, 0.25 m and 3 deg of yaw per keyframe (object poses).
void crossingCar(int frames, std::vector<Eigen::Isometry3d>& bodies,
                 std::vector<Eigen::Isometry3d>& objects) {
  Eigen::Isometry3d motion = Eigen::Isometry3d::Identity();
  motion.translation() = Eigen::Vector3d(0.0, -0.25, 0.0);
  motion.linear() = Eigen::AngleAxisd(0.05, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  Eigen::Isometry3d L0 = Eigen::Isometry3d::Identity();
  L0.translation() = Eigen::Vector3d(7.0, 0.5, 0.0);
  for (int n = 0; n < frames; ++n) {
    Eigen::Isometry3d body = Eigen::Isometry3d::Identity();
    body.translation().x() = 0.1 * n;
    bodies.push_back(body);
    objects.push_back(n == 0 ? L0 : objects.back() * motion);
  }
}

}  // namespace

TEST(FactorSolve, RigidObjectPosesComeBackFromFeaturesAndSmoothMotion) {
  // Body poses and the extrinsic are known; the car's first pose is held (the object-frame
  // gauge, RigidObjectReprojectionFactor.h).
  std::mt19937 rng(72);
  const PinholeCamera cam = testCamera();
  const Eigen::Isometry3d T_bc = randomExtrinsic(rng);  // camera looks along body x
  constexpr int kFrames = 4;
  std::vector<Eigen::Isometry3d> bodies, objects;
  crossingCar(kFrames, bodies, objects);

  ceres::Problem problem;
  std::vector<std::vector<double>> bodyBlocks, objectBlocks;
  std::vector<double> extrinsic = poseBlock(T_bc);
  problem.AddParameterBlock(extrinsic.data(), kPoseSize, new PoseManifold);
  problem.SetParameterBlockConstant(extrinsic.data());
  for (int n = 0; n < kFrames; ++n) {
    bodyBlocks.push_back(poseBlock(bodies[n]));
    objectBlocks.push_back(poseBlock(n == 0 ? objects[n] : objects[n] * randomPose(rng, 0.2, 0.1)));
  }
  for (int n = 0; n < kFrames; ++n) {
    problem.AddParameterBlock(bodyBlocks[n].data(), kPoseSize, new PoseManifold);
    problem.SetParameterBlockConstant(bodyBlocks[n].data());
    problem.AddParameterBlock(objectBlocks[n].data(), kPoseSize, new PoseManifold);
  }
  problem.SetParameterBlockConstant(objectBlocks[0].data());

  std::vector<std::array<double, 3>> points(25);
  for (auto& m : points) {
    const Eigen::Vector3d truth = uniformVector(rng, 1.0);
    const Eigen::Vector3d start = truth + uniformVector(rng, 0.1);
    m = {start.x(), start.y(), start.z()};
    for (int n = 0; n < kFrames; ++n) {
      const Eigen::Vector3d p_c = T_bc.inverse() * (bodies[n].inverse() * (objects[n] * truth));
      ASSERT_GT(p_c.z(), 1.0);
      problem.AddResidualBlock(new RigidObjectReprojectionFactor(cam, cam.project(p_c), 1.5),
                               new ceres::CauchyLoss(1.0), bodyBlocks[n].data(), extrinsic.data(),
                               objectBlocks[n].data(), m.data());
    }
  }
  for (int n = 2; n < kFrames; ++n)
    problem.AddResidualBlock(new RigidSmoothMotionFactor(0.05, 0.02), nullptr,
                             objectBlocks[n - 2].data(), objectBlocks[n - 1].data(),
                             objectBlocks[n].data());
  const ceres::Solver::Summary summary = solve(problem);
  ASSERT_TRUE(summary.IsSolutionUsable()) << summary.BriefReport();
  EXPECT_LT(summary.final_cost, 1e-12);
  for (int n = 1; n < kFrames; ++n) {
    EXPECT_LT(positionError(objectBlocks[n], objects[n]), 1e-6) << n;
    EXPECT_LT(angleError(objectBlocks[n], objects[n]), 1e-7) << n;
  }
}
