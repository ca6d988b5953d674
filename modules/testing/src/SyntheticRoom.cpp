#include "dynslam/testing/SyntheticRoom.h"

#include <algorithm>
#include <cmath>

namespace dynslam::testing {

core::CameraIntrinsics vgaCamera() {
  core::CameraIntrinsics k;
  k.fx = k.fy = 525;
  k.cx = 319.5;
  k.cy = 239.5;
  k.width = 640;
  k.height = 480;
  return k;
}

void renderRoom(const Eigen::Isometry3d& T_world_camera, const core::CameraIntrinsics& k,
                cv::Mat& rgb, cv::Mat& depth) {
  rgb.create(k.height, k.width, CV_8UC3);
  depth.create(k.height, k.width, CV_32FC1);
  const Eigen::Vector3d origin = T_world_camera.translation();
  for (int v = 0; v < k.height; ++v)
    for (int u = 0; u < k.width; ++u) {
      const Eigen::Vector3d rayCam((u - k.cx) / k.fx, (v - k.cy) / k.fy, 1.0);
      const Eigen::Vector3d ray = T_world_camera.linear() * rayCam;
      double best = 1e9;
      const auto hit = [&](int axis, double plane) {
        if (std::abs(ray[axis]) < 1e-9) return;
        const double s = (plane - origin[axis]) / ray[axis];
        if (s > 0 && s < best) best = s;
      };
      hit(2, 3.0);
      hit(1, 1.0);
      hit(0, -1.5);
      const Eigen::Vector3d p = origin + best * ray;
      const double texture = 128 + 50 * std::sin(9 * p.x() + 2 * p.z()) * std::cos(7 * p.y()) +
                             40 * std::sin(17 * (p.x() - p.y() + p.z()));
      const auto g = static_cast<uchar>(std::clamp(texture, 0.0, 255.0));
      rgb.at<cv::Vec3b>(v, u) = {g, g, g};
      depth.at<float>(v, u) = static_cast<float>(best);  // rayCam.z == 1: s is the depth
    }
}

std::vector<Eigen::Isometry3d> handheldPath(int frames) {
  std::vector<Eigen::Isometry3d> path;
  for (int i = 0; i < frames; ++i) {
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
    T.translation() = Eigen::Vector3d(0.01 * i, -0.004 * i, 0.006 * i);
    T.linear() = Eigen::AngleAxisd(0.5 * i * M_PI / 180, Eigen::Vector3d(0.2, 1, 0.1).normalized())
                     .toRotationMatrix();
    path.push_back(T);
  }
  return path;
}

}  // namespace dynslam::testing
