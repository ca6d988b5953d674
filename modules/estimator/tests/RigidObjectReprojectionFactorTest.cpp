#include <dynslam/estimator/factors/RigidObjectReprojectionFactor.h>

#include "FactorJacobianCheck.h"
#include "FactorTestStates.h"

#include <gtest/gtest.h>

using namespace dynslam::estimator;
using namespace dynslam::estimator::testing;

namespace {

/// A point on a car seen at keyframe n: body pose, extrinsic, object pose L_n, point in the
/// object frame.
struct ObjectPoint {
  Eigen::Isometry3d T_wb, T_bc, L_n;
  Eigen::Vector3d m_obj;
  Eigen::Vector2d pixel;  ///< exact
};

ObjectPoint randomObjectPoint(std::mt19937& rng) {
  ObjectPoint o;
  o.T_wb = randomPose(rng, 5.0, M_PI);
  o.T_bc = randomExtrinsic(rng);
  o.L_n = randomPose(rng, 8.0, M_PI);
  const Eigen::Vector3d p_c = randomPointInView(rng, testCamera());
  o.pixel = testCamera().project(p_c);
  o.m_obj = o.L_n.inverse() * (o.T_wb * (o.T_bc * p_c));
  return o;
}

std::vector<std::vector<double>> blocksOf(const ObjectPoint& o) {
  return {poseBlock(o.T_wb), poseBlock(o.T_bc), poseBlock(o.L_n),
          {o.m_obj.x(), o.m_obj.y(), o.m_obj.z()}};
}

}  // namespace

TEST(RigidObjectReprojectionFactor, AnalyticJacobianMatchesNumericAtRandomStates) {
  std::mt19937 rng(41);
  std::normal_distribution<double> pixelNoise(0.0, 3.0);
  double worst = 0;
  for (int trial = 0; trial < 20; ++trial) {
    const ObjectPoint o = randomObjectPoint(rng);
    const Eigen::Vector2d observed = o.pixel + Eigen::Vector2d(pixelNoise(rng), pixelNoise(rng));
    const RigidObjectReprojectionFactor f(testCamera(), observed, 1.5);
    const JacobianMismatch m = compareJacobians(f, blocksOf(o), {true, true, true, false});
    EXPECT_LT(m.max_rel_error, 1e-5) << "trial " << trial << ": " << m.where;
    worst = std::max(worst, m.max_rel_error);
  }
  std::printf("worst relative Jacobian error over 20 states: %.1e\n", worst);
}

TEST(RigidObjectReprojectionFactor, ResidualIsZeroAtTheTrueState) {
  std::mt19937 rng(42);
  for (int trial = 0; trial < 10; ++trial) {
    const ObjectPoint o = randomObjectPoint(rng);
    const RigidObjectReprojectionFactor f(testCamera(), o.pixel, 1.5);
    EXPECT_LT(residualAt<2>(f, blocksOf(o)).norm(), 1e-9) << trial;
  }
}

TEST(RigidObjectReprojectionFactor, PredictsWhatThePapersEquation19Predicts) {
  // m_n = L_n L_{n-1}^-1 m_{n-1} (paper) with m_{n-1} = L_{n-1} m_obj is L_n m_obj (here):
  // project the paper's m_n by hand and compare with the factor's residual.
  std::mt19937 rng(43);
  const PinholeCamera cam = testCamera();
  for (int trial = 0; trial < 10; ++trial) {
    ObjectPoint o = randomObjectPoint(rng);
    const Eigen::Isometry3d L_prev = o.L_n * randomPose(rng, 0.5, 0.2).inverse();
    const Eigen::Vector3d m_prev = L_prev * o.m_obj;
    const Eigen::Vector3d m_n = o.L_n * L_prev.inverse() * m_prev;
    const Eigen::Vector2d paper = cam.project(o.T_bc.inverse() * (o.T_wb.inverse() * m_n));
    const Eigen::Vector2d observed(300.0, 200.0);
    const RigidObjectReprojectionFactor f(cam, observed, 1.5);
    EXPECT_LT((residualAt<2>(f, blocksOf(o)) - (observed - paper) / 1.5).norm(), 1e-9);
  }
}

TEST(RigidObjectReprojectionFactor, KnownObjectMotionGivesTheExpectedPixelError) {
  // Body = camera = world; the feature 4 m ahead on the object's frame origin axis.
  const PinholeCamera cam = testCamera();
  const double sigma = 1.5;
  const RigidObjectReprojectionFactor f(cam, {cam.cx, cam.cy}, sigma);
  const std::vector<double> I = poseBlock(Eigen::Isometry3d::Identity());
  const std::vector<double> m = {0.0, 0.0, 4.0};
  EXPECT_LT(residualAt<2>(f, {I, I, I, m}).norm(), 1e-12);
  // The object 0.1 m lower (camera y down): the prediction moves fy * 0.1 / 4 pixels down.
  Eigen::Isometry3d lower = Eigen::Isometry3d::Identity();
  lower.translation().y() = 0.1;
  Eigen::Vector2d r = residualAt<2>(f, {I, I, poseBlock(lower), m});
  EXPECT_NEAR(r.x(), 0.0, 1e-12);
  EXPECT_NEAR(r.y(), -cam.fy * 0.025 / sigma, 1e-9);
  // The object turned by a about camera y: the point goes to (4 sin a, 0, 4 cos a), which
  // projects fx tan a pixels right of the centre.
  const double a = 0.1;
  Eigen::Isometry3d turned = Eigen::Isometry3d::Identity();
  turned.linear() = Eigen::AngleAxisd(a, Eigen::Vector3d::UnitY()).toRotationMatrix();
  r = residualAt<2>(f, {I, I, poseBlock(turned), m});
  EXPECT_NEAR(r.x(), -cam.fx * std::tan(a) / sigma, 1e-9);
  EXPECT_NEAR(r.y(), 0.0, 1e-12);
}
