// SlidingWindow's states: keyframes entering with their landmarks, non-rigid points and object
// poses, the switch to visual-inertial, and what the stage reads back. The optimisation (factors,
// solve, marginalisation) is SlidingWindowProblem.cpp.
#include "dynslam/estimator/SlidingWindow.h"

#include "dynslam/estimator/StateBlocks.h"

#include <stdexcept>

namespace dynslam::estimator {

SlidingWindow::SlidingWindow(const SlidingWindowParams& params, const PinholeCamera& camera,
                             const Eigen::Isometry3d& T_body_camera)
    : params_(params), camera_(camera), extrinsic_prior_(T_body_camera) {
  if (params_.window_size < 2)
    throw std::invalid_argument("SlidingWindow: window_size must be >= 2");
  poseToBlock(T_body_camera, extrinsic_);
  time_offset_[0] = params_.calibration.time_offset_s;
  Eigen::Map<Eigen::Vector3d>{gravity_} = params_.gravity;
}

Eigen::Isometry3d SlidingWindow::extrinsic() const { return poseFromBlock(extrinsic_); }

void SlidingWindow::continueCalibration(const Eigen::Isometry3d& T_body_camera,
                                        double time_offset_s) {
  poseToBlock(T_body_camera, extrinsic_);
  time_offset_[0] = time_offset_s;
}

// Right after the IMU initialization the velocities and biases are still settling, and a free
// time offset took up their error (-16 ms for a true +10 ms on SyntheticFrames). Held instead
// (by a prior at the current value, see calibrationSettling), the marginalisation prior was
// conditioned on it and locked it there. So the states are free from the initialization on, but
// for the first window of keyframes their priors are tight.
bool SlidingWindow::calibrationSettling() const { return imu_keyframes_ <= params_.window_size; }

bool SlidingWindow::estimatesTimeOffset() const {
  return params_.use_imu && params_.calibration.estimate_time_offset;
}

bool SlidingWindow::estimatesExtrinsic() const {
  return params_.use_imu && params_.calibration.estimate_extrinsic != ExtrinsicEstimation::None;
}

bool SlidingWindow::timeOffsetFree() const {
  return estimatesTimeOffset() && excitation_.observesTimeOffset(params_.calibration.excitation);
}

bool SlidingWindow::extrinsicFree() const {
  return estimatesExtrinsic() && excitation_.observesExtrinsic(params_.calibration.excitation);
}

void SlidingWindow::updateExcitation() {
  if (!(estimatesTimeOffset() || estimatesExtrinsic())) return;  // nothing it would free
  std::vector<KeyframeMotion> motion;
  for (const Keyframe& k : keyframes_) {
    KeyframeMotion m;
    m.q_world_body = Eigen::Quaterniond(poseFromBlock(k.pose).rotation());
    m.velocity_world = Eigen::Vector3d(k.speed_bias);
    m.angular_velocity_body = k.angular_velocity;
    motion.push_back(m);
  }
  excitation_ = measureExcitation(motion);
}

SlidingWindow::~SlidingWindow() = default;

SlidingWindow::Keyframe* SlidingWindow::keyframe(std::int64_t id) {
  if (keyframes_.empty() || id < keyframes_.front().id || id > keyframes_.back().id) return nullptr;
  return &keyframes_[size_t(id - keyframes_.front().id)];
}

const SlidingWindow::Keyframe* SlidingWindow::keyframe(std::int64_t id) const {
  return const_cast<SlidingWindow*>(this)->keyframe(id);
}

double SlidingWindow::depthIn(const Keyframe& k, const Eigen::Vector3d& world) const {
  return ((poseFromBlock(k.pose) * poseFromBlock(extrinsic_)).inverse() * world).z();
}

double SlidingWindow::depthAtStateTime(const Keyframe& k, const Eigen::Vector2d& pixel,
                                       double depth) const {
  if (time_offset_[0] == 0 || !(depth > 0)) return depth;
  const Eigen::Isometry3d T_bc = extrinsic();
  const Eigen::Matrix3d R_wb = poseFromBlock(k.pose).rotation();
  const Eigen::Vector3d p_b = T_bc * (camera_.bearing(pixel) * depth);
  // A static point seen from a moving body: d p_b / dt = -w x p_b - v_b.
  const Eigen::Vector3d v_b = R_wb.transpose() * Eigen::Vector3d(k.speed_bias);
  const Eigen::Vector3d rate_c =
      T_bc.rotation().transpose() * (-k.angular_velocity.cross(p_b) - v_b);
  return depth - time_offset_[0] * rate_c.z();
}

Eigen::Vector3d SlidingWindow::landmarkWorld(const Landmark& l) const {
  const Keyframe* anchor = keyframe(l.anchor);
  const LandmarkObservation& a = l.anchorObservation();
  const Eigen::Vector3d inCamera =
      camera_.bearing(atStateTime(a.pixel, a.velocity)) / std::max(l.inverse_depth, 1e-6);
  return poseFromBlock(anchor->pose) * (poseFromBlock(extrinsic_) * inCamera);
}

void SlidingWindow::observeNonRigid(const KeyframeInput& input, const Keyframe& k) {
  // Moving points' own factors take the pixel at the state time by the offset of now.
  for (const auto& feature : input.nonrigid_features) {
    FeatureObservation f = feature;
    f.pixel = atStateTime(f.pixel, f.velocity);
    auto it = nonrigid_.find(f.id);
    if (it == nonrigid_.end()) {
      if (!(f.depth > 0)) continue;  // a new point needs its depth to be placed
      NonRigidPoint p;
      p.t0 = k.t;
      const Eigen::Vector3d world =
          input.T_world_body * (poseFromBlock(extrinsic_) * (camera_.bearing(f.pixel) * f.depth));
      for (int i = 0; i < 3; ++i) {
        p.position[i] = world(i);
        p.velocity[i] = 0;
      }
      it = nonrigid_.emplace(f.id, p).first;
    }
    it->second.observations[k.id] = {f.pixel, f.depth};
  }
}

SolveReport SlidingWindow::addKeyframe(const KeyframeInput& input) {
  if (!keyframes_.empty() && !(input.t > keyframes_.back().t))
    throw std::invalid_argument("SlidingWindow: keyframe times must increase");
  if (!input.T_world_body.matrix().allFinite() || !input.velocity.allFinite())
    throw std::invalid_argument(
        "SlidingWindow: the keyframe's initial pose or velocity is not finite");
  Keyframe k;
  k.id = next_id_++;
  k.t = input.t;
  k.features = input.features.size();
  poseToBlock(input.T_world_body, k.pose);
  // A visual-inertial keyframe without a preintegration (the IMU stream had a gap): no IMU
  // factor ties its velocity to the previous keyframe's, and the iteration-capped solves move a
  // wrong start slowly (docs/notes/estimator.md, 2026-11-28 (IMU gap)). Its mean velocity since
  // the previous keyframe is the start.
  Eigen::Vector3d velocity = input.velocity;
  if (params_.use_imu && !input.preintegration && !keyframes_.empty()) {
    const Keyframe& previous = keyframes_.back();
    velocity = (input.T_world_body.translation() - poseFromBlock(previous.pose).translation()) /
               (input.t - previous.t);
  }
  for (int i = 0; i < 3; ++i) k.speed_bias[i] = velocity(i);
  for (int i = 3; i < 9; ++i)
    k.speed_bias[i] = keyframes_.empty() ? 0.0 : keyframes_.back().speed_bias[i];
  k.preintegration = keyframes_.empty() ? nullptr : input.preintegration;
  k.angular_velocity = input.angular_velocity;
  if (params_.use_imu) ++imu_keyframes_;
  keyframes_.push_back(k);
  for (const auto& f : input.features)
    landmarks_.observe(f.id, k.id, {f.pixel, f.depth, f.velocity}, 3.0);
  observeNonRigid(input, k);
  const Eigen::Isometry3d T_world_camera = input.T_world_body * poseFromBlock(extrinsic_);
  for (const auto& object : input.rigid_objects) {
    std::vector<RigidObjectFeature> features;
    for (const auto& f : object.features)
      features.push_back({f.id, atStateTime(f.pixel, f.velocity), f.depth});
    objects_.observe(object.object_id, k.id, features, T_world_camera, camera_,
                     object.first_pose_guess);
  }
  // Each object's frame at the centroid of the points seen now (SlidingWindow.h).
  objects_.recentre(k.id);
  SolveReport report = solve();
  if (int(keyframes_.size()) > params_.window_size) marginalizeOldest();
  return report;
}

bool SlidingWindow::imuInitInput(std::vector<ImuInitKeyframe>& keyframes,
                                 std::vector<ImuPreintegration*>& preintegrations) const {
  keyframes.clear();
  preintegrations.clear();
  for (size_t k = 0; k < keyframes_.size(); ++k) {
    keyframes.push_back({keyframes_[k].t, poseFromBlock(keyframes_[k].pose)});
    if (k == 0) continue;
    if (!keyframes_[k].preintegration) return false;
    preintegrations.push_back(keyframes_[k].preintegration.get());
  }
  return true;
}

void SlidingWindow::switchToImu(const ImuInitialization& init) {
  if (init.velocities_world.size() != keyframes_.size())
    throw std::invalid_argument("SlidingWindow::switchToImu: one velocity per keyframe needed");
  for (size_t k = 0; k < keyframes_.size(); ++k) {
    Keyframe& kf = keyframes_[k];
    for (int i = 0; i < 3; ++i) {
      kf.speed_bias[i] = init.velocities_world[k](i);
      kf.speed_bias[3 + i] = 0.0;
      kf.speed_bias[6 + i] = init.gyro_bias(i);
    }
  }
  Eigen::Map<Eigen::Vector3d>{gravity_} = init.gravity_world;
  camera_anchor_.reset();  // the next solve anchors the gauge again
  prior_ = {};
  params_.use_imu = true;
}

double SlidingWindow::latestTime() const { return keyframes_.back().t; }
std::vector<std::size_t> SlidingWindow::featureCounts() const {
  std::vector<std::size_t> counts;
  for (const Keyframe& k : keyframes_) counts.push_back(k.features);
  return counts;
}
Eigen::Isometry3d SlidingWindow::latestPose() const {
  return poseFromBlock(keyframes_.back().pose);
}
Eigen::Vector3d SlidingWindow::latestVelocity() const {
  return Eigen::Vector3d(keyframes_.back().speed_bias);
}
Eigen::Vector3d SlidingWindow::latestAccBias() const {
  return Eigen::Vector3d(keyframes_.back().speed_bias + 3);
}
Eigen::Vector3d SlidingWindow::latestGyroBias() const {
  return Eigen::Vector3d(keyframes_.back().speed_bias + 6);
}

std::optional<Eigen::Vector3d> SlidingWindow::nonRigidVelocity(std::int64_t id) const {
  const auto it = nonrigid_.find(id);
  if (it == nonrigid_.end() || it->second.observations.size() < 2) return std::nullopt;
  return Eigen::Vector3d(it->second.velocity);
}

std::vector<std::pair<int, Eigen::Isometry3d>> SlidingWindow::latestObjectPoses() const {
  std::vector<std::pair<int, Eigen::Isometry3d>> out;
  if (keyframes_.empty()) return out;
  for (const auto& [id, o] : objects_.all()) {
    const auto L = o.poses.find(keyframes_.back().id);
    if (L != o.poses.end()) out.emplace_back(id, poseFromBlock(L->second.data()));
  }
  return out;
}

std::size_t SlidingWindow::dropLandmarks(const std::vector<std::int64_t>& ids) {
  std::size_t dropped = 0;
  for (const std::int64_t id : ids) dropped += landmarks_.erase(id);
  return dropped;
}

std::vector<std::pair<std::int64_t, Eigen::Vector3d>> SlidingWindow::landmarkPositions() const {
  std::vector<std::pair<std::int64_t, Eigen::Vector3d>> out;
  for (const auto& [id, l] : landmarks_.all())
    if (l.observations.size() >= 2 && keyframe(l.anchor)) out.emplace_back(id, landmarkWorld(l));
  return out;
}

SlidingWindow::Keyframe* SlidingWindow::keyframeAt(double t) {
  for (Keyframe& k : keyframes_)
    if (std::abs(k.t - t) < 1e-9) return &k;
  return nullptr;
}

std::optional<Eigen::Vector3d> SlidingWindow::antennaAt(double t) const {
  const Keyframe* k = const_cast<SlidingWindow*>(this)->keyframeAt(t);
  if (!k) return std::nullopt;
  return poseFromBlock(k->pose) * params_.gnss_lever_arm;
}

bool SlidingWindow::addGnssTarget(const GnssTarget& target) {
  Keyframe* k = keyframeAt(target.t);
  if (k) k->gnss = target;
  return k != nullptr;
}

}  // namespace dynslam::estimator
