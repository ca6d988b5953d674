#include "dynslam/estimator/EstimatorStage.h"

#include "dynslam/estimator/FramePoseTracker.h"
#include "dynslam/estimator/StateBlocks.h"

#include <dynslam/core/Median.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace dynslam::estimator {

EstimatorStage::EstimatorStage() = default;
EstimatorStage::~EstimatorStage() = default;

void EstimatorStage::configure(const core::IniConfig& cfg, const std::string& section) {
  core::loadOptionsStrict(options_, cfg, section);
  camera_in_imu_.reset();
  if (!options_.camera_in_imu.empty())
    camera_in_imu_ = parseCameraInImu(options_.camera_in_imu, "[" + section + "] camera_in_imu");
  selector_ = KeyframeSelector(options_.keyframes);
}

Eigen::Isometry3d EstimatorStage::configuredExtrinsic(const core::Frame& frame) const {
  return camera_in_imu_ ? *camera_in_imu_ : frame.T_body_imu.inverse() * frame.T_body_camera;
}

void EstimatorStage::startWindow(const core::Frame& frame) {
  const auto& k = frame.intrinsics;
  if (!(k.fx > 0 && k.fy > 0))
    throw std::runtime_error("Estimator: frame " + std::to_string(frame.index) +
                             " has no camera intrinsics");
  SlidingWindowParams params = options_.window;
  params.use_imu = false;  // until the IMU initialization succeeds, which finds the gravity
  params.gravity = Eigen::Vector3d(0, 0, -options_.imu_init.gravity_magnitude);
  auto window = std::make_unique<SlidingWindow>(params, PinholeCamera{k.fx, k.fy, k.cx, k.cy},
                                                configuredExtrinsic(frame));
  // A restart goes on from the calibration estimated so far.
  if (window_) window->continueCalibration(window_->extrinsic(), window_->timeOffset());
  window_ = std::move(window);
  selector_ = KeyframeSelector(options_.keyframes);
}

Eigen::Isometry3d EstimatorStage::predictBody(double t, Eigen::Vector3d* velocity,
                                              bool* fromImu) const {
  if (fromImu) *fromImu = false;
  if (window_ && window_->usesImu() && imu_) {
    if (const auto pre = imu_->peekAt(t)) {
      const Eigen::Isometry3d T = window_->latestPose();
      Eigen::Vector3d p, v;
      Eigen::Quaterniond q;
      pre->predict(T.translation(), Eigen::Quaterniond(T.rotation()), window_->latestVelocity(),
                   window_->latestAccBias(), window_->latestGyroBias(), window_->gravity(), p, q,
                   v);
      Eigen::Isometry3d out = Eigen::Isometry3d::Identity();
      out.linear() = q.toRotationMatrix();
      out.translation() = p;
      if (velocity) *velocity = v;
      if (!last_body_ || plausibleStep(last_body_->inverse() * out)) {
        if (fromImu) *fromImu = true;
        return out;
      }
      // A diverging IMU state: fall through to the visual motion model.
    }
  }
  if (velocity) velocity->setZero();
  if (!last_body_) return Eigen::Isometry3d::Identity();
  if (!previous_body_) return *last_body_;
  // Constant velocity, unless the last step was itself implausible (a failure being recovered
  // from): extrapolating a jump would compound it frame after frame.
  const Eigen::Isometry3d step = previous_body_->inverse() * *last_body_;
  if (!plausibleStep(step)) return *last_body_;
  return *last_body_ * step;
}

bool EstimatorStage::plausibleStep(const Eigen::Isometry3d& step) const {
  return withinStep(step, options_.pnp_max_correction_m, options_.pnp_max_correction_deg);
}

