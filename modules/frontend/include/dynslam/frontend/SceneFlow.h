#pragma once
// Scene flow (method.md section 3, Eq. 11): the motion of a point after removing the camera's
// own motion, F = P_{k+1} - T_{C(k+1)<-W} T_{W<-C(k)} P_k = P_{k+1} - T_{C(k+1)<-C(k)} P_k,
// with P_k, P_{k+1} the point in the camera frames of the two frames. Zero for a static point
// under the true camera motion; the point's own displacement (in the later camera frame)
// otherwise.
#include <dynslam/core/Frame.h>

#include <Eigen/Geometry>
#include <opencv2/core/types.hpp>

namespace dynslam::frontend {

/// The camera-frame point (x right, y down, z forward) of a pixel with depth z (pinhole).
inline Eigen::Vector3d backProject(const cv::Point2f& pixel, double z,
                                   const core::CameraIntrinsics& k) {
  return {(pixel.x - k.cx) * z / k.fx, (pixel.y - k.cy) * z / k.fy, z};
}

/// The pixel of a camera-frame point (pinhole; the inverse of backProject). The point must lie
/// in front of the camera (z > 0): the callers check it.
inline Eigen::Vector2d project(const Eigen::Vector3d& P, const core::CameraIntrinsics& k) {
  return {k.fx * P.x() / P.z() + k.cx, k.fy * P.y() / P.z() + k.cy};
}

/// F of Eq. 11; T_cur_prev maps previous-camera coordinates to this frame's camera coordinates.
inline Eigen::Vector3d sceneFlow(const Eigen::Vector3d& P_prev, const Eigen::Vector3d& P_cur,
                                 const Eigen::Isometry3d& T_cur_prev) {
  return P_cur - T_cur_prev * P_prev;
}

}  // namespace dynslam::frontend
