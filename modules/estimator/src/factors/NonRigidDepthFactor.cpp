#include "dynslam/estimator/factors/NonRigidDepthFactor.h"

#include "dynslam/estimator/StateBlocks.h"
#include "dynslam/estimator/factors/CameraChain.h"
#include "dynslam/estimator/factors/TangentJacobian.h"

namespace dynslam::estimator {

NonRigidDepthFactor::NonRigidDepthFactor(double dt, double measured_depth,
                                         const DepthNoiseModel& noise)
    : dt_(dt), measured_depth_(measured_depth), inv_sigma_(1.0 / noise.sigma(measured_depth)) {}

bool NonRigidDepthFactor::Evaluate(double const* const* parameters, double* residuals,
                                   double** jacobians) const {
  const Eigen::Map<const Eigen::Vector3d> p_w0(parameters[2]), v_w(parameters[3]);
  WorldToCameraJacobians dp;
  const Eigen::Vector3d p_c = worldToCamera(poseFromBlock(parameters[0]),
                                            poseFromBlock(parameters[1]), p_w0 + dt_ * v_w,
                                            jacobians ? &dp : nullptr);
  residuals[0] = inv_sigma_ * (p_c.z() - measured_depth_);
  if (!jacobians) return true;
  // d r / d p_c = [0 0 inv_sigma]: the third rows of the chain's Jacobians.
  if (jacobians[0])
    storePoseJacobian<1>(Eigen::Matrix<double, 1, 6>(inv_sigma_ * dp.body_pose.row(2)), jacobians[0]);
  if (jacobians[1])
    storePoseJacobian<1>(Eigen::Matrix<double, 1, 6>(inv_sigma_ * dp.extrinsic.row(2)), jacobians[1]);
  const Eigen::RowVector3d dr_dpw = inv_sigma_ * dp.point.row(2);
  if (jacobians[2]) {
    Eigen::Map<Eigen::RowVector3d> J(jacobians[2]);
    J = dr_dpw;
  }
  if (jacobians[3]) {
    Eigen::Map<Eigen::RowVector3d> J(jacobians[3]);
    J = dt_ * dr_dpw;
  }
  return true;
}

}  // namespace dynslam::estimator