void EstimatorStage::tryImuInitialization(double t) {
  if (!imu_ || window_->usesImu() || int(window_->size()) < options_.window.window_size) return;
  // The alignment trusts the visual poses: not while the window holds keyframes that saw too
  // little (black or featureless frames, whose poses are only predictions).
  for (const std::size_t n : window_->featureCounts())
    if (int(n) < options_.keyframes.min_shared) return;
  std::vector<ImuInitKeyframe> keyframes;
  std::vector<ImuPreintegration*> preintegrations;
  if (!window_->imuInitInput(keyframes, preintegrations)) return;
  ++imu_init_attempts_;
  const ImuInitialization init = initializeImu(keyframes, preintegrations, options_.imu_init);
  if (!init.success) {
    if (init.reason != last_init_failure_)
      MRPT_LOG_INFO_STREAM("IMU initialization at t = " << t - first_t_
                                                        << " s refused: " << init.reason);
    last_init_failure_ = init.reason;
    return;
  }
  window_->switchToImu(init);
  imu_initialized_at_ = t - first_t_;
  MRPT_LOG_INFO_STREAM("IMU initialized at t = " << imu_initialized_at_ << " s: gyro bias "
                                                 << init.gyro_bias.transpose() << " rad/s, "
                                                 << "alignment residual " << init.position_rms
                                                 << " m");
}

void EstimatorStage::process(core::Frame& frame) {
  if (frames_++ == 0) first_t_ = frame.t;
  takeSensorData(frame);
  RoutedFeatures routed = routeFrameFeatures(frame);
  const Eigen::Isometry3d T_ic = window_ ? window_->extrinsic() : configuredExtrinsic(frame);
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();
  Eigen::Isometry3d T_wb = trackBody(frame, routed.pixels, T_ic, velocity);
  KeyframeOutcome keyframe;
  int shared = 0;
  const KeyframeSelector::Reason reason = keyframeReason(frame.t, routed, &shared);
  if (reason != KeyframeSelector::Reason::NotKeyframe)
    keyframe = makeKeyframe(frame, routed, {reason, shared, T_ic, velocity}, T_wb);
  anchorToGnss(frame.t);
  writePose(frame, T_wb, T_ic, keyframe);
}

void EstimatorStage::takeSensorData(const core::Frame& frame) {
  if (options_.use_imu && !imu_) {
    for (const auto& s : frame.imu)
      if (s.has_gyro && s.has_acc)
        imu_ = std::make_unique<KeyframeImu>(options_.window.imu_noise, KeyframeImu::kMaxGapS,
                                             options_.imu_max_preintegration_s);
  }
  if (imu_) imu_->addSamples(frame.imu, frame.index);
  if (options_.use_gnss && !gnss_ && !frame.gnss.empty())
    gnss_ = std::make_unique<GnssAnchor>(options_.gnss);
  if (gnss_) gnss_->addFixes(frame.gnss);
}

RoutedFeatures EstimatorStage::routeFrameFeatures(const core::Frame& frame) {
  const bool objectFactors =
      !(options_.object_factors_wait_for_imu && imu_ && !(window_ && window_->usesImu()));
  RoutedFeatures routed = routeFeatures(
      frame.features, options_.dynamic_handling, objectFactors && options_.nonrigid_factors,
      objectFactors && options_.rigid_factors,
      window_ ? window_->timeOffset() : options_.window.calibration.time_offset_s);
  if (window_ && options_.drop_moving_landmarks)
    landmarks_dropped_ += window_->dropLandmarks(routed.not_landmarks);
  return routed;
}

Eigen::Isometry3d EstimatorStage::trackBody(const core::Frame& frame,
                                            const std::map<std::int64_t, Eigen::Vector2d>& pixels,
                                            const Eigen::Isometry3d& T_ic,
                                            Eigen::Vector3d& velocity) {
  bool predictedByImu = false;
  const Eigen::Isometry3d predicted = predictBody(frame.t, &velocity, &predictedByImu);
  Eigen::Isometry3d T_wb = predicted;
  if (!window_) {
    startWindow(frame);
  } else {
    const PinholeCamera camera{frame.intrinsics.fx, frame.intrinsics.fy, frame.intrinsics.cx,
                               frame.intrinsics.cy};
    FramePoseTrackerParams pnp{options_.min_pnp_inliers, options_.pnp_threshold_px};
    const auto tracked =
        trackFramePose(camera, window_->landmarkPositions(), pixels, predicted * T_ic, pnp);
    // Near the motion prediction, or near the last pose: the constant-velocity prediction
    // extrapolates one bad step frame after frame, and refusing every PnP pose as too far from
    // it restarted the window over and over, while the PnP pose against the window's own map
    // stays right (docs/notes/estimator.md, 2026-11-28 (PnP pose near the last pose)). With an
    // IMU prediction and pnp_max_imu_correction_* set, near it.
    const std::optional<Eigen::Isometry3d> trackedBody =
        tracked ? std::optional(tracked->T_world_camera * T_ic.inverse()) : std::nullopt;
    const PnpPoseGate gate{options_.pnp_max_correction_m, options_.pnp_max_correction_deg,
                           options_.pnp_max_imu_correction_m, options_.pnp_max_imu_correction_deg};
    if (trackedBody && acceptPnpPose(*trackedBody, predicted, predictedByImu, last_body_, gate))
      T_wb = *trackedBody;
    else
      ++pnp_failures_;
  }
  if (!T_wb.matrix().allFinite()) T_wb = last_body_ ? *last_body_ : Eigen::Isometry3d::Identity();
  return T_wb;
}

