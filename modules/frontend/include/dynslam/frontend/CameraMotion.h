#pragma once
// The camera's own motion between two frames, which the scene flow (method.md Eq. 11) removes.
//
// The method predicts it "from the IMU", but the IMU alone gives only the rotation (the gyro
// integrated over the frame's samples); the translation needs the velocity. So the translation
// comes from the background itself, the features outside every object mask, static in the
// scenes the method targets and metric thanks to the depth:
//  - with a gyro: the rotation is the gyro's and only the translation is registered (RANSAC
//    over one-pair hypotheses, then the inverse-variance weighted mean of the inliers). A full
//    3-D registration of points metres away gets the rotation wrong by tenths of a degree per
//    frame under the depth noise, which the translation then compensates by centimetres; the
//    gyro's rotation over a frame is good to hundredths. When it leaves most pairs unexplained
//    (extrinsics that do not hold), the full registration below is tried as well;
//  - without a gyro: the 4-point RANSAC 3-D registration (RigidRegistration.h) with the
//    previous motion as an extra hypothesis, then the precise registration on all inliers.
// When a stage before this one already estimated the poses (Frame::T_world_camera on both
// frames), those are used instead. Without enough background pairs (a person filling the
// view), the gyro rotation with the recent translation, else the previous motion, stands in
// (constant velocity). The recent translation is the component-wise median of the last
// kRecentTranslations registered ones, not the last one: the last registration before the view
// fills up is the one made on the fewest pairs. Measured: docs/notes/frontend.md, 2026-11-28
// (front-end settings' history).
#include <dynslam/core/Frame.h>
#include <dynslam/frontend/RigidRegistration.h>

#include <deque>
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
enum class CameraMotionSource {
  Poses,                        ///< T_world_camera of an earlier stage on both frames
  ImuRotationRegistration,      ///< gyro rotation, translation registered on the background
  Registration,                 ///< 6-DoF registration of the background
  ImuRotationConstantVelocity,  ///< too little background: gyro rotation, previous translation
  ConstantVelocity,             ///< too little background and no gyro: the previous motion
};

struct CameraMotionEstimate {
  RigidMotion motion;  ///< static points: q = R p + t (previous camera frame -> this one)
  CameraMotionSource source = CameraMotionSource::ConstantVelocity;
  int inliers = 0;     ///< background pairs that agree with it (registrations only)
  /// Standard error of the translation, m (the inliers' scatter about it over their number);
  /// 0 when not measured (poses, constant velocity).
  double translation_sigma = 0;
};

struct CameraMotionParams {
  RansacParams ransac{100, 4, 0.05};  ///< 6-DoF: tau looser than the objects' (farther points)
  /// Depth noise model sigma(z) = depth_sigma_z2 z^2 (m^-1; D455-like 0.0015): gates and weights
  /// the pairs of the translation-only registration.
  double depth_sigma_z2 = 0.0015;
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
  void reset() {
    previous_ = {};
    recent_.clear();
  }

  /// Registered translations the constant-velocity translation is the median of.
  static constexpr size_t kRecentTranslations = 10;

 private:
  /// RANSAC over the translation alone (one pair per hypothesis) with R fixed; the precise
  /// translation is the inverse-variance weighted mean of the inliers' q - R p.
  std::optional<RegistrationResult> translationWithRotation(const std::vector<Eigen::Vector3d>& p,
                                                            const std::vector<Eigen::Vector3d>& q,
                                                            const Eigen::Matrix3d& R);

  CameraMotionParams params_;
  std::mt19937 rng_;
  double lastSigma_ = 0;  ///< translation_sigma of the last registration
  RigidMotion previous_;
  std::deque<Eigen::Vector3d> recent_;  ///< translations of the last registrations, oldest first
};

}  // namespace dynslam::frontend
