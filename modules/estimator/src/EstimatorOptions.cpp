#include "dynslam/estimator/EstimatorStage.h"

#include <mrpt/config/CConfigFileBase.h>

#include <stdexcept>

namespace dynslam::estimator {
namespace {

constexpr core::Keyword<DynamicHandling> kHandlings[] = {{"none", DynamicHandling::None},
                                                         {"remove", DynamicHandling::Remove},
                                                         {"full", DynamicHandling::Full}};

}  // namespace

void EstimatorOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& c,
                                          const std::string& s) {
  auto& w = window;
  w.window_size = c.read_int(s, "window_size", w.window_size);
  w.max_iterations = c.read_int(s, "max_iterations", w.max_iterations);
  w.max_solver_time_s = c.read_double(s, "max_solver_time", w.max_solver_time_s);
  w.solver_threads = c.read_int(s, "solver_threads", w.solver_threads);
  w.line_search_steps = c.read_int(s, "line_search_steps", w.line_search_steps);
  w.pixel_sigma = c.read_double(s, "pixel_sigma", w.pixel_sigma);
  w.huber_sigmas = c.read_double(s, "huber_sigmas", w.huber_sigmas);
  w.depth_noise.a = c.read_double(s, "depth_sigma_a", w.depth_noise.a);
  w.depth_noise.b = c.read_double(s, "depth_sigma_b", w.depth_noise.b);
  w.transferred_depth = core::readBool(c, s, "transferred_depth", w.transferred_depth);
  w.motion_prior_sigma_translation =
      c.read_double(s, "motion_prior_sigma_translation", w.motion_prior_sigma_translation);
  w.motion_prior_sigma_rotation =
      c.read_double(s, "motion_prior_sigma_rotation", w.motion_prior_sigma_rotation);
  w.gyro_rotation_sigma = c.read_double(s, "gyro_rotation_sigma", w.gyro_rotation_sigma);
  w.object_motion_sigma_translation =
      c.read_double(s, "object_motion_sigma_translation", w.object_motion_sigma_translation);
  w.object_motion_sigma_rotation =
      c.read_double(s, "object_motion_sigma_rotation", w.object_motion_sigma_rotation);
  keyframes.min_parallax_px = c.read_double(s, "keyframe_parallax_px", keyframes.min_parallax_px);
  keyframes.max_interval_s = c.read_double(s, "keyframe_max_interval", keyframes.max_interval_s);
  keyframes.min_shared = c.read_int(s, "keyframe_min_shared", keyframes.min_shared);
  min_pnp_inliers = c.read_int(s, "min_pnp_inliers", min_pnp_inliers);
  pnp_threshold_px = c.read_double(s, "pnp_threshold_px", pnp_threshold_px);
  pnp_max_correction_m = c.read_double(s, "pnp_max_correction_m", pnp_max_correction_m);
  pnp_max_correction_deg = c.read_double(s, "pnp_max_correction_deg", pnp_max_correction_deg);
  pnp_max_imu_correction_m = c.read_double(s, "pnp_max_imu_correction_m", pnp_max_imu_correction_m);
  pnp_max_imu_correction_deg =
      c.read_double(s, "pnp_max_imu_correction_deg", pnp_max_imu_correction_deg);
  max_speed = c.read_double(s, "max_speed", max_speed);
  max_gyro_bias = c.read_double(s, "max_gyro_bias", max_gyro_bias);
  max_acc_bias = c.read_double(s, "max_acc_bias", max_acc_bias);
  min_keyframe_features = c.read_int(s, "min_keyframe_features", min_keyframe_features);
  use_imu = core::readBool(c, s, "use_imu", use_imu);
  auto& n = window.imu_noise;
  n.acc_noise = c.read_double(s, "acc_noise", n.acc_noise);
  n.gyro_noise = c.read_double(s, "gyro_noise", n.gyro_noise);
  n.acc_random_walk = c.read_double(s, "acc_random_walk", n.acc_random_walk);
  n.gyro_random_walk = c.read_double(s, "gyro_random_walk", n.gyro_random_walk);
  imu_init.gravity_magnitude = c.read_double(s, "gravity", imu_init.gravity_magnitude);
  imu_init.min_acceleration_rms =
      c.read_double(s, "init_min_acceleration_rms", imu_init.min_acceleration_rms);
  window.gravity = Eigen::Vector3d(0, 0, -imu_init.gravity_magnitude);
  dynamic_handling = core::readKeyword(c, s, "dynamic_handling", dynamic_handling, kHandlings);
  nonrigid_factors = core::readBool(c, s, "nonrigid_factors", nonrigid_factors);
  rigid_factors = core::readBool(c, s, "rigid_factors", rigid_factors);
  object_factors_wait_for_imu =
      core::readBool(c, s, "object_factors_wait_for_imu", object_factors_wait_for_imu);
  drop_moving_landmarks = core::readBool(c, s, "drop_moving_landmarks", drop_moving_landmarks);
  use_gnss = core::readBool(c, s, "use_gnss", use_gnss);
  gnss.uere_horizontal_m = c.read_double(s, "gnss_uere_horizontal", gnss.uere_horizontal_m);
  gnss.vertical_factor = c.read_double(s, "gnss_vertical_factor", gnss.vertical_factor);
  gnss.alignment.min_span_m = c.read_double(s, "gnss_align_span", gnss.alignment.min_span_m);
  for (int i = 0; i < 3; ++i)
    window.gnss_lever_arm[i] =
        c.read_double(s, std::string("gnss_lever_arm_") + "xyz"[i], window.gnss_lever_arm[i]);
  window.gnss_huber_sigmas = c.read_double(s, "gnss_huber_sigmas", window.gnss_huber_sigmas);
  if (!(gnss.uere_horizontal_m > 0 && gnss.vertical_factor > 0 && gnss.alignment.min_span_m > 0))
    throw std::invalid_argument(
        "gnss_uere_horizontal, gnss_vertical_factor and gnss_align_span must be > 0");
}

