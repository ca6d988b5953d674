#pragma once
// Where an object's body centre is, measured from one frame's mask and depth (the ObjectStates
// stage's measurement). A camera sees the near surface of a body; its centre lies behind that
// surface along the line of sight by half the body's depth, which one view cannot see: it is
// assumed to be thickness_fraction of the seen width (a walker's torso is about half as deep
// as his shoulders are wide), at most max_thickness_m (a car seen from its side).
//
// In the camera frame, with `up` (unit) and the horizontal line of sight f to the mask's median
// point, each mask pixel with depth is split into across (r = up x f), along (f) and up
// coordinates; width and height are their 2nd to 98th percentile spans (widened to the whole
// span of evenly spread pixels); the centre is (median across, median along + thickness / 2,
// middle of the height), its covariance the configured sigmas along those three axes.
#include <dynslam/core/Frame.h>

#include <Eigen/Core>

#include <optional>

namespace dynslam::tracking {

struct ObjectCentreParams {
  int pixel_stride = 4;             ///< px; every this-th mask pixel in x and y
  int min_points = 30;              ///< mask pixels with depth for a measurement
  double thickness_fraction = 0.5;  ///< the body's depth along the line of sight / its width
  double max_thickness_m = 2.0;
  double sigma_across_m = 0.05;  ///< the centre's sigma across the line of sight
  double sigma_along_m = 0.10;   ///< along it (the assumed depth)
  double sigma_up_m = 0.10;      ///< along up (a mask cut at the floor or by an occluder)
};

struct ObjectCentre {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();  ///< camera frame, m
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Identity();
  Eigen::Vector3d extent = Eigen::Vector3d::Zero();  ///< across, along (assumed), up; m
  int points = 0;                                    ///< mask pixels with depth it used
};

/// The centre of `mask`'s object in this frame; nullopt with fewer than min_points pixels with
/// depth, or an `up_camera` along the line of sight.
std::optional<ObjectCentre> measureObjectCentre(const cv::Mat& depth,
                                                const core::CameraIntrinsics& K,
                                                const core::ObjectMask& mask,
                                                const Eigen::Vector3d& up_camera,
                                                const ObjectCentreParams& params);

}  // namespace dynslam::tracking
