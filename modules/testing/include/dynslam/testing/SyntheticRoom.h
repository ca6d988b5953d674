#pragma once
// A ray-cast corner of a textured room (back wall z = 3, floor y = 1, left wall x = -1.5 in a
// world whose axes are the first camera's optical axes), for tests that need RGB-D images with
// exactly known camera poses and no dataset.
#include <dynslam/core/Frame.h>

#include <Eigen/Geometry>
#include <opencv2/core.hpp>

#include <vector>

namespace dynslam::testing {

/// 640 x 480, f = 525, principal point at the centre (a Kinect-like camera).
core::CameraIntrinsics vgaCamera();

/// Colour (CV_8UC3, grey texture) and depth (CV_32FC1, metres) seen from T_world_camera.
void renderRoom(const Eigen::Isometry3d& T_world_camera, const core::CameraIntrinsics& camera,
                cv::Mat& rgb, cv::Mat& depth);

/// A smooth handheld-like path: per frame about 1 cm of translation and 0.5 degree of rotation.
std::vector<Eigen::Isometry3d> handheldPath(int frames);

}  // namespace dynslam::testing
