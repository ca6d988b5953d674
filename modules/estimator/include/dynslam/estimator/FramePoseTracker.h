#pragma once
// The pose of a frame from the window's landmarks (the frames between keyframes, and the first
// guess of a new keyframe): RANSAC PnP (OpenCV) on the frame's static features whose landmark
// the window has positioned, started from a predicted pose, refined on the inliers.
#include <Eigen/Geometry>

#include <cstdint>
#include <map>
#include <optional>
#include <vector>

namespace dynslam::estimator {

struct PinholeCamera;

struct FramePoseTrackerParams {
  int min_inliers = 15;             ///< fewer: no pose (the caller keeps its prediction)
  double ransac_threshold_px = 3.0; ///< PnP RANSAC reprojection threshold
};

struct TrackedPose {
  Eigen::Isometry3d T_world_camera = Eigen::Isometry3d::Identity();
  int inliers = 0;
  int candidates = 0;  ///< features with a landmark
};

/// `landmarks`: world positions by feature id; `pixels`: this frame's features by id.
std::optional<TrackedPose> trackFramePose(
    const PinholeCamera& camera, const std::vector<std::pair<std::int64_t, Eigen::Vector3d>>& landmarks,
    const std::map<std::int64_t, Eigen::Vector2d>& pixels, const Eigen::Isometry3d& predicted,
    const FramePoseTrackerParams& params = {});

}  // namespace dynslam::estimator
