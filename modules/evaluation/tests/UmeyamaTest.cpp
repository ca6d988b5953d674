// Umeyama alignment recovers known similarities exactly, keeps rotations proper when the best
// orthogonal fit is a reflection, and refuses degenerate point sets.
#include <dynslam/evaluation/EvaluationError.h>
#include <dynslam/evaluation/Umeyama.h>

#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include <random>

namespace ev = dynslam::evaluation;

namespace {

Eigen::Matrix3Xd randomPoints(int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-10.0, 10.0);
  Eigen::Matrix3Xd pts(3, n);
  for (int i = 0; i < n; ++i) pts.col(i) = Eigen::Vector3d(u(rng), u(rng), u(rng));
  return pts;
}

Eigen::Matrix3d knownRotation() {
  return Eigen::AngleAxisd(1.1, Eigen::Vector3d(0.3, -0.5, 0.8).normalized()).toRotationMatrix();
}

Eigen::Matrix3Xd transformed(const Eigen::Matrix3Xd& x, const Eigen::Matrix3d& r,
                             const Eigen::Vector3d& t, double s) {
  return (s * (r * x)).colwise() + t;
}

}  // namespace

TEST(EvalUmeyama, RecoversKnownSim3WithScale) {
  const Eigen::Matrix3Xd x = randomPoints(50, 1);
  const Eigen::Matrix3d r = knownRotation();
  const Eigen::Vector3d t(4.0, -2.5, 7.25);
  const double s = 2.75;
  const ev::SimilarityTransform fit = ev::umeyamaAlignment(x, transformed(x, r, t, s), true);
  EXPECT_NEAR((fit.rotation - r).cwiseAbs().maxCoeff(), 0.0, 1e-12);
  EXPECT_NEAR((fit.translation - t).cwiseAbs().maxCoeff(), 0.0, 1e-11);
  EXPECT_NEAR(fit.scale, s, 1e-12);
  EXPECT_NEAR(fit.rotation.determinant(), 1.0, 1e-12);
}

TEST(EvalUmeyama, RecoversKnownSe3WithoutScale) {
  const Eigen::Matrix3Xd x = randomPoints(20, 2);
  const Eigen::Matrix3d r = knownRotation();
  const Eigen::Vector3d t(-1.0, 0.5, 3.0);
  const ev::SimilarityTransform fit = ev::umeyamaAlignment(x, transformed(x, r, t, 1.0), false);
  EXPECT_NEAR((fit.rotation - r).cwiseAbs().maxCoeff(), 0.0, 1e-12);
  EXPECT_NEAR((fit.translation - t).cwiseAbs().maxCoeff(), 0.0, 1e-12);
  EXPECT_EQ(fit.scale, 1.0);
}

TEST(EvalUmeyama, WithoutScaleKeepsScaleOneOnScaledData) {
  // Scaled data, scale not estimated: the rotation is still exact (the cross-covariance only
  // grows by s), the scale stays 1 and the translation maps the centroids onto each other.
  const Eigen::Matrix3Xd x = randomPoints(30, 3);
  const Eigen::Matrix3d r = knownRotation();
  const Eigen::Vector3d t(2.0, 2.0, -2.0);
  const Eigen::Matrix3Xd y = transformed(x, r, t, 0.5);
  const ev::SimilarityTransform fit = ev::umeyamaAlignment(x, y, false);
  EXPECT_EQ(fit.scale, 1.0);
  EXPECT_NEAR((fit.rotation - r).cwiseAbs().maxCoeff(), 0.0, 1e-12);
  const Eigen::Vector3d expected_t = y.rowwise().mean() - r * x.rowwise().mean();
  EXPECT_NEAR((fit.translation - expected_t).cwiseAbs().maxCoeff(), 0.0, 1e-12);
}

