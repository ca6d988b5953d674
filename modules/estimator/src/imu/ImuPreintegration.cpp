#include "dynslam/estimator/imu/ImuPreintegration.h"

#include "dynslam/estimator/StateBlocks.h"

#include <stdexcept>

namespace dynslam::estimator {
namespace {

enum : int { kP = 0, kR = 3, kV = 6, kBa = 9, kBg = 12 };

}  // namespace

ImuPreintegration::ImuPreintegration(const Eigen::Vector3d& acc0, const Eigen::Vector3d& gyr0,
                                     const Eigen::Vector3d& ba, const Eigen::Vector3d& bg,
                                     const ImuNoise& noise)
    : noise_(noise), acc0_(acc0), gyr0_(gyr0), ba_(ba), bg_(bg) {
  reset();
}

void ImuPreintegration::reset() {
  acc_ = acc0_;
  gyr_ = gyr0_;
  sum_dt_ = 0;
  alpha_.setZero();
  beta_.setZero();
  gamma_.setIdentity();
  jacobian_.setIdentity();
  covariance_.setZero();
}

void ImuPreintegration::push(double dt, const Eigen::Vector3d& acc, const Eigen::Vector3d& gyr) {
  if (!(dt > 0) || !acc.allFinite() || !gyr.allFinite())
    throw std::invalid_argument("ImuPreintegration::push: needs dt > 0 and finite samples (dt = " +
                                std::to_string(dt) + ")");
  samples_.push_back({dt, acc, gyr});
  midpointStep(dt, acc, gyr);
}

void ImuPreintegration::repropagate(const Eigen::Vector3d& ba, const Eigen::Vector3d& bg) {
  ba_ = ba;
  bg_ = bg;
  reset();
  for (const auto& s : samples_) midpointStep(s.dt, s.acc, s.gyr);
}

bool ImuPreintegration::needsRepropagation(const Eigen::Vector3d& ba,
                                           const Eigen::Vector3d& bg) const {
  return (ba - ba_).norm() > 0.10 || (bg - bg_).norm() > 0.01;
}

// Midpoint rule over [t, t + dt] between the previous sample (acc_, gyr_) and this one, and
// the discrete-time error propagation x_{k+1} = F x_k + V n of VINS-Mono (its F and V, written
// out below). A sample's white noise has variance sigma^2 / dt, but V treats the noise at the
// two ends of a step as independent with weight 1/2 each, while every sample really enters two
// consecutive steps: with sigma^2 / dt the propagated covariance is half the true spread (the
// Monte-Carlo test measured 2.0x). Hence 2 sigma^2 / dt per end. Bias random walks: sigma^2 dt.
void ImuPreintegration::midpointStep(double dt, const Eigen::Vector3d& acc1,
                                     const Eigen::Vector3d& gyr1) {
  const Eigen::Matrix3d R0 = gamma_.toRotationMatrix();
  const Eigen::Vector3d w = 0.5 * (gyr_ + gyr1) - bg_;
  const Eigen::Quaterniond gamma1 = (gamma_ * quaternionExp(w * dt)).normalized();
  const Eigen::Matrix3d R1 = gamma1.toRotationMatrix();
  const Eigen::Vector3d a0 = acc_ - ba_, a1 = acc1 - ba_;
  const Eigen::Vector3d a = 0.5 * (R0 * a0 + R1 * a1);
  const Eigen::Vector3d alpha1 = alpha_ + beta_ * dt + 0.5 * a * dt * dt;
  const Eigen::Vector3d beta1 = beta_ + a * dt;

  const Eigen::Matrix3d I = Eigen::Matrix3d::Identity();
  const Eigen::Matrix3d wx = skew(w), a0x = skew(a0), a1x = skew(a1);
  Matrix15d F = Matrix15d::Identity();
  F.block<3, 3>(kP, kR) =
      -0.25 * R0 * a0x * dt * dt - 0.25 * R1 * a1x * (I - wx * dt) * dt * dt;
  F.block<3, 3>(kP, kV) = I * dt;
  F.block<3, 3>(kP, kBa) = -0.25 * (R0 + R1) * dt * dt;
  F.block<3, 3>(kP, kBg) = 0.25 * R1 * a1x * dt * dt * dt;
  F.block<3, 3>(kR, kR) = I - wx * dt;
  F.block<3, 3>(kR, kBg) = -I * dt;
  F.block<3, 3>(kV, kR) = -0.5 * R0 * a0x * dt - 0.5 * R1 * a1x * (I - wx * dt) * dt;
  F.block<3, 3>(kV, kBa) = -0.5 * (R0 + R1) * dt;
  F.block<3, 3>(kV, kBg) = 0.5 * R1 * a1x * dt * dt;

  // Noise order: [n_a0, n_g0, n_a1, n_g1, n_ba, n_bg].
  Eigen::Matrix<double, 15, 18> V = Eigen::Matrix<double, 15, 18>::Zero();
  V.block<3, 3>(kP, 0) = 0.25 * R0 * dt * dt;
  V.block<3, 3>(kP, 3) = -0.125 * R1 * a1x * dt * dt * dt;
  V.block<3, 3>(kP, 6) = 0.25 * R1 * dt * dt;
  V.block<3, 3>(kP, 9) = V.block<3, 3>(kP, 3);
  V.block<3, 3>(kR, 3) = 0.5 * I * dt;
  V.block<3, 3>(kR, 9) = 0.5 * I * dt;
  V.block<3, 3>(kV, 0) = 0.5 * R0 * dt;
  V.block<3, 3>(kV, 3) = -0.25 * R1 * a1x * dt * dt;
  V.block<3, 3>(kV, 6) = 0.5 * R1 * dt;
  V.block<3, 3>(kV, 9) = V.block<3, 3>(kV, 3);
  V.block<3, 3>(kBa, 12) = I * dt;
  V.block<3, 3>(kBg, 15) = I * dt;

  Eigen::Matrix<double, 18, 1> variances;
  const double na = 2 * noise_.acc_noise * noise_.acc_noise / dt;
  const double ng = 2 * noise_.gyro_noise * noise_.gyro_noise / dt;
  const double wa = noise_.acc_random_walk * noise_.acc_random_walk / dt;
  const double wg = noise_.gyro_random_walk * noise_.gyro_random_walk / dt;
  variances << Eigen::Vector3d::Constant(na), Eigen::Vector3d::Constant(ng),
      Eigen::Vector3d::Constant(na), Eigen::Vector3d::Constant(ng), Eigen::Vector3d::Constant(wa),
      Eigen::Vector3d::Constant(wg);

  jacobian_ = F * jacobian_;
  covariance_ = F * covariance_ * F.transpose() + V * variances.asDiagonal() * V.transpose();
  alpha_ = alpha1;
  beta_ = beta1;
  gamma_ = gamma1;
  sum_dt_ += dt;
  acc_ = acc1;
  gyr_ = gyr1;
}

Eigen::Vector3d ImuPreintegration::deltaPosition(const Eigen::Vector3d& ba,
                                                 const Eigen::Vector3d& bg) const {
  return alpha_ + jacobian_.block<3, 3>(kP, kBa) * (ba - ba_) +
         jacobian_.block<3, 3>(kP, kBg) * (bg - bg_);
}

Eigen::Vector3d ImuPreintegration::deltaVelocity(const Eigen::Vector3d& ba,
                                                 const Eigen::Vector3d& bg) const {
  return beta_ + jacobian_.block<3, 3>(kV, kBa) * (ba - ba_) +
         jacobian_.block<3, 3>(kV, kBg) * (bg - bg_);
}

Eigen::Quaterniond ImuPreintegration::deltaRotation(const Eigen::Vector3d& bg) const {
  return (gamma_ * quaternionExp(jacobian_.block<3, 3>(kR, kBg) * (bg - bg_))).normalized();
}

void ImuPreintegration::predict(const Eigen::Vector3d& p_i, const Eigen::Quaterniond& q_i,
                                const Eigen::Vector3d& v_i, const Eigen::Vector3d& ba,
                                const Eigen::Vector3d& bg, const Eigen::Vector3d& gravity,
                                Eigen::Vector3d& p_j, Eigen::Quaterniond& q_j,
                                Eigen::Vector3d& v_j) const {
  const double T = sum_dt_;
  p_j = p_i + v_i * T + 0.5 * gravity * T * T + q_i * deltaPosition(ba, bg);
  v_j = v_i + gravity * T + q_i * deltaVelocity(ba, bg);
  q_j = (q_i * deltaRotation(bg)).normalized();
}

}  // namespace dynslam::estimator
