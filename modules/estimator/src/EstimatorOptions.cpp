#include "dynslam/estimator/EstimatorStage.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace dynslam::estimator {
namespace {

constexpr core::Keyword<DynamicHandling> kHandlings[] = {{"none", DynamicHandling::None},
                                                         {"remove", DynamicHandling::Remove},
                                                         {"full", DynamicHandling::Full}};
constexpr core::Keyword<ExtrinsicEstimation> kExtrinsicModes[] = {
    {"none", ExtrinsicEstimation::None},
    {"rotation", ExtrinsicEstimation::Rotation},
    {"full", ExtrinsicEstimation::Full}};
constexpr core::Keyword<LandmarkReanchoring> kReanchorings[] = {
    {"next", LandmarkReanchoring::Next}, {"newest", LandmarkReanchoring::Newest}};

}  // namespace

void EstimatorOptions::describe(core::OptionVisitor& v) {
  describeWindow(v);
  describeFrames(v);
  describeImu(v);
  describeDynamics(v);
  describeGnss(v);
  describeCalibration(v);
}

void EstimatorOptions::describeCalibration(core::OptionVisitor& v) {
  using core::Range;
  auto& c = window.calibration;
  v.key("estimate_time_offset", c.estimate_time_offset,
        "estimate the camera-IMU time offset t_d online once the IMU is initialized "
        "(VINS-Fusion's estimate_td); not yet reliable: the estimate stays near its start "
        "(docs/benchmarks.md)");
  v.key("time_offset", c.time_offset_s, Range::closed(-0.2, 0.2),
        "s; camera-IMU time offset t_d, t_imu = t_camera + t_d (VINS-Fusion's td): the value "
        "used when not estimated, the start and the prior's mean when estimated");
  v.key("time_offset_sigma", c.time_offset_sigma_s, Range::above(0),
        "s; the prior's sigma on t_d (estimate_time_offset)");
  v.key("estimate_extrinsic", c.estimate_extrinsic, kExtrinsicModes,
        "none: the camera-IMU extrinsic as configured; rotation: its rotation estimated online "
        "once the IMU is initialized, translation held; full: both (VINS-Fusion's "
        "estimate_extrinsic), held while the window does not turn (calibration_min_rotation_deg); "
        "the window's gauge is then its first camera pose and the world gravity is estimated "
        "with it (docs/benchmarks.md)");
  v.key("extrinsic_sigma_rotation_deg", c.extrinsic_sigma_rotation_deg, Range::above(0),
        "deg; the prior's sigma on the extrinsic rotation (estimate_extrinsic)");
  v.key("extrinsic_sigma_translation", c.extrinsic_sigma_translation_m, Range::above(0),
        "m; the prior's sigma on the extrinsic translation (estimate_extrinsic = full)");
  v.key("calibration_min_rotation_deg", c.excitation.min_rotation_deg, Range::atLeast(0),
        "deg; the extrinsic is held where it is while no keyframe of the window is turned by "
        "this much from the window's first (without rotation it is not observable)");
  v.key("calibration_min_rate_change", c.excitation.min_rate_change, Range::atLeast(0),
        "rad/s; t_d is held while the window's angular rates stay this close to their mean and "
        "its body-frame velocities closer than calibration_min_velocity_change (under constant "
        "local velocity a time offset is not observable)");
  v.key("calibration_min_velocity_change", c.excitation.min_velocity_change, Range::atLeast(0),
        "m/s; see calibration_min_rate_change");
  v.key("camera_in_imu", camera_in_imu,
        "the colour camera in the IMU frame, 16 numbers: a row-major 4x4 (Kalibr's T_imu_cam, "
        "VINS-Fusion's body_T_cam0); the configured extrinsic instead of the rawlog's sensor "
        "poses (empty: the rawlog's)");
  const CalibrationParams defaults;
  const std::string needed = "estimate_time_offset = true";
  v.requires("time_offset_sigma", c.time_offset_sigma_s != defaults.time_offset_sigma_s, needed,
             c.estimate_time_offset);
  const bool extrinsic = c.estimate_extrinsic != ExtrinsicEstimation::None;
  v.requires("extrinsic_sigma_rotation_deg",
             c.extrinsic_sigma_rotation_deg != defaults.extrinsic_sigma_rotation_deg,
             "estimate_extrinsic = rotation or full", extrinsic);
  v.requires("extrinsic_sigma_translation",
             c.extrinsic_sigma_translation_m != defaults.extrinsic_sigma_translation_m,
             "estimate_extrinsic = full", c.estimate_extrinsic == ExtrinsicEstimation::Full);
}