KeyframeSelector::Reason EstimatorStage::keyframeReason(double t, const RoutedFeatures& routed,
                                                        int* shared) {
  // A frame that sees almost nothing (black, blurred, a wall) makes no keyframe: its pose is
  // the prediction, and the window waits for frames it can constrain.
  const bool seesEnough =
      window_->empty() || int(routed.landmarks.size()) >= options_.min_keyframe_features;
  if (!seesEnough) {
    ++blind_frames_;
    return KeyframeSelector::Reason::NotKeyframe;
  }
  return selector_.decide(t, routed.pixels, shared);
}

EstimatorStage::KeyframeOutcome EstimatorStage::makeKeyframe(core::Frame& frame,
                                                             RoutedFeatures& routed,
                                                             const KeyframeContext& context,
                                                             Eigen::Isometry3d& T_wb) {
  core::KeyframeRecord record;
  record.reason = KeyframeSelector::name(context.reason);
  record.static_features = int(routed.landmarks.size());
  record.shared_features = context.shared;
  record.nonrigid_features = int(routed.nonrigid.size());
  nonrigid_observations_ += routed.nonrigid.size();
  KeyframeInput in = keyframeInput(frame, routed, T_wb, context);
  SolveReport report = window_->addKeyframe(in);
  record.solve_ms = report.solve_ms;
  record.iterations = report.iterations;
  record.rigid_objects = report.rigid_objects;
  ++keyframes_;
  solve_ms_.add(report.solve_ms);
  rigid_objects_solved_ += std::size_t(report.rigid_objects);
  detectFailure(report, T_wb);
  // Whatever failed, the pose to go on from is one that was plausible: the tracked pose when
  // it was, else the last frame's.
  if (!report.usable && last_body_ && !plausibleStep(last_body_->inverse() * T_wb))
    T_wb = *last_body_;
  if (gnss_) gnss_->keyframeAdded(frame.t);
  KeyframeOutcome outcome;
  if (report.usable) {
    T_wb = window_->latestPose();
    outcome.objects = window_->latestObjectPoses();
    selector_.accept(frame.t, routed.pixels);
    tryImuInitialization(frame.t);
    if (window_->usesImu()) T_wb = window_->latestPose();
  } else {
    MRPT_LOG_WARN_STREAM("frame " << frame.index << ": solve failed (" << report.message
                                  << "), window restarted");
    restartWindow(frame, in, T_wb, routed.pixels);
    outcome.restarted = true;
  }
  record.restarted = outcome.restarted;
  record.visual_inertial = window_->usesImu();
  if (record.visual_inertial) {
    record.velocity = window_->latestVelocity();
    record.acc_bias = window_->latestAccBias();
    record.gyro_bias = window_->latestGyroBias();
  }
  record.time_offset = window_->timeOffset();
  record.extrinsic_rotation_change = logSO3(extrinsicChange(window_->extrinsic()).rotation());
  record.extrinsic_translation_change =
      window_->extrinsic().translation() - window_->extrinsicPrior().translation();
  record.time_offset_free = window_->timeOffsetFree();
  record.extrinsic_free = window_->extrinsicFree();
  free_keyframes_[0] += record.time_offset_free;
  free_keyframes_[1] += record.extrinsic_free;
  frame.keyframe = record;
  return outcome;
}

