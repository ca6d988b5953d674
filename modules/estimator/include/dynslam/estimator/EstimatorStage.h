#pragma once
// The estimator stage (class "Estimator", ini section [Estimator]; method.md section 5): reads
// the frame's tracked features (FeatureTracking, and DynamicClassification when it ran),
// selects keyframes, keeps the sliding window (SlidingWindow) and writes the camera pose of every
// frame into Frame::T_world_camera: keyframes from the window's solve, the frames between them by
// PnP against the window's landmarks. It also carries the tracked objects' rigid point sets
// into world trajectories (ObjectTrajectories: Frame::object_poses).
//
// Which features constrain the camera, and how, is dynamic_handling (the paper and its Table 9
// baselines): FeatureRouting.h.
//
// Sensors: RGB-D, and the IMU when the frames carry gyro + accelerometer samples and use_imu is
// on. The window starts from RGB-D alone (a constant-motion prior ties consecutive keyframes,
// world = the first frame's IMU frame); once it is full, the IMU initialization (ImuInitializer)
// is tried at every keyframe until it succeeds (and only while every keyframe of the window saw
// enough), and the window turns visual-inertial (gravity as found in the unchanged world, IMU
// factors, frames between keyframes predicted by the IMU). The estimator's body frame is the
// IMU's; its camera extrinsic is T_imu_camera = T_body_imu^-1 T_body_camera from the rawlog's
// sensor poses. Without an IMU (e.g. 7-Scenes, TUM's accelerometer-only IMU) it stays RGB-D
// only.
#include <dynslam/core/Options.h>
#include <dynslam/core/SampleReservoir.h>
#include <dynslam/core/Stage.h>
#include <dynslam/estimator/FeatureRouting.h>
#include <dynslam/estimator/ImuInitializer.h>
#include <dynslam/estimator/KeyframeImu.h>
#include <dynslam/estimator/KeyframeSelector.h>
#include <dynslam/estimator/ObjectTrajectories.h>
#include <dynslam/estimator/SlidingWindow.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace dynslam::estimator {

/// [Estimator]: every key, its range and meaning in describe() (EstimatorOptions.cpp).
struct EstimatorOptions : core::Options {
  SlidingWindowParams window;
  KeyframeSelectorParams keyframes;
  DynamicHandling dynamic_handling = DynamicHandling::Full;
  bool nonrigid_factors = true;
  bool rigid_factors = true;
  /// No r_D / r_O / r_om until the IMU initialization succeeds (method.md does not speak of
  /// start-up): in the visual-only start-up window the objects' motion models pulled the camera
  /// (docs/notes/estimator.md, 2026-11-28 (object_factors_wait_for_imu)).
  bool object_factors_wait_for_imu = true;
  /// Why: a moving feature's landmark was made from frames in which it was not known to move (a
  /// walker entering the view undetected, a detector miss).
  bool drop_moving_landmarks = true;
  bool use_imu = true;
  /// A preintegration spanning longer (no keyframe: tracking lost, frames missing) is dropped
  /// with its samples: its memory stays bounded, and past ~10 s the bias drift makes it
  /// worthless (VINS-Fusion skips IMU factors over 10 s too).
  double imu_max_preintegration_s = 10.0;
  ImuInitializerOptions imu_init;
  int min_pnp_inliers = 15;
  double pnp_threshold_px = 3.0;
  /// Farther from the constant-velocity prediction: a wrong RANSAC consensus.
  double pnp_max_correction_m = 0.3, pnp_max_correction_deg = 20.0;
  /// PnpPoseGate (FramePoseTracker.h). Not the method (0: off); measured gain:
  /// docs/notes/estimator.md, 2026-11-28 (pnp_max_imu_correction).
  double pnp_max_imu_correction_m = 0.05, pnp_max_imu_correction_deg = 3.0;
  /// Failure detection: estimates beyond these restart the window.
  double max_speed = 10.0, max_gyro_bias = 0.2, max_acc_bias = 2.0;
  int min_keyframe_features = 15;
  bool use_gnss = false;  ///< GnssAnchor; the lever arm is window.gnss_lever_arm
  GnssAnchorParams gnss;
  /// The camera in the IMU frame as 16 numbers, a row-major 4x4 (Kalibr's T_imu_cam,
  /// VINS-Fusion's body_T_cam0); empty: from the rawlog's sensor poses.
  std::string camera_in_imu;

