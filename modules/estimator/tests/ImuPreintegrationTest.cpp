// ImuPreintegration against an analytic motion: exact samples reproduce the relative motion,
// the first-order bias correction matches integrating again, the propagated covariance matches
// a Monte-Carlo spread, repropagation restores the exact result.
#include "ImuTestMotion.h"

#include <dynslam/estimator/imu/ImuPreintegration.h>

#include <gtest/gtest.h>

#include <random>

using namespace dynslam::estimator;
using namespace dynslam::estimator::testing;

namespace {

constexpr double kRate = 200.0;

ImuPreintegration integrate(double t0, double duration, const Eigen::Vector3d& ba,
                            const Eigen::Vector3d& bg, const Eigen::Vector3d& trueBa,
                            const Eigen::Vector3d& trueBg, std::mt19937* rng = nullptr,
                            const ImuNoise& noise = {}) {
  const double dt = 1.0 / kRate;
  std::normal_distribution<double> n(0.0, 1.0);
  const auto sample = [&](double t, Eigen::Vector3d& acc, Eigen::Vector3d& gyr) {
    acc = specificForce(t) + trueBa;
    gyr = bodyRate() + trueBg;
    if (rng) {
      for (int k = 0; k < 3; ++k) {
        acc(k) += noise.acc_noise / std::sqrt(dt) * n(*rng);
        gyr(k) += noise.gyro_noise / std::sqrt(dt) * n(*rng);
      }
    }
  };
  Eigen::Vector3d acc, gyr;
  sample(t0, acc, gyr);
  ImuPreintegration pre(acc, gyr, ba, bg, noise);
  const int steps = int(std::lround(duration * kRate));
  for (int k = 1; k <= steps; ++k) {
    sample(t0 + k * dt, acc, gyr);
    pre.push(dt, acc, gyr);
  }
  return pre;
}

}  // namespace

TEST(ImuPreintegration, ExactSamplesPredictTheRelativeMotion) {
  const Eigen::Vector3d zero = Eigen::Vector3d::Zero();
  const ImuPreintegration pre = integrate(1.0, 0.5, zero, zero, zero, zero);
  EXPECT_NEAR(pre.sumDt(), 0.5, 1e-12);
  const MotionState i = motionAt(1.0), j = motionAt(1.5);
  Eigen::Vector3d p, v;
  Eigen::Quaterniond q;
  pre.predict(i.p, i.q, i.v, zero, zero, kTestGravity, p, q, v);
  EXPECT_LT((p - j.p).norm(), 1e-4) << "midpoint rule at 200 Hz over 0.5 s";
  EXPECT_LT((v - j.v).norm(), 1e-4);
  EXPECT_LT(q.angularDistance(j.q), 1e-6);
}

TEST(ImuPreintegration, FirstOrderBiasCorrectionMatchesIntegratingAgain) {
  const Eigen::Vector3d zero = Eigen::Vector3d::Zero();
  const Eigen::Vector3d ba(0.05, -0.03, 0.04), bg(0.004, -0.006, 0.003);
  const ImuPreintegration atZero = integrate(0.3, 0.5, zero, zero, zero, zero);
  const ImuPreintegration atBias = integrate(0.3, 0.5, ba, bg, zero, zero);
  // Integrating with bias (ba, bg) removed, vs correcting the zero-bias result to first order.
  const double dpFull = (atBias.alpha() - atZero.alpha()).norm();
  const double dpError = (atZero.deltaPosition(ba, bg) - atBias.alpha()).norm();
  const double dvFull = (atBias.beta() - atZero.beta()).norm();
  const double dvError = (atZero.deltaVelocity(ba, bg) - atBias.beta()).norm();
  const double dqFull = atBias.gamma().angularDistance(atZero.gamma());
  const double dqError = atZero.deltaRotation(bg).angularDistance(atBias.gamma());
  EXPECT_GT(dpFull, 5e-3);
  EXPECT_LT(dpError, 0.02 * dpFull) << dpError << " of " << dpFull;
  EXPECT_LT(dvError, 0.02 * dvFull) << dvError << " of " << dvFull;
  EXPECT_LT(dqError, 0.02 * dqFull) << dqError << " of " << dqFull;

  EXPECT_FALSE(atZero.needsRepropagation(ba, bg));
  EXPECT_TRUE(atZero.needsRepropagation(ba, Eigen::Vector3d(0.02, 0, 0)));
  ImuPreintegration again = atZero;
  again.repropagate(ba, bg);
  EXPECT_LT((again.alpha() - atBias.alpha()).norm(), 1e-12);
  EXPECT_LT(again.gamma().angularDistance(atBias.gamma()), 1e-12);
  EXPECT_EQ(again.linearizedBa(), ba);
}

TEST(ImuPreintegration, CovarianceMatchesTheSpreadOfNoisyRuns) {
  const Eigen::Vector3d zero = Eigen::Vector3d::Zero();
  ImuNoise noise;
  noise.acc_noise = 0.05;
  noise.gyro_noise = 0.005;
  std::mt19937 rng(7);
  const ImuPreintegration exact = integrate(0.0, 0.5, zero, zero, zero, zero, nullptr, noise);
  constexpr int kRuns = 400;
  Eigen::Matrix<double, 9, 9> spread = Eigen::Matrix<double, 9, 9>::Zero();
  for (int k = 0; k < kRuns; ++k) {
    const ImuPreintegration noisy = integrate(0.0, 0.5, zero, zero, zero, zero, &rng, noise);
    Eigen::Matrix<double, 9, 1> e;
    e << noisy.alpha() - exact.alpha(),
        2.0 * (exact.gamma().inverse() * noisy.gamma()).vec(), noisy.beta() - exact.beta();
    spread += e * e.transpose() / kRuns;
  }
  const Matrix15d& P = exact.covariance();
  for (int block = 0; block < 3; ++block) {
    const double predicted = P.block<3, 3>(3 * block, 3 * block).trace();
    const double measured = spread.block<3, 3>(3 * block, 3 * block).trace();
    EXPECT_NEAR(measured / predicted, 1.0, 0.2)
        << "block " << block << ": predicted " << predicted << ", measured " << measured;
  }
}

TEST(ImuPreintegration, RejectsBadSamples) {
  const Eigen::Vector3d zero = Eigen::Vector3d::Zero();
  ImuPreintegration pre(zero, zero, zero, zero, ImuNoise{});
  EXPECT_THROW(pre.push(0.0, zero, zero), std::invalid_argument);
  EXPECT_THROW(pre.push(0.005, Eigen::Vector3d(NAN, 0, 0), zero), std::invalid_argument);
}
