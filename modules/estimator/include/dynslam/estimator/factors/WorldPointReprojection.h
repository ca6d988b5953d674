#pragma once
// The whitened pixel residual of a world point seen from a body pose through the camera
// extrinsic, and its Jacobians: shared by the factors whose landmark is a world point (the
// non-rigid constant-velocity and the rigid-object reprojection factors), which differ only in
// how they compute that point and chain its Jacobian to their own blocks.
#include <dynslam/estimator/factors/PinholeProjection.h>

#include <Eigen/Core>

namespace dynslam::estimator {

struct WorldPointReprojection {
  Eigen::Matrix<double, 2, 6> body_pose;  ///< d r / d T_world_body (tangent)
  Eigen::Matrix<double, 2, 6> extrinsic;  ///< d r / d T_body_camera (tangent)
  Eigen::Matrix<double, 2, 3> point;      ///< d r / d p_world
};

/// r = (observed - pi(T_bc^-1 T_wb^-1 p_world)) * inv_sigma into `residual`; the Jacobians into
/// `jacobians` when given. False when the point is closer than kMinProjectionDepth or behind.
bool reprojectWorldPoint(const PinholeCamera& camera, const double* body_pose,
                         const double* extrinsic, const Eigen::Vector3d& p_world,
                         const Eigen::Vector2d& observed, double inv_sigma, double* residual,
                         WorldPointReprojection* jacobians);

}  // namespace dynslam::estimator