  void describe(core::OptionVisitor& v) override;

 private:
  void describeWindow(core::OptionVisitor& v);
  void describeFrames(core::OptionVisitor& v);  // keyframes, PnP
  void describeImu(core::OptionVisitor& v);
  void describeDynamics(core::OptionVisitor& v);
  void describeGnss(core::OptionVisitor& v);
  void describeCalibration(core::OptionVisitor& v);
};

/// camera_in_imu parsed and checked: 16 numbers, the last row 0 0 0 1, a rotation orthonormal
/// with determinant +1 (within 1e-6). Throws core::ConfigError naming `key` otherwise.
Eigen::Isometry3d parseCameraInImu(const std::string& text, const std::string& key);

class EstimatorStage : public core::Stage {
 public:
  EstimatorStage();
  ~EstimatorStage() override;

  void configure(const core::IniConfig& cfg, const std::string& section) override;
  void process(core::Frame& frame) override;
  void finish() override;
  bool estimatesPose() const override { return true; }
  /// keyframes, solve_ms_median, solve_ms_max, pnp_failures, resets, imu_initialized_at (s
  /// of stream, -1 never), imu_init_attempts, nonrigid_per_keyframe (features given to r_D),
  /// rigid_objects_per_keyframe (objects with r_O / r_om factors in the solve), imu_gaps,
  /// blind_frames (too few features for a keyframe), landmarks_dropped_moving
  /// (drop_moving_landmarks), gnss_aligned_at (s of stream, -1 never),
  /// gnss_alignment_rms (m), gnss_factors; the calibration at the end (CalibrationParams):
  /// time_offset_s and time_offset_sigma_s, extrinsic_x/y/z (m) and extrinsic_roll/pitch/yaw
  /// (deg, of T_imu_camera), extrinsic_rotation_change_deg and extrinsic_translation_change_m
  /// from the configured value, extrinsic_sigma_rotation_deg and
  /// extrinsic_sigma_translation_m (largest axis); a sigma is -1 when not estimated;
  /// time_offset_free_keyframes and extrinsic_free_keyframes: keyframes whose solve estimated
  /// each (the others held it: CalibrationExcitation.h).
  std::vector<std::pair<std::string, double>> statistics() const override;

  const EstimatorOptions& options() const { return options_; }

 private:
  /// What a keyframe is made from besides the routed features.
  struct KeyframeContext {
    KeyframeSelector::Reason reason;
    int shared = 0;            ///< features shared with the last keyframe
    Eigen::Isometry3d T_ic;    ///< camera in the body (IMU) frame
    Eigen::Vector3d velocity;  ///< the prediction's (IMU) or zero
  };
  /// What a keyframe left for the frame's output.
  struct KeyframeOutcome {
    bool restarted = false;
    std::vector<std::pair<int, Eigen::Isometry3d>> objects;  ///< the window's object poses
  };

