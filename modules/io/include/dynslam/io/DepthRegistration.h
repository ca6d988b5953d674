#pragma once
// Re-projects a depth image into another camera (z-buffered forward warp), for sensors whose
// depth and colour cameras are not the same (Kinect v1 rawlogs written by MRPT's grabber).
#include <dynslam/core/Frame.h>

#include <Eigen/Geometry>
#include <opencv2/core/mat.hpp>

namespace dynslam::io {

/// `depth` (CV_32FC1 metres, camera `from`) seen from camera `to`, whose pose in `from`'s
/// optical frame is given as T_to_from (maps points from `from` into `to`). Pixels no depth
/// point lands on are 0; where several land, the nearest wins.
cv::Mat registerDepth(const cv::Mat& depth, const core::CameraIntrinsics& from,
                      const core::CameraIntrinsics& to, const Eigen::Isometry3d& T_to_from);

/// Converts ranges along each pixel's ray into depths along the optical axis, in place.
void rangesToDepths(cv::Mat& ranges, const core::CameraIntrinsics& camera);

}  // namespace dynslam::io
