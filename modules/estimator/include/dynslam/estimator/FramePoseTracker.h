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

/// Bounds on how far a frame's PnP pose may lie from what was expected of it (m, deg).
struct PnpPoseGate {
  /// From the motion prediction or from the last pose: farther is a wrong RANSAC consensus.
  double max_m = 0.3, max_deg = 20.0;
  /// From an IMU prediction (0: off, the bounds above only). Not the method: where a walker
  /// filling the view passes for static, PnP follows it, while the IMU's prediction over a
  /// keyframe interval stays close (docs/notes/estimator.md, 2026-11-28 (pnp_max_imu_correction)).
  double imu_max_m = 0.0, imu_max_deg = 0.0;
};

/// Finite, translated by at most `max_m` and turned by at most `max_deg`.
bool withinStep(const Eigen::Isometry3d& step, double max_m, double max_deg);

/// Whether a frame takes its PnP body pose `tracked`: with an IMU prediction and the gate's IMU
/// bounds set, when within them of `predicted`; otherwise when within the loose bounds of
/// `predicted` or of `last` (the constant-velocity prediction extrapolates one bad step frame
/// after frame, the last pose does not).
bool acceptPnpPose(const Eigen::Isometry3d& tracked, const Eigen::Isometry3d& predicted,
                   bool predictedByImu, const std::optional<Eigen::Isometry3d>& last,
                   const PnpPoseGate& gate);

/// `landmarks`: world positions by feature id; `pixels`: this frame's features by id.
std::optional<TrackedPose> trackFramePose(
    const PinholeCamera& camera, const std::vector<std::pair<std::int64_t, Eigen::Vector3d>>& landmarks,
    const std::map<std::int64_t, Eigen::Vector2d>& pixels, const Eigen::Isometry3d& predicted,
    const FramePoseTrackerParams& params = {});

}  // namespace dynslam::estimator
