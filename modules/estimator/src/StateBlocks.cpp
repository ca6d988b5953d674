#include "dynslam/estimator/StateBlocks.h"

#include <cmath>

namespace dynslam::estimator {

Eigen::Isometry3d poseFromBlock(const double* block) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.translation() = Eigen::Vector3d(block[0], block[1], block[2]);
  T.linear() = Eigen::Quaterniond(block[6], block[3], block[4], block[5]).normalized()
                   .toRotationMatrix();
  return T;
}

void poseToBlock(const Eigen::Isometry3d& pose, double* block) {
  const Eigen::Quaterniond q(pose.rotation());
  block[0] = pose.translation().x();
  block[1] = pose.translation().y();
  block[2] = pose.translation().z();
  block[3] = q.x();
  block[4] = q.y();
  block[5] = q.z();
  block[6] = q.w();
}

Eigen::Isometry3d nearestRigid(const Eigen::Isometry3d& T) {
  Eigen::Isometry3d out = Eigen::Isometry3d::Identity();
  out.linear() = Eigen::Quaterniond(T.rotation()).normalized().toRotationMatrix();
  out.translation() = T.translation();
  return out;
}

Eigen::Quaterniond quaternionExp(const Eigen::Vector3d& theta) {
  const double angle = theta.norm();
  if (angle < 1e-10) {
    // Second-order accurate near zero, then normalised.
    return Eigen::Quaterniond(1.0, 0.5 * theta.x(), 0.5 * theta.y(), 0.5 * theta.z())
        .normalized();
  }
  return Eigen::Quaterniond(Eigen::AngleAxisd(angle, theta / angle));
}

Eigen::Matrix3d skew(const Eigen::Vector3d& v) {
  Eigen::Matrix3d m;
  m << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
  return m;
}

Eigen::Matrix3d rightJacobianSO3(const Eigen::Vector3d& phi) {
  const double a = phi.norm();
  const Eigen::Matrix3d W = skew(phi);
  if (a < 1e-5) return Eigen::Matrix3d::Identity() - 0.5 * W + W * W / 6.0;
  return Eigen::Matrix3d::Identity() - (1.0 - std::cos(a)) / (a * a) * W +
         (a - std::sin(a)) / (a * a * a) * W * W;
}

Eigen::Vector3d logSO3(const Eigen::Matrix3d& R) {
  Eigen::Quaterniond q(R);
  if (q.w() < 0) q.coeffs() = -q.coeffs();
  const double n = q.vec().norm();
  if (n < 1e-10) return 2.0 * q.vec() / q.w();  // first order, exact to rounding here
  return 2.0 * std::atan2(n, q.w()) * q.vec() / n;
}

Eigen::Matrix3d inverseRightJacobianSO3(const Eigen::Vector3d& phi) {
  const double a = phi.norm();
  const Eigen::Matrix3d W = skew(phi);
  if (a < 1e-5) return Eigen::Matrix3d::Identity() + 0.5 * W + W * W / 12.0;
  return Eigen::Matrix3d::Identity() + 0.5 * W +
         (1.0 / (a * a) - (1.0 + std::cos(a)) / (2.0 * a * std::sin(a))) * W * W;
}

bool PoseManifold::Plus(const double* x, const double* delta, double* x_plus_delta) const {
  Eigen::Map<const Eigen::Vector3d> p(x);
  Eigen::Map<const Eigen::Quaterniond> q(x + 3);
  Eigen::Map<const Eigen::Vector3d> dp(delta), dtheta(delta + 3);
  Eigen::Map<Eigen::Vector3d> p_out(x_plus_delta);
  Eigen::Map<Eigen::Quaterniond> q_out(x_plus_delta + 3);
  p_out = p + dp;
  q_out = (q * quaternionExp(dtheta)).normalized();
  return true;
}

bool PoseManifold::PlusJacobian(const double* /*x*/, double* jacobian) const {
  Eigen::Map<Eigen::Matrix<double, 7, 6, Eigen::RowMajor>> J(jacobian);
  J.setZero();
  J.topRows<6>().setIdentity();
  return true;
}

bool PoseManifold::Minus(const double* y, const double* x, double* y_minus_x) const {
  Eigen::Map<const Eigen::Vector3d> py(y), px(x);
  Eigen::Map<const Eigen::Quaterniond> qy(y + 3), qx(x + 3);
  Eigen::Map<Eigen::Vector3d> dp(y_minus_x), dtheta(y_minus_x + 3);
  dp = py - px;
  const Eigen::AngleAxisd aa(qx.conjugate() * qy);
  dtheta = aa.angle() * aa.axis();
  if (dtheta.norm() > M_PI) dtheta -= 2 * M_PI * dtheta.normalized();
  return true;
}

bool PoseManifold::MinusJacobian(const double* /*x*/, double* jacobian) const {
  // The pseudo-inverse of PlusJacobian: consistent with the convention above.
  Eigen::Map<Eigen::Matrix<double, 6, 7, Eigen::RowMajor>> J(jacobian);
  J.setZero();
  J.leftCols<6>().setIdentity();
  return true;
}

}  // namespace dynslam::estimator
