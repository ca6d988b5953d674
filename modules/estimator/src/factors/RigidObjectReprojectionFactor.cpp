#include "dynslam/estimator/factors/RigidObjectReprojectionFactor.h"

#include "dynslam/estimator/StateBlocks.h"
#include "dynslam/estimator/factors/WorldPointReprojection.h"
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
  WorldPointReprojection J;
  if (!reprojectWorldPoint(camera_, parameters[0], parameters[1], m_n, pixel_n_, inv_sigma_,
                           residuals, jacobians ? &J : nullptr))
    return false;
  if (!jacobians) return true;
  if (jacobians[0]) storePoseJacobian<2>(J.body_pose, jacobians[0]);
  if (jacobians[1]) storePoseJacobian<2>(J.extrinsic, jacobians[1]);
  const Eigen::Matrix<double, 2, 3>& dr_dm = J.point;  // w.r.t. the world point m_n
  if (jacobians[2]) {
    // m_n = R_L m_obj + t_L: d/dt_L = I, d/dtheta_L = -R_L [m_obj]x (rotation on the right).
    Eigen::Matrix<double, 3, 6> dm_dL;
    dm_dL.leftCols<3>().setIdentity();
    dm_dL.rightCols<3>() = -L_n.rotation() * skew(m_obj);
    storePoseJacobian<2>(dr_dm * dm_dL, jacobians[2]);
  }
  if (jacobians[3]) {
    Eigen::Map<Eigen::Matrix<double, 2, 3, Eigen::RowMajor>> out(jacobians[3]);
    out = dr_dm * L_n.rotation();
  }
  return true;
}

}  // namespace dynslam::estimator