TEST(EvalUmeyama, ScaleEstimateMatchesUmeyamaFormulaOnNoisyData) {
  // With noise the fit is no longer exact; compare with Eigen's own, independently written
  // Umeyama implementation.
  const Eigen::Matrix3Xd x = randomPoints(200, 4);
  Eigen::Matrix3Xd y = transformed(x, knownRotation(), Eigen::Vector3d(1, 2, 3), 1.7);
  std::mt19937 rng(5);
  std::normal_distribution<double> noise(0.0, 0.05);
  for (int i = 0; i < y.cols(); ++i)
    y.col(i) += Eigen::Vector3d(noise(rng), noise(rng), noise(rng));
  const ev::SimilarityTransform fit = ev::umeyamaAlignment(x, y, true);
  const Eigen::Matrix4d eigen_fit = Eigen::umeyama(x, y, true);
  const double eigen_scale = std::cbrt(eigen_fit.block<3, 3>(0, 0).determinant());
  EXPECT_NEAR(fit.scale, eigen_scale, 1e-12);
  EXPECT_NEAR((fit.rotation - eigen_fit.block<3, 3>(0, 0) / eigen_scale).cwiseAbs().maxCoeff(), 0.0,
              1e-12);
  EXPECT_NEAR((fit.translation - eigen_fit.block<3, 1>(0, 3)).cwiseAbs().maxCoeff(), 0.0, 1e-10);
  EXPECT_NEAR(fit.scale, 1.7, 0.01);
}

TEST(EvalUmeyama, MirroredPlanarPointsGiveProperRotationNotReflection) {
  // Points in the z = 0 plane mirrored at the x-z plane (y -> -y). The best orthogonal map is
  // the reflection diag(1, -1, 1), which is not a rotation; the sign correction must instead
  // return the half turn about x, diag(1, -1, -1), which fits the planar points exactly.
  Eigen::Matrix3Xd x = randomPoints(25, 6);
  x.row(2).setZero();
  const Eigen::Matrix3d mirror = Eigen::Vector3d(1, -1, 1).asDiagonal();
  const Eigen::Vector3d t(0.5, -0.25, 2.0);
  const Eigen::Matrix3Xd y = (mirror * x).colwise() + t;
  const ev::SimilarityTransform fit = ev::umeyamaAlignment(x, y, true);
  const Eigen::Matrix3d half_turn = Eigen::Vector3d(1, -1, -1).asDiagonal();
  EXPECT_NEAR(fit.rotation.determinant(), 1.0, 1e-12);
  EXPECT_NEAR((fit.rotation - half_turn).cwiseAbs().maxCoeff(), 0.0, 1e-12);
  EXPECT_NEAR(fit.scale, 1.0, 1e-12);
  EXPECT_NEAR((fit.translation - t).cwiseAbs().maxCoeff(), 0.0, 1e-12);
}

TEST(EvalUmeyama, MirroredSpatialPointsStillGiveARotation) {
  // A true 3-D reflection cannot be fitted by any rotation; the result must still be proper
  // (det = +1) and orthonormal, and the residual must be larger than zero.
  const Eigen::Matrix3Xd x = randomPoints(40, 7);
  const Eigen::Matrix3d mirror = Eigen::Vector3d(1, 1, -1).asDiagonal();
  const Eigen::Matrix3Xd y = mirror * x;
  const ev::SimilarityTransform fit = ev::umeyamaAlignment(x, y, false);
  EXPECT_NEAR(fit.rotation.determinant(), 1.0, 1e-12);
  EXPECT_NEAR((fit.rotation.transpose() * fit.rotation - Eigen::Matrix3d::Identity()).norm(), 0.0,
              1e-12);
  const Eigen::Matrix3Xd mapped = (fit.rotation * x).colwise() + fit.translation;
  EXPECT_GT((mapped - y).norm(), 1.0);
}

TEST(EvalUmeyama, RejectsDegenerateAndMismatchedInput) {
  Eigen::Matrix3Xd line(3, 5);
  for (int i = 0; i < 5; ++i) line.col(i) = Eigen::Vector3d(i, 2.0 * i, -i);
  EXPECT_THROW(ev::umeyamaAlignment(line, line, false), ev::EvaluationError);
  EXPECT_THROW(ev::umeyamaAlignment(randomPoints(4, 8), randomPoints(5, 8), false),
               ev::EvaluationError);
  EXPECT_THROW(ev::umeyamaAlignment(Eigen::Matrix3Xd(3, 0), Eigen::Matrix3Xd(3, 0), false),
               ev::EvaluationError);
}
