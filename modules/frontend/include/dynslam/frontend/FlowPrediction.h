#pragma once
// Where the KLT search starts for each point (method.md section 3: "the flow of each point is
// initialised from the IMU-predicted rotation"). Over one frame interval the camera's rotation
// moves the image far more than its translation does, and the rotation alone maps pixels by
// the infinite homography H = K R K^-1, independent of depth: so the gyro puts the search
// within a pixel or two of the answer even when the image jumps tens of pixels, and KLT then
// only corrects the translation's parallax.
#include <dynslam/core/Frame.h>

#include <Eigen/Core>
#include <opencv2/core/types.hpp>

#include <vector>

namespace dynslam::frontend {

/// Pixels of `previous` (previous image) moved by the camera rotation R (q = R p for a static
/// point: previous camera frame -> this one): x' ~ K R K^-1 x. A point whose ray turns behind
/// the camera keeps its pixel.
std::vector<cv::Point2f> predictByRotation(const std::vector<cv::Point2f>& previous,
                                           const core::CameraIntrinsics& K,
                                           const Eigen::Matrix3d& R);

}  // namespace dynslam::frontend
