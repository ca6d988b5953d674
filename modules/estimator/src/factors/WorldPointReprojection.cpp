#include "dynslam/estimator/factors/WorldPointReprojection.h"

#include "dynslam/estimator/StateBlocks.h"
#include "dynslam/estimator/factors/CameraChain.h"

namespace dynslam::estimator {

bool reprojectWorldPoint(const PinholeCamera& camera, const double* body_pose,
                         const double* extrinsic, const Eigen::Vector3d& p_world,
                         const Eigen::Vector2d& observed, double inv_sigma, double* residual,
                         WorldPointReprojection* jacobians) {
  WorldToCameraJacobians dp;
  const Eigen::Vector3d p_c = worldToCamera(poseFromBlock(body_pose), poseFromBlock(extrinsic),
                                            p_world, jacobians ? &dp : nullptr);
  if (p_c.z() < kMinProjectionDepth) return false;
  Eigen::Matrix<double, 2, 3> dpixel;
  Eigen::Map<Eigen::Vector2d> r(residual);
  r = inv_sigma * (observed - camera.project(p_c, &dpixel));
  if (!jacobians) return true;
  const Eigen::Matrix<double, 2, 3> dr_dp = -inv_sigma * dpixel;
  jacobians->body_pose = dr_dp * dp.body_pose;
  jacobians->extrinsic = dr_dp * dp.extrinsic;
  jacobians->point = dr_dp * dp.point;
  return true;
}

}  // namespace dynslam::estimator
