#include "dynslam/estimator/factors/RigidObjectDepthFactor.h"

#include "dynslam/estimator/StateBlocks.h"
#include "dynslam/estimator/factors/CameraChain.h"
#include "dynslam/estimator/factors/TangentJacobian.h"

namespace dynslam::estimator {

RigidObjectDepthFactor::RigidObjectDepthFactor(double measured_depth, const DepthNoiseModel& noise)
    : measured_depth_(measured_depth), inv_sigma_(1.0 / noise.sigma(measured_depth)) {}

bool RigidObjectDepthFactor::Evaluate(double const* const* parameters, double* residuals,
                                      double** jacobians) const {
  const Eigen::Isometry3d L_n = poseFromBlock(parameters[2]);
  const Eigen::Map<const Eigen::Vector3d> m_obj(parameters[3]);
  WorldToCameraJacobians dp;
  const Eigen::Vector3d p_c =
      worldToCamera(poseFromBlock(parameters[0]), poseFromBlock(parameters[1]), L_n * m_obj,
                    jacobians ? &dp : nullptr);
  residuals[0] = inv_sigma_ * (p_c.z() - measured_depth_);
  if (!jacobians) return true;
  // d r / d p_c = [0 0 inv_sigma]: the third rows of the chain's Jacobians.
  if (jacobians[0])
    storePoseJacobian<1>(Eigen::Matrix<double, 1, 6>(inv_sigma_ * dp.body_pose.row(2)),
                         jacobians[0]);
  if (jacobians[1])
    storePoseJacobian<1>(Eigen::Matrix<double, 1, 6>(inv_sigma_ * dp.extrinsic.row(2)),
                         jacobians[1]);
  const Eigen::RowVector3d dr_dm = inv_sigma_ * dp.point.row(2);  // w.r.t. the world point m_n
  if (jacobians[2]) {
    // m_n = R_L m_obj + t_L: d/dt_L = I, d/dtheta_L = -R_L [m_obj]x (rotation on the right).
    Eigen::Matrix<double, 3, 6> dm_dL;
    dm_dL.leftCols<3>().setIdentity();
    dm_dL.rightCols<3>() = -L_n.rotation() * skew(m_obj);
    storePoseJacobian<1>(Eigen::Matrix<double, 1, 6>(dr_dm * dm_dL), jacobians[2]);
  }
  if (jacobians[3]) {
    Eigen::Map<Eigen::RowVector3d> J(jacobians[3]);
    J = dr_dm * L_n.rotation();
  }
  return true;
}

}  // namespace dynslam::estimator
