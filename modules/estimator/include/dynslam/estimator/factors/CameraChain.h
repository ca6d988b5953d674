#pragma once
// Moving points between the world, a body pose T_world_body (pose block) and the camera through
// the extrinsic T_body_camera (pose block), with Jacobians with respect to each block's tangent
// [dp, dtheta] (StateBlocks.h: position added, rotation perturbed on the right). Shared by the
// reprojection and depth factors so each derives its Jacobian once, here.
#include <Eigen/Core>
#include <Eigen/Geometry>

namespace dynslam::estimator {

using PoseTangentJacobian = Eigen::Matrix<double, 3, 6>;

/// d p_camera / d(...) of p_camera = T_body_camera^-1 T_world_body^-1 p_world.
struct WorldToCameraJacobians {
  PoseTangentJacobian body_pose;  ///< w.r.t. T_world_body
  PoseTangentJacobian extrinsic;  ///< w.r.t. T_body_camera
  Eigen::Matrix3d point;          ///< w.r.t. p_world
};
Eigen::Vector3d worldToCamera(const Eigen::Isometry3d& T_world_body,
                              const Eigen::Isometry3d& T_body_camera,
                              const Eigen::Vector3d& p_world,
                              WorldToCameraJacobians* jacobians = nullptr);

/// d p_world / d(...) of p_world = T_world_body T_body_camera p_camera.
struct CameraToWorldJacobians {
  PoseTangentJacobian body_pose;
  PoseTangentJacobian extrinsic;
  Eigen::Matrix3d point;  ///< w.r.t. p_camera
};
Eigen::Vector3d cameraToWorld(const Eigen::Isometry3d& T_world_body,
                              const Eigen::Isometry3d& T_body_camera,
                              const Eigen::Vector3d& p_camera,
                              CameraToWorldJacobians* jacobians = nullptr);

/// A static feature anchored in camera i: p_camera_i = bearing_i / inverse_depth, seen from
/// camera j. Returns the point in camera j and, on request, its Jacobians.
struct InverseDepthTransferJacobians {
  PoseTangentJacobian pose_i;  ///< w.r.t. T_world_body(i)
  PoseTangentJacobian pose_j;  ///< w.r.t. T_world_body(j)
  PoseTangentJacobian extrinsic;
  Eigen::Vector3d inverse_depth;
  Eigen::Matrix3d bearing;  ///< w.r.t. bearing_i
};
Eigen::Vector3d transferInverseDepthPoint(const Eigen::Isometry3d& T_world_body_i,
                                          const Eigen::Isometry3d& T_world_body_j,
                                          const Eigen::Isometry3d& T_body_camera,
                                          const Eigen::Vector3d& bearing_i, double inverse_depth,
                                          InverseDepthTransferJacobians* jacobians = nullptr);

}  // namespace dynslam::estimator
