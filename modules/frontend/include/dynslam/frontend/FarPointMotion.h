#pragma once
// The motion of a point the depth camera cannot see (beyond its range), from its pixels alone.
// Scene flow (Eq. 11) needs the point's depth; without it the camera's motion still says where a
// static point could appear: for every depth z >= minDepth along the earlier pixel's ray, the
// point moved with the camera lands on one segment of the image, from the projection at
// z = minDepth to the one at infinity (the rotation alone). A pixel off that segment moved by
// itself, and a point z away shows a displacement d of its own as about f d / z pixels: with
// z >= minDepth, d >= (distance to the segment) * minDepth / f. DynamicClassifier measures
// objects beyond the depth range with that lower bound (far_object_min_depth).
#include <dynslam/core/Frame.h>

#include <Eigen/Geometry>
#include <opencv2/core/types.hpp>

namespace dynslam::frontend {

/// Pixel distance from `current` to the segment on which a static point first seen at
/// `previous` would appear now at any depth >= minDepth (m, > 0), T_cur_prev mapping the earlier
/// camera frame to the current one. 0 when the segment is not in front of the camera.
double farPointResidualPx(const cv::Point2f& previous, const cv::Point2f& current,
                          const Eigen::Isometry3d& T_cur_prev, const core::CameraIntrinsics& k,
                          double minDepth);

/// The lower bound of the displacement (m) of such a point between the two frames:
/// farPointResidualPx * minDepth / f, f the mean focal length.
double farPointMinDisplacement(const cv::Point2f& previous, const cv::Point2f& current,
                               const Eigen::Isometry3d& T_cur_prev, const core::CameraIntrinsics& k,
                               double minDepth);

}  // namespace dynslam::frontend
