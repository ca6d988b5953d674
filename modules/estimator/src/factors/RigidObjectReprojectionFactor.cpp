#include "dynslam/estimator/factors/RigidObjectReprojectionFactor.h"

#include "dynslam/estimator/StateBlocks.h"
#include "dynslam/estimator/factors/CameraChain.h"
#include "dynslam/estimator/factors/TangentJacobian.h"

namespace dynslam::estimator {

RigidObjectReprojectionFactor::RigidObjectReprojectionFactor(const PinholeCamera& camera,
                                                             const Eigen::Vector2d& pixel_n,
                                                             double sigma_pixel)
    : camera_(camera), pixel_n_(pixel_n), inv_sigma_(1.0 / sigma_pixel) {}

bool RigidObjectReprojectionFactor::Evaluate(double const* const* parameters, double* residuals,
                                             double** jacobians) const {
  const Eigen::Isometry3d L_n = poseFromBlock(parameters[2]);
  const Eigen::Map<const Eigen::Vector3d> m_obj(parameters[3]);
  const Eigen::Vector3d m_n = L_n * m_obj;
  WorldToCameraJacobians dp;
  const Eigen::Vector3d p_c = worldToCamera(poseFromBlock(parameters[0]),
                                            poseFromBlock(parameters[1]), m_n,
                                            jacobians ? &dp : nullptr);
  if (p_c.z() < kMinProjectionDepth) return false;

  Eigen::Matrix<double, 2, 3> dpixel;
  Eigen::Map<Eigen::Vector2d> r(residuals);
  r = inv_sigma_ * (pixel_n_ - camera_.project(p_c, &dpixel));
  if (!jacobians) return true;

  const Eigen::Matrix<double, 2, 3> dr_dp = -inv_sigma_ * dpixel;
  if (jacobians[0]) storePoseJacobian<2>(dr_dp * dp.body_pose, jacobians[0]);
  if (jacobians[1]) storePoseJacobian<2>(dr_dp * dp.extrinsic, jacobians[1]);
  const Eigen::Matrix<double, 2, 3> dr_dm = dr_dp * dp.point;  // w.r.t. the world point m_n
  if (jacobians[2]) {
    // m_n = R_L m_obj + t_L: d/dt_L = I, d/dtheta_L = -R_L [m_obj]x (rotation on the right).
    Eigen::Matrix<double, 3, 6> dm_dL;
    dm_dL.leftCols<3>().setIdentity();
    dm_dL.rightCols<3>() = -L_n.rotation() * skew(m_obj);
    storePoseJacobian<2>(dr_dm * dm_dL, jacobians[2]);
  }
  if (jacobians[3]) {
    Eigen::Map<Eigen::Matrix<double, 2, 3, Eigen::RowMajor>> J(jacobians[3]);
    J = dr_dm * L_n.rotation();
  }
  return true;
}

}  // namespace dynslam::estimator