Eigen::Isometry3d parseCameraInImu(const std::string& text, const std::string& key) {
  std::istringstream in(text);
  std::vector<double> values;
  std::string token;
  while (in >> token) {
    try {
      std::size_t used = 0;
      values.push_back(std::stod(token, &used));
      if (used != token.size()) throw std::invalid_argument(token);
    } catch (const std::exception&) {
      throw core::ConfigError(key + ": '" + token + "' is not a number");
    }
  }
  if (values.size() != 16)
    throw core::ConfigError(key + ": expected 16 numbers (a row-major 4x4), got " +
                            std::to_string(values.size()));
  const Eigen::Matrix4d M =
      Eigen::Map<const Eigen::Matrix<double, 4, 4, Eigen::RowMajor>>(values.data());
  if (!M.allFinite()) throw core::ConfigError(key + ": the numbers must be finite");
  if ((M.row(3) - Eigen::RowVector4d(0, 0, 0, 1)).cwiseAbs().maxCoeff() > 1e-9)
    throw core::ConfigError(key + ": the last row must be 0 0 0 1");
  const Eigen::Matrix3d R = M.topLeftCorner<3, 3>();
  const double offOrthonormal =
      (R.transpose() * R - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff();
  if (offOrthonormal > 1e-6 || R.determinant() < 0)
    throw core::ConfigError(key +
                            ": the rotation is not orthonormal with determinant +1 (R^T R "
                            "differs from I by " +
                            std::to_string(offOrthonormal) + ", det " +
                            std::to_string(R.determinant()) + ")");
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = Eigen::Quaterniond(R).normalized().toRotationMatrix();
  T.translation() = M.topRightCorner<3, 1>();
  return T;
}

void EstimatorOptions::describeWindow(core::OptionVisitor& v) {
  using core::Range;
  const Range positive = Range::above(0), off = Range::atLeast(0);
  auto& w = window;
  v.key("window_size", w.window_size, Range::atLeast(2), "keyframes in the sliding window");
  v.key("max_iterations", w.max_iterations, Range::atLeast(1),
        "Ceres iterations per keyframe solve");
  v.key("max_solver_time", w.max_solver_time_s, positive,
        "s; Ceres wall-time limit per keyframe solve");
  v.key("line_search_steps", w.line_search_steps, off,
        "steps of Ceres's projected line search after each step of a bounded problem (Ceres: "
        "20); 0: the step is only projected onto the bounds");
  v.key("pixel_sigma", w.pixel_sigma, positive, "px; feature position noise");
  v.key("huber_sigmas", w.huber_sigmas, positive, "Huber threshold on whitened residuals");
  v.key("depth_sigma_a", w.depth_noise.a, positive, "m; depth noise sigma_d = a + b d^2");
  v.key("depth_sigma_b", w.depth_noise.b, off, "1/m; depth noise sigma_d = a + b d^2");
  v.key("transferred_depth", w.transferred_depth,
        "depth measured in later keyframes constrains them too (not the method: the first "
        "observation's only)");
  v.key("landmark_reanchoring", w.landmark_reanchoring, kReanchorings,
        "a landmark anchored at the keyframe leaving the window (its factors go into the "
        "marginalisation prior): next: anchored at its next observation, the others used again "
        "(VINS-Fusion; the prior already holds them); newest: anchored at its newest "
        "observation, the ones before dropped (no measurement counted twice)");
  v.key("motion_prior_sigma_translation", w.motion_prior_sigma_translation, positive,
        "m per keyframe interval; RGB-D-only constant-motion prior");
  v.key("motion_prior_sigma_rotation", w.motion_prior_sigma_rotation, positive,
        "rad per keyframe interval; RGB-D-only constant-motion prior");
  v.key("gyro_rotation_sigma", w.gyro_rotation_sigma, off,
        "rad/s; until the IMU is initialized, consecutive keyframes keep the gyro's rotation "
        "within this rate times their interval (not the method; 0: off)");
  v.key("object_motion_sigma_translation", w.object_motion_sigma_translation, positive,
        "m per keyframe interval; r_om, a rigid object's change of motion");
  v.key("object_motion_sigma_rotation", w.object_motion_sigma_rotation, positive,
        "rad per keyframe interval; r_om, a rigid object's change of motion");
}

void EstimatorOptions::describeFrames(core::OptionVisitor& v) {
  using core::Range;
  const Range positive = Range::above(0), off = Range::atLeast(0);
  v.key("keyframe_parallax_px", keyframes.min_parallax_px, off,
        "px; mean feature motion since the last keyframe that makes a keyframe");
  v.key("keyframe_max_interval", keyframes.max_interval_s, positive,
        "s; a keyframe at least this often");
  v.key("keyframe_min_shared", keyframes.min_shared, off,
        "fewer features shared with the last keyframe make a keyframe");
  v.key("min_pnp_inliers", min_pnp_inliers, Range::atLeast(4),
        "PnP inliers needed to track a frame");
  v.key("pnp_threshold_px", pnp_threshold_px, positive, "px; PnP RANSAC reprojection threshold");
  v.key("pnp_max_correction_m", pnp_max_correction_m, positive,
        "m; a PnP pose farther than this from the motion prediction and from the last pose is "
        "rejected (not the method)");
  v.key("pnp_max_correction_deg", pnp_max_correction_deg, positive,
        "deg; the same for the rotation (not the method)");
  v.key("pnp_max_imu_correction_m", pnp_max_imu_correction_m, off,
        "m; visual-inertial: a PnP pose farther from the IMU prediction is not used (not the "
        "method; 0: off)");
  v.key("pnp_max_imu_correction_deg", pnp_max_imu_correction_deg, off,
        "deg; the same for the rotation (not the method; 0: off)");
  v.key("min_keyframe_features", min_keyframe_features, off,
        "a frame with fewer static features makes no keyframe, its pose is predicted (not the "
        "method; 0: off)");
}

void EstimatorOptions::describeImu(core::OptionVisitor& v) {
  using core::Range;
  const Range positive = Range::above(0);
  auto& n = window.imu_noise;
  v.key("use_imu", use_imu, "use the IMU when the frames carry gyro + accelerometer samples");
  v.key("acc_noise", n.acc_noise, positive, "m/s^2/sqrt(Hz); accelerometer white noise");
  v.key("gyro_noise", n.gyro_noise, positive, "rad/s/sqrt(Hz); gyroscope white noise");
  v.key("acc_random_walk", n.acc_random_walk, positive,
        "m/s^3/sqrt(Hz); accelerometer bias random walk");
  v.key("gyro_random_walk", n.gyro_random_walk, positive,
        "rad/s^2/sqrt(Hz); gyroscope bias random walk");
  v.key("imu_max_preintegration", imu_max_preintegration_s, positive,
        "s; an IMU preintegration between keyframes spanning longer is dropped with its samples "
        "(that keyframe pair gets no IMU factor): bounds its memory when no keyframe comes");
  v.key("gravity", imu_init.gravity_magnitude, positive, "m/s^2; local gravity");
  v.key("init_min_acceleration_rms", imu_init.min_acceleration_rms, Range::atLeast(0),
        "m/s^2; IMU initialization waits for this much motion (0: still starts accepted)");
  v.key("max_speed", max_speed, positive, "m/s; a faster estimate is a failure (window restarted)");
  v.key("max_gyro_bias", max_gyro_bias, positive,
        "rad/s; a larger gyro bias estimate is a failure");
  v.key("max_acc_bias", max_acc_bias, positive,
        "m/s^2; a larger accelerometer bias estimate is a failure");
}

void EstimatorOptions::describeDynamics(core::OptionVisitor& v) {
  v.key("dynamic_handling", dynamic_handling, kHandlings,
        "none: every feature static (VINS-Mono); remove: only Static features off the detected "
        "objects, people and cars masked out moving or not (Dynamic-VINS); full: the paper, "
        "Static features on objects kept (see nonrigid_factors, rigid_factors)");
  v.key("drop_moving_landmarks", drop_moving_landmarks,
        "a feature classified as moving (with remove also a still one on a detected object) "
        "takes its static landmark, with every observation, out of the window (not with none; "
        "not the method)");
  v.key("nonrigid_factors", nonrigid_factors,
        "NonRigid features as constant-velocity world points (r_D); false: dropped (Table 9)");
  v.key("rigid_factors", rigid_factors,
        "Rigid features as points of their object, whose poses the window estimates (r_O, "
        "r_om); false: dropped (Table 9)");
  v.key("object_factors_wait_for_imu", object_factors_wait_for_imu,
        "with full and an IMU: the object factors start once the IMU is initialized (moving "
        "features dropped until then; not in the method)");
  // Table 9's ablations switch the factors off; with none or remove they are never made.
  const bool full = dynamic_handling == DynamicHandling::Full;
  v.requires("nonrigid_factors", !nonrigid_factors, "dynamic_handling = full", full);
  v.requires("rigid_factors", !rigid_factors, "dynamic_handling = full", full);
}

void EstimatorOptions::describeGnss(core::OptionVisitor& v) {
  const core::Range positive = core::Range::above(0);
  v.key("use_gnss", use_gnss,
        "GNSS position factors on keyframes (ENU from the first fix, aligned to the world once "
        "the path spans gnss_align_span)");
  v.key("gnss_uere_horizontal", gnss.uere_horizontal_m, positive,
        "m; horizontal sigma of a fix at HDOP 1 (2-5 m plain GPS, ~0.02 m RTK)");
  v.key("gnss_vertical_factor", gnss.vertical_factor, positive,
        "vertical sigma = this x horizontal sigma");
  v.key("gnss_align_span", gnss.alignment.min_span_m, positive,
        "m; horizontal extent of the path before ENU is aligned to the world");
  auto& arm = window.gnss_lever_arm;
  v.key("gnss_lever_arm_x", arm.x(), core::Range::any(), "m; GNSS antenna in the body (IMU) frame");
  v.key("gnss_lever_arm_y", arm.y(), core::Range::any(), "m; GNSS antenna in the body (IMU) frame");
  v.key("gnss_lever_arm_z", arm.z(), core::Range::any(), "m; GNSS antenna in the body (IMU) frame");
  v.key("gnss_huber_sigmas", window.gnss_huber_sigmas, positive,
        "Huber threshold on the whitened GNSS residual");
  // The receiver's settings act only through the GNSS factors.
  const GnssAnchorParams receiver;
  const SlidingWindowParams factor;
  const std::string needed = "use_gnss = true";
  v.requires("gnss_uere_horizontal", gnss.uere_horizontal_m != receiver.uere_horizontal_m, needed,
             use_gnss);
  v.requires("gnss_vertical_factor", gnss.vertical_factor != receiver.vertical_factor, needed,
             use_gnss);
  v.requires("gnss_align_span", gnss.alignment.min_span_m != receiver.alignment.min_span_m, needed,
             use_gnss);
  v.requires("gnss_lever_arm_x", arm.x() != factor.gnss_lever_arm.x(), needed, use_gnss);
  v.requires("gnss_lever_arm_y", arm.y() != factor.gnss_lever_arm.y(), needed, use_gnss);
  v.requires("gnss_lever_arm_z", arm.z() != factor.gnss_lever_arm.z(), needed, use_gnss);
  v.requires("gnss_huber_sigmas", window.gnss_huber_sigmas != factor.gnss_huber_sigmas, needed,
             use_gnss);
}

}  // namespace dynslam::estimator
