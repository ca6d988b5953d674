#include "dynslam/estimator/factors/NonRigidConstantVelocityFactor.h"

#include "dynslam/estimator/StateBlocks.h"
#include "dynslam/estimator/factors/WorldPointReprojection.h"
#include "dynslam/estimator/factors/TangentJacobian.h"

namespace dynslam::estimator {

NonRigidConstantVelocityFactor::NonRigidConstantVelocityFactor(const PinholeCamera& camera,
                                                               const Eigen::Vector2d& pixel_n,
                                                               double dt, double sigma_pixel)
    : camera_(camera), pixel_n_(pixel_n), dt_(dt), inv_sigma_(1.0 / sigma_pixel) {}

bool NonRigidConstantVelocityFactor::Evaluate(double const* const* parameters,
                                              double* residuals, double** jacobians) const {
  const Eigen::Map<const Eigen::Vector3d> p_w0(parameters[2]), v_w(parameters[3]);
  const Eigen::Vector3d p_wn = p_w0 + dt_ * v_w;
  WorldPointReprojection J;
  if (!reprojectWorldPoint(camera_, parameters[0], parameters[1], p_wn, pixel_n_, inv_sigma_,
                           residuals, jacobians ? &J : nullptr))
    return false;
  if (!jacobians) return true;
  if (jacobians[0]) storePoseJacobian<2>(J.body_pose, jacobians[0]);
  if (jacobians[1]) storePoseJacobian<2>(J.extrinsic, jacobians[1]);
  const Eigen::Matrix<double, 2, 3>& dr_dpw = J.point;
  if (jacobians[2]) {
    Eigen::Map<Eigen::Matrix<double, 2, 3, Eigen::RowMajor>> out(jacobians[2]);
    out = dr_dpw;
  }
  if (jacobians[3]) {
    Eigen::Map<Eigen::Matrix<double, 2, 3, Eigen::RowMajor>> out(jacobians[3]);
    out = dt_ * dr_dpw;
  }
  return true;
}

}  // namespace dynslam::estimator
