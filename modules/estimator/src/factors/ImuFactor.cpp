#include "dynslam/estimator/factors/ImuFactor.h"

#include "dynslam/estimator/StateBlocks.h"

#include <Eigen/Cholesky>

#include <stdexcept>

namespace dynslam::estimator {
namespace {

enum : int { kP = 0, kR = 3, kV = 6, kBa = 9, kBg = 12 };

// Left and right multiplication matrices of a quaternion [w, x, y, z]: p * q = L(p) q = R(q) p.
Eigen::Matrix4d quatLeft(const Eigen::Quaterniond& q) {
  Eigen::Matrix4d m;
  m(0, 0) = q.w();
  m.block<1, 3>(0, 1) = -q.vec().transpose();
  m.block<3, 1>(1, 0) = q.vec();
  m.block<3, 3>(1, 1) = q.w() * Eigen::Matrix3d::Identity() + skew(q.vec());
  return m;
}

Eigen::Matrix4d quatRight(const Eigen::Quaterniond& q) {
  Eigen::Matrix4d m;
  m(0, 0) = q.w();
  m.block<1, 3>(0, 1) = -q.vec().transpose();
  m.block<3, 1>(1, 0) = q.vec();
  m.block<3, 3>(1, 1) = q.w() * Eigen::Matrix3d::Identity() - skew(q.vec());
  return m;
}

}  // namespace

ImuFactor::ImuFactor(std::shared_ptr<const ImuPreintegration> preintegration)
    : preintegration_(std::move(preintegration)) {
  const Matrix15d information = preintegration_->covariance().inverse();
  if (!information.allFinite())
    throw std::invalid_argument("ImuFactor: the preintegrated covariance is singular");
  sqrt_information_ = Eigen::LLT<Matrix15d>(information).matrixL().transpose();
}

bool ImuFactor::Evaluate(double const* const* parameters, double* residuals,
                         double** jacobians) const {
  const Eigen::Vector3d p_i(parameters[0]);
  const Eigen::Quaterniond q_i(parameters[0][6], parameters[0][3], parameters[0][4],
                               parameters[0][5]);
  const Eigen::Vector3d v_i(parameters[1]), ba_i(parameters[1] + 3), bg_i(parameters[1] + 6);
  const Eigen::Vector3d p_j(parameters[2]);
  const Eigen::Quaterniond q_j(parameters[2][6], parameters[2][3], parameters[2][4],
                               parameters[2][5]);
  const Eigen::Vector3d v_j(parameters[3]), ba_j(parameters[3] + 3), bg_j(parameters[3] + 6);
  const Eigen::Vector3d gravity(parameters[4]);

  const ImuPreintegration& pre = *preintegration_;
  const double T = pre.sumDt();
  const Eigen::Matrix3d Ri_T = q_i.toRotationMatrix().transpose();
  const Eigen::Quaterniond gamma = pre.deltaRotation(bg_i);
  const Eigen::Vector3d dp_world = p_j - p_i - v_i * T - 0.5 * gravity * T * T;
  const Eigen::Vector3d dv_world = v_j - v_i - gravity * T;

  Eigen::Map<Eigen::Matrix<double, 15, 1>> r(residuals);
  r.segment<3>(kP) = Ri_T * dp_world - pre.deltaPosition(ba_i, bg_i);
  r.segment<3>(kR) = 2.0 * (gamma.inverse() * (q_i.inverse() * q_j)).vec();
  r.segment<3>(kV) = Ri_T * dv_world - pre.deltaVelocity(ba_i, bg_i);
  r.segment<3>(kBa) = ba_j - ba_i;
  r.segment<3>(kBg) = bg_j - bg_i;
  r = sqrt_information_ * r;
  if (!jacobians) return true;

  const Linearisation at{q_i, q_j, gamma, bg_i, Ri_T, dp_world, dv_world, T};
  if (jacobians[0]) poseJacobianI(at, jacobians[0]);
  if (jacobians[1]) speedBiasJacobianI(at, jacobians[1]);
  if (jacobians[2]) poseJacobianJ(at, jacobians[2]);
  if (jacobians[3]) speedBiasJacobianJ(at, jacobians[3]);
  if (jacobians[4]) gravityJacobian(at, jacobians[4]);
  return true;
}

void ImuFactor::poseJacobianI(const Linearisation& at, double* jacobian) const {
  Eigen::Map<Eigen::Matrix<double, 15, 7, Eigen::RowMajor>> Jp(jacobian);
  Jp.setZero();
  Jp.block<3, 3>(kP, 0) = -at.Ri_T;
  Jp.block<3, 3>(kP, 3) = skew(at.Ri_T * at.dp_world);
  Jp.block<3, 3>(kR, 3) =
      -(quatLeft(at.q_j.inverse() * at.q_i) * quatRight(at.gamma)).bottomRightCorner<3, 3>();
  Jp.block<3, 3>(kV, 3) = skew(at.Ri_T * at.dv_world);
  Jp.leftCols<6>() = sqrt_information_ * Jp.leftCols<6>();
}

void ImuFactor::speedBiasJacobianI(const Linearisation& at, double* jacobian) const {
  const ImuPreintegration& pre = *preintegration_;
  const Matrix15d& J = pre.jacobian();
  const Eigen::Matrix3d dp_dba = J.block<3, 3>(kP, kBa), dp_dbg = J.block<3, 3>(kP, kBg);
  const Eigen::Matrix3d dq_dbg = J.block<3, 3>(kR, kBg);
  const Eigen::Matrix3d dv_dba = J.block<3, 3>(kV, kBa), dv_dbg = J.block<3, 3>(kV, kBg);
  const Eigen::Matrix3d I = Eigen::Matrix3d::Identity();
  Eigen::Map<Eigen::Matrix<double, 15, 9, Eigen::RowMajor>> Js(jacobian);
  Js.setZero();
  Js.block<3, 3>(kP, 0) = -at.Ri_T * at.T;
  Js.block<3, 3>(kP, 3) = -dp_dba;
  Js.block<3, 3>(kP, 6) = -dp_dbg;
  // gamma(bg) = gamma0 Exp(dq_dbg (bg - bg0)): the right Jacobian of that Exp makes the
  // derivative exact away from the linearisation point (VINS drops it: first order only).
  const Eigen::Vector3d phi = dq_dbg * (at.bg_i - pre.linearizedBg());
  Js.block<3, 3>(kR, 6) =
      -quatLeft(at.q_j.inverse() * at.q_i * at.gamma).bottomRightCorner<3, 3>() *
      rightJacobianSO3(phi) * dq_dbg;
  Js.block<3, 3>(kV, 0) = -at.Ri_T;
  Js.block<3, 3>(kV, 3) = -dv_dba;
  Js.block<3, 3>(kV, 6) = -dv_dbg;
  Js.block<3, 3>(kBa, 3) = -I;
  Js.block<3, 3>(kBg, 6) = -I;
  Js = sqrt_information_ * Js;
}

void ImuFactor::poseJacobianJ(const Linearisation& at, double* jacobian) const {
  Eigen::Map<Eigen::Matrix<double, 15, 7, Eigen::RowMajor>> Jp(jacobian);
  Jp.setZero();
  Jp.block<3, 3>(kP, 0) = at.Ri_T;
  Jp.block<3, 3>(kR, 3) =
      quatLeft(at.gamma.inverse() * at.q_i.inverse() * at.q_j).bottomRightCorner<3, 3>();
  Jp.leftCols<6>() = sqrt_information_ * Jp.leftCols<6>();
}

void ImuFactor::speedBiasJacobianJ(const Linearisation& at, double* jacobian) const {
  const Eigen::Matrix3d I = Eigen::Matrix3d::Identity();
  Eigen::Map<Eigen::Matrix<double, 15, 9, Eigen::RowMajor>> Js(jacobian);
  Js.setZero();
  Js.block<3, 3>(kV, 0) = at.Ri_T;
  Js.block<3, 3>(kBa, 3) = I;
  Js.block<3, 3>(kBg, 6) = I;
  Js = sqrt_information_ * Js;
}

void ImuFactor::gravityJacobian(const Linearisation& at, double* jacobian) const {
  Eigen::Map<Eigen::Matrix<double, 15, 3, Eigen::RowMajor>> Jg(jacobian);
  Jg.setZero();
  Jg.block<3, 3>(kP, 0) = -0.5 * at.T * at.T * at.Ri_T;
  Jg.block<3, 3>(kV, 0) = -at.T * at.Ri_T;
  Jg = sqrt_information_ * Jg;
}

}  // namespace dynslam::estimator
