#include "dynslam/estimator/factors/RigidSmoothMotionFactor.h"

#include "dynslam/estimator/StateBlocks.h"
#include "dynslam/estimator/factors/TangentJacobian.h"

#include <cmath>

namespace dynslam::estimator {

RigidSmoothMotionFactor::RigidSmoothMotionFactor(const Matrix6d& information)
    : sqrt_information_(sqrtInformationFromInformation<6>(information)) {}

RigidSmoothMotionFactor::RigidSmoothMotionFactor(double sigma_translation,
                                                 double sigma_rotation) {
  sqrt_information_.setZero();
  sqrt_information_.diagonal() << Eigen::Vector3d::Constant(1.0 / sigma_translation),
      Eigen::Vector3d::Constant(1.0 / sigma_rotation);
}

bool RigidSmoothMotionFactor::Evaluate(double const* const* parameters, double* residuals,
                                       double** jacobians) const {
  const Eigen::Isometry3d La = poseFromBlock(parameters[0]);  // L_{n-2}
  const Eigen::Isometry3d Lb = poseFromBlock(parameters[1]);  // L_{n-1}
  const Eigen::Isometry3d Lc = poseFromBlock(parameters[2]);  // L_n
  const Eigen::Matrix3d &Ra = La.rotation(), &Rb = Lb.rotation(), &Rc = Lc.rotation();
  const Eigen::Vector3d &ta = La.translation(), &tb = Lb.translation(), &tc = Lc.translation();

  // E = Lb^-1 La Lb^-1 Lc.
  const Eigen::Matrix3d RbT = Rb.transpose();
  const Eigen::Matrix3d A = RbT * Ra * RbT;        // rotation of Lb^-1 La Lb^-1
  const Eigen::Vector3d w = RbT * (tc - tb);       // translation of H_{n-1,n}
  const Eigen::Vector3d u = RbT * (ta - tb);       // translation of H_{n-2,n-1}^-1
  const Eigen::Matrix3d R_E = A * Rc;
  const Eigen::Vector3d t_E = RbT * Ra * w + u;
  const Eigen::Vector3d phi = logSO3(R_E);

  Eigen::Matrix<double, 6, 1> r;
  r << t_E, phi;
  Eigen::Map<Eigen::Matrix<double, 6, 1>> out(residuals);
  out = sqrt_information_ * r;
  if (!jacobians) return true;

  // Right perturbations R <- R Exp(d) (StateBlocks.h), using R^T Exp(x) R = Exp(R^T x):
  //   d/d_c: R_E Exp(d_c)                             -> Jr^-1
  //   d/d_a: Rb^T Ra Exp(d_a) Rb^T Rc = R_E Exp(M^T d_a), M = Rb^T Rc
  //   d/d_b: Rb^T appears twice, each as Exp(-d_b) Rb^T -> -(R_E^T + M^T)
  // and for t_E = Rb^T Ra w + u, w and u depending on Rb^T and the positions.
  const Eigen::Matrix3d JrInv = inverseRightJacobianSO3(phi);
  const Eigen::Matrix3d MT = Rc.transpose() * Rb;
  const Eigen::Matrix3d RbTRa = RbT * Ra;
  using Jacobian6 = Eigen::Matrix<double, 6, 6>;
  if (jacobians[0]) {
    Jacobian6 J = Jacobian6::Zero();
    J.block<3, 3>(0, 0) = RbT;
    J.block<3, 3>(0, 3) = -RbTRa * skew(w);
    J.block<3, 3>(3, 3) = JrInv * MT;
    storePoseJacobian<6>(sqrt_information_ * J, jacobians[0]);
  }
  if (jacobians[1]) {
    Jacobian6 J = Jacobian6::Zero();
    J.block<3, 3>(0, 0) = -A - RbT;
    J.block<3, 3>(0, 3) = skew(RbTRa * w) + RbTRa * skew(w) + skew(u);
    J.block<3, 3>(3, 3) = -JrInv * (R_E.transpose() + MT);
    storePoseJacobian<6>(sqrt_information_ * J, jacobians[1]);
  }
  if (jacobians[2]) {
    Jacobian6 J = Jacobian6::Zero();
    J.block<3, 3>(0, 0) = A;
    J.block<3, 3>(3, 3) = JrInv;
    storePoseJacobian<6>(sqrt_information_ * J, jacobians[2]);
  }
  return true;
}

}  // namespace dynslam::estimator
