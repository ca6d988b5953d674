#include <dynslam/estimator/factors/StaticReprojectionFactor.h>

#include "FactorJacobianCheck.h"
#include "FactorTestStates.h"

#include <gtest/gtest.h>

using namespace dynslam::estimator;
using namespace dynslam::estimator::testing;

namespace {
/// The static scene's blocks and a time offset t_d (s).
std::vector<std::vector<double>> withTimeOffset(const StaticScene& s, double td) {
  auto blocks = blocksOf(s);
  blocks.push_back({td});
  return blocks;
}
}  // namespace

TEST(StaticReprojectionFactor, AnalyticJacobianMatchesNumericAtRandomStates) {
  std::mt19937 rng(11);
  std::normal_distribution<double> pixelNoise(0.0, 3.0);
  double worst = 0;
  for (int trial = 0; trial < 20; ++trial) {
    const StaticScene s = randomStaticScene(rng);
    // Off the true state, so the residual's curvature shows in the check.
    const Eigen::Vector2d observed = s.pixel_j + Eigen::Vector2d(pixelNoise(rng), pixelNoise(rng));
    const StaticReprojectionFactor f(testCamera(), s.pixel_i, observed, 1.5);
    const JacobianMismatch m =
        compareJacobians(f, withTimeOffset(s, 0.0), {true, true, true, false, false});
    EXPECT_LT(m.max_rel_error, 1e-5) << "trial " << trial << ": " << m.where;
    worst = std::max(worst, m.max_rel_error);
  }
  std::printf("worst relative Jacobian error over 20 states: %.1e\n", worst);
}

TEST(StaticReprojectionFactor, ResidualIsZeroAtTheTrueState) {
  std::mt19937 rng(12);
  for (int trial = 0; trial < 10; ++trial) {
    const StaticScene s = randomStaticScene(rng);
    const StaticReprojectionFactor f(testCamera(), s.pixel_i, s.pixel_j, 1.5);
    EXPECT_LT(residualAt<2>(f, withTimeOffset(s, 0.0)).norm(), 1e-9) << trial;
  }
}

TEST(StaticReprojectionFactor, KnownPerturbationGivesTheExpectedWhitenedPixelError) {
  // Body = camera = world at i; a point 4 m straight ahead, seen at the principal point from
  // both frames. Moving frame j 0.2 m to the right (camera x) moves the prediction
  // fx * 0.2 / 4 pixels to the left, so observed - predicted = +fx * 0.05 / sigma in u.
  const PinholeCamera cam = testCamera();
  const double sigma = 1.5;
  const Eigen::Vector2d centre(cam.cx, cam.cy);
  const StaticReprojectionFactor f(cam, centre, centre, sigma);
  const Eigen::Isometry3d I = Eigen::Isometry3d::Identity();
  Eigen::Isometry3d moved = I;
  moved.translation().x() = 0.2;
  EXPECT_LT(residualAt<2>(f, {poseBlock(I), poseBlock(I), poseBlock(I), {0.25}, {0.0}}).norm(),
            1e-12);
  const Eigen::Vector2d r =
      residualAt<2>(f, {poseBlock(I), poseBlock(moved), poseBlock(I), {0.25}, {0.0}});
  EXPECT_NEAR(r.x(), cam.fx * 0.05 / sigma, 1e-9);
  EXPECT_NEAR(r.y(), 0.0, 1e-12);
  // Along the optical axis nothing moves, whatever the depth.
  EXPECT_LT(residualAt<2>(f, {poseBlock(I), poseBlock(I), poseBlock(I), {0.9}, {0.0}}).norm(),
            1e-12);
}

TEST(StaticReprojectionFactor, RefusesPointsBehindTheCameraAndNonPositiveInverseDepth) {
  const PinholeCamera cam = testCamera();
  const StaticReprojectionFactor f(cam, {cam.cx, cam.cy}, {cam.cx, cam.cy}, 1.5);
  const Eigen::Isometry3d I = Eigen::Isometry3d::Identity();
  Eigen::Isometry3d ahead = I;
  ahead.translation().z() = 5.0;  // camera j beyond the point (4 m): the point is behind it
  std::vector<std::vector<double>> b = {
      poseBlock(I), poseBlock(ahead), poseBlock(I), {0.25}, {0.0}};
  std::vector<double*> p;
  for (auto& x : b) p.push_back(x.data());
  double r[2];
  EXPECT_FALSE(f.Evaluate(p.data(), r, nullptr));
  b[1] = poseBlock(I);
  b[3][0] = 0.0;
  EXPECT_FALSE(f.Evaluate(p.data(), r, nullptr));
}

TEST(StaticReprojectionFactor, TimeOffsetJacobianMatchesNumericWithMovingPixels) {
  // Features moving across the image at up to 400 px/s, offsets of up to 40 ms: the t_d column
  // and every other block's, off the true state.
  std::mt19937 rng(13);
  std::normal_distribution<double> pixelNoise(0.0, 3.0), speed(0.0, 200.0);
  std::uniform_real_distribution<double> offset(-0.04, 0.04);
  double worst = 0;
  for (int trial = 0; trial < 20; ++trial) {
    const StaticScene s = randomStaticScene(rng);
    const Eigen::Vector2d vi(speed(rng), speed(rng)), vj(speed(rng), speed(rng));
    const Eigen::Vector2d observed = s.pixel_j + Eigen::Vector2d(pixelNoise(rng), pixelNoise(rng));
    const StaticReprojectionFactor f(testCamera(), s.pixel_i, observed, 1.5, vi, vj);
    const JacobianMismatch m =
        compareJacobians(f, withTimeOffset(s, offset(rng)), {true, true, true, false, false});
    EXPECT_LT(m.max_rel_error, 1e-5) << "trial " << trial << ": " << m.where;
    worst = std::max(worst, m.max_rel_error);
  }
  std::printf("worst relative Jacobian error with t_d over 20 states: %.1e\n", worst);
}

TEST(StaticReprojectionFactor, TheTrueTimeOffsetMovesBothPixelsBackToTheStateTime) {
  // The images were taken t_d after the states: each pixel seen t_d * v further along its
  // image motion. At the true t_d the residual vanishes; at t_d = 0 it is the unmoved error.
  std::mt19937 rng(14);
  const double td = 0.03;
  for (int trial = 0; trial < 10; ++trial) {
    const StaticScene s = randomStaticScene(rng);
    const Eigen::Vector2d vi(150.0, -80.0), vj(-60.0, 220.0);
    const StaticReprojectionFactor f(testCamera(), s.pixel_i + td * vi, s.pixel_j + td * vj, 1.0,
                                     vi, vj);
    EXPECT_LT(residualAt<2>(f, withTimeOffset(s, td)).norm(), 1e-6) << trial;
    EXPECT_GT(residualAt<2>(f, withTimeOffset(s, 0.0)).norm(), 1.0) << trial;
  }
}
