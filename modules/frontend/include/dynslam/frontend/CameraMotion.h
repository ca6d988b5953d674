#pragma once
// The camera's own motion between two frames, which the scene flow (method.md Eq. 11) removes.
//
// Why this source: the method predicts it "from the IMU", but the IMU alone gives only the
// rotation (the gyro integrated over the frame's samples); the translation needs the velocity,
// which only the estimator (issue 6) will provide. So the translation, and a check of the
// rotation, come from the background itself: a RANSAC 3-D registration (RigidRegistration.h)
// of the features outside every object mask, with the IMU rotation (its translation from the
// median of q - R p) and the previous motion as extra hypotheses that compete with the drawn
// ones, then the precise registration on all inliers. RGB-D gives metric depth, so a handful of
// background points fixes the motion; they are the same features the camera is tracked with,
// and most of them are static in every scenario the method targets. When a stage before this
// one already estimated the poses (Frame::T_world_camera on both frames), those are used
// instead. Without enough background pairs (a person filling the view), the IMU rotation with
// the previous translation, else the previous motion, stands in (constant velocity).
#include <dynslam/core/Frame.h>
#include <dynslam/frontend/RigidRegistration.h>

#include <optional>
#include <random>
#include <vector>

namespace dynslam::frontend {

/// Rotation of the camera between the previous frame (time t_prev) and this one, integrated
/// from the gyro samples of `imu` (those with t in (t_prev, t_cur], each held over the interval
/// that ends at it), expressed as the R of q = R p for static points (p in the previous camera
/// frame, q in this one). nullopt when no sample has a gyro reading. The sensor extrinsics map
/// the IMU axes to the camera's: R_CI = R_BC^T R_BI.
std::optional<Eigen::Matrix3d> gyroCameraRotation(const std::vector<core::ImuSample>& imu,
                                                  double t_prev, double t_cur,
                                                  const Eigen::Isometry3d& T_body_imu,
                                                  const Eigen::Isometry3d& T_body_camera);

/// Where a camera motion came from (for logs and the bench).
enum class CameraMotionSource { Poses, Registration, ImuRotationConstantVelocity, ConstantVelocity };

struct CameraMotionEstimate {
  RigidMotion motion;  ///< static points: q = R p + t (previous camera frame -> this one)
  CameraMotionSource source = CameraMotionSource::ConstantVelocity;
  int inliers = 0;     ///< background pairs that agree with it (Registration only)
};

struct CameraMotionParams {
  RansacParams ransac{100, 4, 0.05};  ///< tau looser than the objects': background is farther
  int min_inliers = 8;                ///< fewer: the registration is not trusted
};

class CameraMotionEstimator {
 public:
  explicit CameraMotionEstimator(CameraMotionParams params = {}, std::uint32_t seed = 1);

  /// Background pairs p (previous camera frame) -> q (this one), the gyro rotation when there
  /// is one, the poses when a pose stage set them on both frames.
  CameraMotionEstimate estimate(const std::vector<Eigen::Vector3d>& p,
                                const std::vector<Eigen::Vector3d>& q,
                                const std::optional<Eigen::Matrix3d>& gyro_rotation,
                                const std::optional<Eigen::Isometry3d>& T_world_prev,
                                const std::optional<Eigen::Isometry3d>& T_world_cur);

  /// Forget the previous motion (a gap in the stream).
  void reset() { previous_ = {}; }

 private:
  CameraMotionParams params_;
  std::mt19937 rng_;
  RigidMotion previous_;
};

}  // namespace dynslam::frontend
