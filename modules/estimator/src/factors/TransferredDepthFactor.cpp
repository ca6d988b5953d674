#include "dynslam/estimator/factors/TransferredDepthFactor.h"

#include "dynslam/estimator/StateBlocks.h"
#include "dynslam/estimator/factors/CameraChain.h"
#include "dynslam/estimator/factors/TangentJacobian.h"

namespace dynslam::estimator {

TransferredDepthFactor::TransferredDepthFactor(const PinholeCamera& camera,
                                               const Eigen::Vector2d& pixel_i,
                                               double measured_depth_j,
                                               const DepthNoiseModel& noise)
    : bearing_i_(camera.bearing(pixel_i)),
      measured_depth_j_(measured_depth_j),
      inv_sigma_(1.0 / noise.sigma(measured_depth_j)) {}

bool TransferredDepthFactor::Evaluate(double const* const* parameters, double* residuals,
                                      double** jacobians) const {
  const double inverse_depth = parameters[3][0];
  if (!(inverse_depth > 0)) return false;
  InverseDepthTransferJacobians dp;
  const Eigen::Vector3d p_cj = transferInverseDepthPoint(
      poseFromBlock(parameters[0]), poseFromBlock(parameters[1]), poseFromBlock(parameters[2]),
      bearing_i_, inverse_depth, jacobians ? &dp : nullptr);
  residuals[0] = inv_sigma_ * (p_cj.z() - measured_depth_j_);
  if (!jacobians) return true;
  // Row z of each point Jacobian, whitened.
  if (jacobians[0])
    storePoseJacobian<1>(inv_sigma_ * dp.pose_i.row(2), jacobians[0]);
  if (jacobians[1])
    storePoseJacobian<1>(inv_sigma_ * dp.pose_j.row(2), jacobians[1]);
  if (jacobians[2])
    storePoseJacobian<1>(inv_sigma_ * dp.extrinsic.row(2), jacobians[2]);
  if (jacobians[3]) jacobians[3][0] = inv_sigma_ * dp.inverse_depth.z();
  return true;
}

}  // namespace dynslam::estimator