  // process(), phase by phase.
  /// Creates the IMU and GNSS inputs once their data appears, and hands them the frame's.
  void takeSensorData(const core::Frame& frame);
  /// routeFeatures() as configured; drops the moving features' landmarks from the window.
  RoutedFeatures routeFrameFeatures(const core::Frame& frame);
  /// The frame's body pose: the PnP pose against the window's landmarks when it passes the
  /// gates, else the prediction. Starts the window on the first frame.
  Eigen::Isometry3d trackBody(const core::Frame& frame,
                              const std::map<std::int64_t, Eigen::Vector2d>& pixels,
                              const Eigen::Isometry3d& T_ic, Eigen::Vector3d& velocity);
  /// Whether the frame makes a keyframe (NotKeyframe when it sees too little).
  KeyframeSelector::Reason keyframeReason(double t, const RoutedFeatures& routed, int* shared);
  /// Adds the keyframe, solves, detects a failure (and restarts) or tries the IMU
  /// initialization; T_wb becomes the body pose to write. Sets frame.keyframe.
  KeyframeOutcome makeKeyframe(core::Frame& frame, RoutedFeatures& routed,
                               const KeyframeContext& context, Eigen::Isometry3d& T_wb);
  KeyframeInput keyframeInput(const core::Frame& frame, RoutedFeatures& routed,
                              const Eigen::Isometry3d& T_wb, const KeyframeContext& context);
  /// Marks a usable solve unusable when its newest keyframe is not plausible.
  void detectFailure(SolveReport& report, const Eigen::Isometry3d& tracked) const;
  void restartWindow(const core::Frame& frame, KeyframeInput& in, const Eigen::Isometry3d& T_wb,
                     const std::map<std::int64_t, Eigen::Vector2d>& pixels);
  /// Frame::T_world_camera and the objects' poses; the motion model's last poses.
  void writePose(core::Frame& frame, Eigen::Isometry3d T_wb, const Eigen::Isometry3d& T_ic,
                 const KeyframeOutcome& keyframe);

  void startWindow(const core::Frame& frame);
  /// The camera in the IMU frame the window starts from: camera_in_imu, else the frame's
  /// sensor poses.
  Eigen::Isometry3d configuredExtrinsic(const core::Frame& frame) const;
  /// The body pose this frame is expected at: IMU propagation from the last keyframe when the
  /// window is visual-inertial, else constant velocity from the last two frames.
  /// `fromImu` (optional): set to whether the IMU propagation gave it.
  Eigen::Isometry3d predictBody(double t, Eigen::Vector3d* velocity, bool* fromImu = nullptr) const;
  void tryImuInitialization(double t);
  /// use_gnss: hands the window the GNSS targets of keyframes whose fixes have arrived.
  void anchorToGnss(double t);
  /// T_body_camera's change from the configured extrinsic: prior^-1 T (T itself before the
  /// first frame).
  Eigen::Isometry3d extrinsicChange(const Eigen::Isometry3d& T_body_camera) const;
  /// statistics()'s calibration entries.
  void appendCalibration(std::vector<std::pair<std::string, double>>& out) const;
  /// A pose change no larger than pnp_max_correction_m / _deg (and finite).
  bool plausibleStep(const Eigen::Isometry3d& step) const;

  EstimatorOptions options_;
  std::optional<Eigen::Isometry3d> camera_in_imu_;  // options_.camera_in_imu, parsed
  CalibrationEstimate final_calibration_;           // finish(): with standard deviations
  int free_keyframes_[2] = {0, 0};  // keyframes whose solve estimated t_d / the extrinsic
  std::unique_ptr<SlidingWindow> window_;
  std::unique_ptr<KeyframeImu> imu_;
  std::unique_ptr<GnssAnchor> gnss_;
  ObjectTrajectories objects_;
  KeyframeSelector selector_;
  std::optional<Eigen::Isometry3d> last_body_, previous_body_;  // for the motion prediction
  core::SampleReservoir solve_ms_;
  std::size_t keyframes_ = 0, pnp_failures_ = 0, resets_ = 0, frames_ = 0;
  std::size_t imu_init_attempts_ = 0, nonrigid_observations_ = 0, blind_frames_ = 0;
  std::size_t rigid_objects_solved_ = 0;  // sum over keyframes of SolveReport::rigid_objects
  std::size_t gnss_factors_ = 0;
  std::size_t landmarks_dropped_ = 0;  // drop_moving_landmarks
  double first_t_ = 0, imu_initialized_at_ = -1, gnss_aligned_at_ = -1;
  std::string last_init_failure_;
};

}  // namespace dynslam::estimator