KeyframeInput EstimatorStage::keyframeInput(const core::Frame& frame, RoutedFeatures& routed,
                                            const Eigen::Isometry3d& T_wb,
                                            const KeyframeContext& context) {
  KeyframeInput in;
  in.t = frame.t;
  in.T_world_body = T_wb;
  in.velocity = context.velocity;
  in.features = std::move(routed.landmarks);
  in.nonrigid_features = std::move(routed.nonrigid);
  // An object new to the window starts in the frame its trajectory has followed so far.
  const auto followed = objects_.predict(frame, T_wb * context.T_ic);
  for (auto& object : routed.rigid_objects)
    if (const auto f = followed.find(object.object_id); f != followed.end())
      object.first_pose_guess = f->second;
  in.rigid_objects = std::move(routed.rigid_objects);
  const Eigen::Vector3d ba = window_->empty() ? Eigen::Vector3d::Zero() : window_->latestAccBias();
  const Eigen::Vector3d bg = window_->empty() ? Eigen::Vector3d::Zero() : window_->latestGyroBias();
  for (auto s = frame.imu.rbegin(); s != frame.imu.rend(); ++s)
    if (s->has_gyro) {
      in.angular_velocity = s->gyro - bg;
      break;
    }
  if (imu_) in.preintegration = imu_->cutAt(frame.t, ba, bg);
  return in;
}

void EstimatorStage::detectFailure(SolveReport& report, const Eigen::Isometry3d& tracked) const {
  // A solve that fails, or moves the new keyframe implausibly far from its tracked pose, or
  // leaves non-finite states or implausible IMU states, restarts the window.
  if (!report.usable) return;
  const Eigen::Isometry3d solved = window_->latestPose();
  const bool finite = solved.matrix().allFinite() && window_->latestVelocity().allFinite();
  const bool jump = !finite || !plausibleStep(tracked.inverse() * solved);
  const bool implausibleImu =
      window_->usesImu() && (window_->latestVelocity().norm() > options_.max_speed ||
                             window_->latestGyroBias().norm() > options_.max_gyro_bias ||
                             window_->latestAccBias().norm() > options_.max_acc_bias);
  if (jump || implausibleImu) {
    report.usable = false;
    report.message = jump ? "the keyframe moved implausibly far from its tracked pose"
                          : "implausible velocity or IMU bias";
  }
}

void EstimatorStage::restartWindow(const core::Frame& frame, KeyframeInput& in,
                                   const Eigen::Isometry3d& T_wb,
                                   const std::map<std::int64_t, Eigen::Vector2d>& pixels) {
  // Solver divergence: start again from the last good pose, the trajectory stays continuous
  // (the new window is RGB-D only until the IMU initializes again).
  ++resets_;
  startWindow(frame);
  in.T_world_body = T_wb;
  in.preintegration = nullptr;
  window_->addKeyframe(in);
  selector_.accept(frame.t, pixels);
}

void EstimatorStage::writePose(core::Frame& frame, Eigen::Isometry3d T_wb,
                               const Eigen::Isometry3d& T_ic, const KeyframeOutcome& keyframe) {
  // A slightly scaled rotation compounds through the motion prediction (to inf within frames).
  T_wb = nearestRigid(T_wb);
  // After a restart the motion model starts from rest: the velocity of the steps that led to
  // the failure is not to be extrapolated into the new window.
  previous_body_ = keyframe.restarted ? T_wb : last_body_;
  last_body_ = T_wb;
  frame.T_world_camera = T_wb * T_ic;
  objects_.update(frame, keyframe.objects);
}

void EstimatorStage::anchorToGnss(double t) {
  if (!gnss_ || !window_) return;
  std::optional<Eigen::Vector3d> gravity;
  if (window_->usesImu()) gravity = window_->gravity();
  const bool wasAligned = gnss_->aligned();
  for (const GnssTarget& target :
       gnss_->resolve([&](double kt) { return window_->antennaAt(kt); }, gravity))
    gnss_factors_ += window_->addGnssTarget(target);
  if (!wasAligned && gnss_->aligned()) {
    gnss_aligned_at_ = t - first_t_;
    MRPT_LOG_INFO_STREAM("GNSS aligned to the world at t = "
                         << gnss_aligned_at_ << " s from " << gnss_->alignment().pairs()
                         << " keyframes (" << (gravity ? "4 DoF about gravity" : "SE(3)")
                         << ", RMS " << gnss_->alignment().rmsResidual() << " m)");
  }
}

