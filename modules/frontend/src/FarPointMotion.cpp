#include "dynslam/frontend/FarPointMotion.h"

#include "dynslam/frontend/SceneFlow.h"

#include <algorithm>

namespace dynslam::frontend {
namespace {

/// project() of a point clearly in front of the camera; false otherwise.
bool projectInFront(const Eigen::Vector3d& P, const core::CameraIntrinsics& k,
                    Eigen::Vector2d& uv) {
  if (!(P.z() > 1e-9)) return false;
  uv = project(P, k);
  return true;
}

double distanceToSegment(const Eigen::Vector2d& p, const Eigen::Vector2d& a,
                         const Eigen::Vector2d& b) {
  const Eigen::Vector2d ab = b - a;
  const double len2 = ab.squaredNorm();
  const double s = len2 > 0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
  return (p - (a + s * ab)).norm();
}

}  // namespace

double farPointResidualPx(const cv::Point2f& previous, const cv::Point2f& current,
                          const Eigen::Isometry3d& T_cur_prev, const core::CameraIntrinsics& k,
                          double minDepth) {
  const Eigen::Vector3d ray = backProject(previous, 1.0, k);  // depth 1 along the ray
  Eigen::Vector2d atInfinity, atMinDepth;
  if (!projectInFront(T_cur_prev.linear() * ray, k, atInfinity) ||
      !projectInFront(T_cur_prev * (minDepth * ray), k, atMinDepth))
    return 0.0;
  return distanceToSegment({current.x, current.y}, atMinDepth, atInfinity);
}

double farPointMinDisplacement(const cv::Point2f& previous, const cv::Point2f& current,
                               const Eigen::Isometry3d& T_cur_prev, const core::CameraIntrinsics& k,
                               double minDepth) {
  return farPointResidualPx(previous, current, T_cur_prev, k, minDepth) * minDepth /
         (0.5 * (k.fx + k.fy));
}

}  // namespace dynslam::frontend
