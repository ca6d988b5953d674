#pragma once
// The ground under the objects (not the method): a plane fitted by RANSAC to the lower half of
// the depth image, and the mask pixels that lie on it dropped. A box around a car seen from the
// road holds a wedge of road within the car's depth range [T_min, T_max] (e = 3 m): on
// outdoor_street_high 36-39 % of the car masks' pixels were road or pavement (bench-segmentation,
// mask IoU 0.49-0.58), and the features there took the car's motion class.
#include <dynslam/core/Frame.h>
#include <dynslam/core/Perception.h>

#include <Eigen/Core>
#include <opencv2/core/mat.hpp>

#include <cstdint>
#include <optional>
#include <vector>

namespace dynslam::segmentation {

struct FloorPlaneParams {
  int samples = 1200;             ///< grid points over the lower half of the image
  int iterations = 60;            ///< RANSAC hypotheses (3 points each)
  double inlier_distance = 0.04;  ///< m from the plane
  double max_tilt_deg = 35;       ///< normal's angle from the camera's up axis (-y), at most
  double min_height = 0.2, max_height = 3.0;  ///< m, camera above the plane
  double min_inlier_share = 0.15;             ///< of the valid samples
  std::uint32_t seed = 1;
};

/// Plane n.p + d = 0 in camera coordinates (x right, y down, z forward), |n| = 1, oriented so
/// that the camera is above it (d > 0 = the camera's height).
struct Plane {
  Eigen::Vector3d n = Eigen::Vector3d::Zero();
  double d = 0;
  double distance(const Eigen::Vector3d& p) const { return n.dot(p) + d; }
};

/// The floor or road in `depth` (CV_32FC1, m), or nothing when no near-horizontal plane below
/// the camera holds enough of the samples (the camera looks at a wall, a crowd fills the view).
std::optional<Plane> fitFloorPlane(const cv::Mat& depth, const core::CameraIntrinsics& k,
                                   const FloorPlaneParams& params = {});

/// Clears the pixels of `mask` whose 3-D point lies less than `margin` above `floor` (or
/// below it).
void dropFloorPixels(core::ObjectMask& mask, const cv::Mat& depth, const core::CameraIntrinsics& k,
                     const Plane& floor, double margin);

}  // namespace dynslam::segmentation
