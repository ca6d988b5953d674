#include "dynslam/estimator/factors/CameraChain.h"

#include "dynslam/estimator/StateBlocks.h"

namespace dynslam::estimator {

// With R <- R Exp(dtheta): R^T x <- Exp(-dtheta) R^T x ~ R^T x + [R^T x]x dtheta, and
// R y <- R (y + dtheta x y) = R y - R [y]x dtheta. Positions enter additively.

Eigen::Vector3d worldToCamera(const Eigen::Isometry3d& T_wb, const Eigen::Isometry3d& T_bc,
                              const Eigen::Vector3d& p_w, WorldToCameraJacobians* J) {
  const Eigen::Matrix3d R_bw = T_wb.rotation().transpose();
  const Eigen::Matrix3d R_cb = T_bc.rotation().transpose();
  const Eigen::Vector3d p_b = R_bw * (p_w - T_wb.translation());
  const Eigen::Vector3d p_c = R_cb * (p_b - T_bc.translation());
  if (J) {
    J->point = R_cb * R_bw;
    J->body_pose.leftCols<3>() = -J->point;
    J->body_pose.rightCols<3>() = R_cb * skew(p_b);
    J->extrinsic.leftCols<3>() = -R_cb;
    J->extrinsic.rightCols<3>() = skew(p_c);
  }
  return p_c;
}

Eigen::Vector3d cameraToWorld(const Eigen::Isometry3d& T_wb, const Eigen::Isometry3d& T_bc,
                              const Eigen::Vector3d& p_c, CameraToWorldJacobians* J) {
  const Eigen::Matrix3d& R_wb = T_wb.rotation();
  const Eigen::Vector3d p_b = T_bc * p_c;
  if (J) {
    J->point = R_wb * T_bc.rotation();
    J->body_pose.leftCols<3>().setIdentity();
    J->body_pose.rightCols<3>() = -R_wb * skew(p_b);
    J->extrinsic.leftCols<3>() = R_wb;
    J->extrinsic.rightCols<3>() = -J->point * skew(p_c);
  }
  return T_wb * p_b;
}

Eigen::Vector3d transferInverseDepthPoint(const Eigen::Isometry3d& T_wbi,
                                          const Eigen::Isometry3d& T_wbj,
                                          const Eigen::Isometry3d& T_bc,
                                          const Eigen::Vector3d& bearing_i, double inverse_depth,
                                          InverseDepthTransferJacobians* J) {
  const Eigen::Vector3d p_ci = bearing_i / inverse_depth;
  if (!J) return worldToCamera(T_wbj, T_bc, cameraToWorld(T_wbi, T_bc, p_ci));
  CameraToWorldJacobians in;
  WorldToCameraJacobians out;
  const Eigen::Vector3d p_cj =
      worldToCamera(T_wbj, T_bc, cameraToWorld(T_wbi, T_bc, p_ci, &in), &out);
  J->pose_i = out.point * in.body_pose;
  J->pose_j = out.body_pose;
  // The extrinsic enters twice: lifting the point out of camera i and projecting into camera j.
  J->extrinsic = out.extrinsic + out.point * in.extrinsic;
  J->bearing = out.point * in.point / inverse_depth;
  J->inverse_depth = J->bearing * (-p_ci);
  return p_cj;
}

}  // namespace dynslam::estimator