void EstimatorOptions::saveToConfigFile(mrpt::config::CConfigFileBase& c,
                                        const std::string& s) const {
  const auto& w = window;
  core::writeKey(c, s, "window_size", w.window_size, "keyframes in the sliding window");
  core::writeKey(c, s, "max_iterations", w.max_iterations, "Ceres iterations per keyframe solve");
  core::writeKey(c, s, "max_solver_time", w.max_solver_time_s,
                 "s; Ceres wall-time limit per keyframe solve");
  core::writeKey(c, s, "solver_threads", w.solver_threads,
                 "Ceres threads; 1 keeps runs repeatable (2: faster, results vary run to run)");
  core::writeKey(c, s, "line_search_steps", w.line_search_steps,
                 "Ceres's projected line search after each step (bounded problems); 0: off, "
                 "each step only projected onto the bounds (a third faster, same APE; Ceres: 20)");
  core::writeKey(c, s, "pixel_sigma", w.pixel_sigma, "px; feature position noise");
  core::writeKey(c, s, "huber_sigmas", w.huber_sigmas, "Huber threshold on whitened residuals");
  core::writeKey(c, s, "depth_sigma_a", w.depth_noise.a, "m; depth noise sigma_d = a + b d^2");
  core::writeKey(c, s, "depth_sigma_b", w.depth_noise.b, "1/m; depth noise sigma_d = a + b d^2");
  core::writeKey(c, s, "transferred_depth", w.transferred_depth,
                 "depth measured in later keyframes constrains them too");
  core::writeKey(c, s, "motion_prior_sigma_translation", w.motion_prior_sigma_translation,
                 "m per keyframe interval; RGB-D-only constant-motion prior");
  core::writeKey(c, s, "motion_prior_sigma_rotation", w.motion_prior_sigma_rotation,
                 "rad per keyframe interval; RGB-D-only constant-motion prior");
  core::writeKey(c, s, "gyro_rotation_sigma", w.gyro_rotation_sigma,
                 "rad/s; until the IMU is initialized, consecutive keyframes keep the gyro's "
                 "rotation within this rate times their interval (not the method; 0: off)");
  core::writeKey(c, s, "object_motion_sigma_translation", w.object_motion_sigma_translation,
                 "m per keyframe interval; r_om, a rigid object's change of motion");
  core::writeKey(c, s, "object_motion_sigma_rotation", w.object_motion_sigma_rotation,
                 "rad per keyframe interval; r_om, a rigid object's change of motion");
  core::writeKey(c, s, "keyframe_parallax_px", keyframes.min_parallax_px,
                 "px; mean feature motion since the last keyframe that makes a keyframe");
  core::writeKey(c, s, "keyframe_max_interval", keyframes.max_interval_s,
                 "s; a keyframe at least this often");
  core::writeKey(c, s, "keyframe_min_shared", keyframes.min_shared,
                 "fewer features shared with the last keyframe make a keyframe");
  core::writeKey(c, s, "min_pnp_inliers", min_pnp_inliers, "PnP inliers needed to track a frame");
  core::writeKey(c, s, "pnp_threshold_px", pnp_threshold_px,
                 "px; PnP RANSAC reprojection threshold");
  core::writeKey(c, s, "pnp_max_correction_m", pnp_max_correction_m,
                 "m; a PnP pose farther than this from the motion prediction is rejected");
  core::writeKey(c, s, "pnp_max_correction_deg", pnp_max_correction_deg,
                 "deg; a PnP pose turned more than this from the motion prediction is rejected");
  core::writeKey(c, s, "pnp_max_imu_correction_m", pnp_max_imu_correction_m,
                 "m; visual-inertial: a PnP pose farther from the IMU prediction is not used "
                 "(0: off)");
  core::writeKey(c, s, "pnp_max_imu_correction_deg", pnp_max_imu_correction_deg,
                 "deg; the same for the rotation (0: off)");
  core::writeKey(c, s, "use_imu", use_imu,
                 "use the IMU when the frames carry gyro + accelerometer samples");
  core::writeKey(c, s, "acc_noise", window.imu_noise.acc_noise,
                 "m/s^2/sqrt(Hz); accelerometer white noise");
  core::writeKey(c, s, "gyro_noise", window.imu_noise.gyro_noise,
                 "rad/s/sqrt(Hz); gyroscope white noise");
  core::writeKey(c, s, "acc_random_walk", window.imu_noise.acc_random_walk,
                 "m/s^3/sqrt(Hz); accelerometer bias random walk");
  core::writeKey(c, s, "gyro_random_walk", window.imu_noise.gyro_random_walk,
                 "rad/s^2/sqrt(Hz); gyroscope bias random walk");
  core::writeKey(c, s, "gravity", imu_init.gravity_magnitude, "m/s^2; local gravity");
  core::writeKey(c, s, "init_min_acceleration_rms", imu_init.min_acceleration_rms,
                 "m/s^2; IMU initialization waits for this much motion (0: still starts accepted)");
  core::writeKey(c, s, "max_speed", max_speed,
                 "m/s; a faster estimate is a failure (window restarted)");
  core::writeKey(c, s, "max_gyro_bias", max_gyro_bias,
                 "rad/s; a larger gyro bias estimate is a failure");
  core::writeKey(c, s, "max_acc_bias", max_acc_bias,
                 "m/s^2; a larger accelerometer bias estimate is a failure");
  core::writeKey(c, s, "min_keyframe_features", min_keyframe_features,
                 "a frame with fewer static features makes no keyframe (its pose is predicted)");
  core::writeKey(
      c, s, "dynamic_handling", std::string(core::wordOf(dynamic_handling, kHandlings)),
      "none: every feature static (VINS-Mono); remove: only Static features off the detected "
      "objects, people and cars masked out moving or not (Dynamic-VINS); full: the paper, Static "
      "features on objects kept (see nonrigid_factors, rigid_factors)");
  core::writeKey(c, s, "drop_moving_landmarks", drop_moving_landmarks,
                 "a feature classified as moving (with remove also a still one on a detected "
                 "object) takes its static landmark, with every observation, out of the window "
                 "(not with none)");
  core::writeKey(c, s, "nonrigid_factors", nonrigid_factors,
                 "with full: NonRigid features as constant-velocity world points (r_D)");
  core::writeKey(c, s, "rigid_factors", rigid_factors,
                 "with full: Rigid features as points of their object, object poses (r_O, r_om)");
  core::writeKey(c, s, "object_factors_wait_for_imu", object_factors_wait_for_imu,
                 "with full and an IMU: the object factors start once the IMU is initialized "
                 "(moving features dropped until then; not in the method)");
  core::writeKey(c, s, "use_gnss", use_gnss,
                 "GNSS position factors on keyframes (ENU from the first fix, aligned to the world "
                 "once the path spans gnss_align_span)");
  core::writeKey(c, s, "gnss_uere_horizontal", gnss.uere_horizontal_m,
                 "m; horizontal sigma of a fix at HDOP 1 (2-5 m plain GPS, ~0.02 m RTK)");
  core::writeKey(c, s, "gnss_vertical_factor", gnss.vertical_factor,
                 "vertical sigma = this x horizontal sigma");
  core::writeKey(c, s, "gnss_align_span", gnss.alignment.min_span_m,
                 "m; horizontal extent of the path before ENU is aligned to the world");
  for (int i = 0; i < 3; ++i)
    core::writeKey(c, s, std::string("gnss_lever_arm_") + "xyz"[i], window.gnss_lever_arm[i],
                   "m; GNSS antenna in the body (IMU) frame");
  core::writeKey(c, s, "gnss_huber_sigmas", window.gnss_huber_sigmas,
                 "Huber threshold on the whitened GNSS residual");
}

}  // namespace dynslam::estimator
