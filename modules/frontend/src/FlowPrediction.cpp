#include "dynslam/frontend/FlowPrediction.h"

namespace dynslam::frontend {

std::vector<cv::Point2f> predictByRotation(const std::vector<cv::Point2f>& previous,
                                           const core::CameraIntrinsics& K,
                                           const Eigen::Matrix3d& R) {
  Eigen::Matrix3d Km;
  Km << K.fx, 0, K.cx, 0, K.fy, K.cy, 0, 0, 1;
  const Eigen::Matrix3d H = Km * R * Km.inverse();
  std::vector<cv::Point2f> out;
  out.reserve(previous.size());
  for (const auto& p : previous) {
    const Eigen::Vector3d q = H * Eigen::Vector3d(p.x, p.y, 1.0);
    if (q.z() <= 1e-9)
      out.push_back(p);
    else
      out.emplace_back(float(q.x() / q.z()), float(q.y() / q.z()));
  }
  return out;
}

}  // namespace dynslam::frontend