void EstimatorStage::finish() {
  if (window_) {
    final_calibration_ = window_->calibration(true);
    MRPT_LOG_INFO_STREAM(
        "calibration: time offset "
        << 1e3 * final_calibration_.time_offset_s << " ms (sigma "
        << 1e3 * final_calibration_.time_offset_sigma_s << " ms), extrinsic rotation change "
        << logSO3(extrinsicChange(final_calibration_.T_body_camera).rotation()).norm() * 180 / M_PI
        << " deg");
  }
  MRPT_LOG_INFO_STREAM(
      frames_ << " frames, " << keyframes_ << " keyframes, solve median "
              << core::upperMedian(solve_ms_.samples()) << " ms, " << pnp_failures_
              << " frames without a PnP pose, " << resets_ << " restarts; IMU "
              << (imu_initialized_at_ >= 0
                      ? "initialized at " + std::to_string(imu_initialized_at_) + " s"
                      : std::string(imu_ ? "never initialized" : "not used")));
}

std::vector<std::pair<std::string, double>> EstimatorStage::statistics() const {
  std::vector<std::pair<std::string, double>> out = {
      {"keyframes", double(keyframes_)},
      {"solve_ms_median", core::upperMedian(solve_ms_.samples())},
      {"solve_ms_max", solve_ms_.max()},
      {"pnp_failures", double(pnp_failures_)},
      {"resets", double(resets_)},
      {"imu_initialized_at", imu_initialized_at_},
      {"imu_init_attempts", double(imu_init_attempts_)},
      {"nonrigid_per_keyframe", keyframes_ ? double(nonrigid_observations_) / keyframes_ : 0.0},
      {"rigid_objects_per_keyframe", keyframes_ ? double(rigid_objects_solved_) / keyframes_ : 0.0},
      {"imu_gaps", imu_ ? double(imu_->gaps()) : 0.0},
      {"imu_overlong", imu_ ? double(imu_->overlong()) : 0.0},
      {"blind_frames", double(blind_frames_)},
      {"landmarks_dropped_moving", double(landmarks_dropped_)},
      {"gnss_aligned_at", gnss_aligned_at_},
      {"gnss_alignment_rms", gnss_ && gnss_->aligned() ? gnss_->alignment().rmsResidual() : 0.0},
      {"gnss_factors", double(gnss_factors_)}};
  appendCalibration(out);
  return out;
}

Eigen::Isometry3d EstimatorStage::extrinsicChange(const Eigen::Isometry3d& T_body_camera) const {
  return window_ ? window_->extrinsicPrior().inverse() * T_body_camera : T_body_camera;
}

void EstimatorStage::appendCalibration(std::vector<std::pair<std::string, double>>& out) const {
  const CalibrationEstimate& c = final_calibration_;
  const auto sigmaOr = [](double sigma) { return std::isfinite(sigma) ? sigma : -1.0; };
  const Eigen::Isometry3d T = window_ ? c.T_body_camera : Eigen::Isometry3d::Identity();
  const Eigen::Isometry3d change = extrinsicChange(T);
  // Roll, pitch, yaw (deg) of R = Rz(yaw) Ry(pitch) Rx(roll), the camera's axes in the IMU's.
  const Eigen::Vector3d ypr = T.rotation().eulerAngles(2, 1, 0) * 180 / M_PI;
  constexpr double kDeg = 180 / M_PI;
  out.insert(
      out.end(),
      {{"time_offset_s", window_ ? c.time_offset_s : options_.window.calibration.time_offset_s},
       {"time_offset_sigma_s", sigmaOr(c.time_offset_sigma_s)},
       {"extrinsic_x", T.translation().x()},
       {"extrinsic_y", T.translation().y()},
       {"extrinsic_z", T.translation().z()},
       {"extrinsic_roll_deg", ypr(2)},
       {"extrinsic_pitch_deg", ypr(1)},
       {"extrinsic_yaw_deg", ypr(0)},
       {"extrinsic_rotation_change_deg", logSO3(change.rotation()).norm() * kDeg},
       {"extrinsic_translation_change_m", change.translation().norm()},
       {"extrinsic_sigma_rotation_deg", sigmaOr(c.extrinsic_sigma.tail<3>().maxCoeff() * kDeg)},
       {"extrinsic_sigma_translation_m", sigmaOr(c.extrinsic_sigma.head<3>().maxCoeff())},
       {"time_offset_free_keyframes", double(free_keyframes_[0])},
       {"extrinsic_free_keyframes", double(free_keyframes_[1])}});
}

}  // namespace dynslam::estimator
