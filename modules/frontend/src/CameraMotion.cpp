#include "dynslam/frontend/CameraMotion.h"

#include <dynslam/core/Median.h>
#include <algorithm>

namespace dynslam::frontend {
std::optional<Eigen::Matrix3d> gyroCameraRotation(const std::vector<core::ImuSample>& imu,
                                                  double t_prev, double t_cur,
                                                  const Eigen::Isometry3d& T_body_imu,
                                                  const Eigen::Isometry3d& T_body_camera) {
  // R_{I(prev) <- I(cur)}: the IMU's orientation at this frame in its orientation at the last.
  Eigen::Matrix3d R_prev_cur = Eigen::Matrix3d::Identity();
  double t = t_prev;
  bool any = false;
  for (const auto& s : imu) {
    if (s.t <= t_prev || s.t > t_cur) continue;
    const double dt = s.t - t;
    t = s.t;
    if (!s.has_gyro) continue;
    any = true;
    const double angle = s.gyro.norm() * dt;
    if (angle > 0) R_prev_cur = R_prev_cur * Eigen::AngleAxisd(angle, s.gyro.normalized());
  }
  if (!any) return std::nullopt;
  const Eigen::Matrix3d R_CI = T_body_camera.linear().transpose() * T_body_imu.linear();
  const Eigen::Matrix3d R_cam_prev_cur = R_CI * R_prev_cur * R_CI.transpose();
  // A static point: p = R_{C(prev)<-C(cur)} q, so q = R^T p.
  return R_cam_prev_cur.transpose();
}

CameraMotionEstimator::CameraMotionEstimator(CameraMotionParams params, std::uint32_t seed)
    : params_(params), rng_(seed) {}

std::optional<RegistrationResult> CameraMotionEstimator::translationWithRotation(
    const std::vector<Eigen::Vector3d>& p, const std::vector<Eigen::Vector3d>& q,
    const Eigen::Matrix3d& R) {
  if (p.empty()) return std::nullopt;
  std::vector<Eigen::Vector3d> d(p.size());  // each pair's own translation
  std::vector<double> gate2(p.size());        // squared inlier gate of each pair
  for (size_t i = 0; i < p.size(); ++i) {
    d[i] = q[i] - R * p[i];
    // 3 sigma of the difference of two depth readings (sigma = depth_sigma_z2 z^2), at least
    // 1 cm: a point 5 m away is as noisy as a walker's motion, and must not outvote near ones.
    const double sp = params_.depth_sigma_z2 * p[i].z() * p[i].z();
    const double sq = params_.depth_sigma_z2 * q[i].z() * q[i].z();
    const double gate = std::max(0.01, 3 * std::sqrt(sp * sp + sq * sq));
    gate2[i] = gate * gate;
  }
  auto inliersOfT = [&](const Eigen::Vector3d& t) {
    std::vector<int> in;
    for (size_t i = 0; i < d.size(); ++i)
      if ((d[i] - t).squaredNorm() < gate2[i]) in.push_back(int(i));
    return in;
  };
  // The precise translation weighs each inlier by the inverse variance of its pair; the
  // hypotheses are ranked by their inlier COUNT: a few near points on an undetected mover must
  // not outvote the many far ones of the static background.
  auto weightedMean = [&](const std::vector<int>& in) {
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    double w = 0;
    for (int i : in) {
      sum += d[size_t(i)] / gate2[size_t(i)];
      w += 1.0 / gate2[size_t(i)];
    }
    return Eigen::Vector3d(sum / w);
  };
  auto support = [](const std::vector<int>& in) { return in.size(); };
  std::vector<int> best = inliersOfT(previous_.t);
  if (auto in = inliersOfT(core::componentwiseUpperMedian(d)); support(in) > support(best))
    best = std::move(in);
  std::uniform_int_distribution<size_t> pick(0, d.size() - 1);
  for (int it = 0; it < params_.ransac.iterations; ++it)  // one pair fixes a translation
    if (auto in = inliersOfT(d[pick(rng_)]); support(in) > support(best)) best = std::move(in);
  if (best.empty()) return std::nullopt;
  RegistrationResult r;
  r.motion = {R, weightedMean(best)};
  r.inliers = inliersOfT(r.motion.t);
  if (r.inliers.empty()) r.inliers = best;
  r.motion.t = weightedMean(r.inliers);
  double sw = 0, swr = 0;
  for (int i : r.inliers) {
    sw += 1.0 / gate2[size_t(i)];
    swr += (d[size_t(i)] - r.motion.t).squaredNorm() / gate2[size_t(i)];
  }
  lastSigma_ = std::sqrt(swr / sw / double(r.inliers.size()));
  return r;
}

CameraMotionEstimate CameraMotionEstimator::estimate(
    const std::vector<Eigen::Vector3d>& p, const std::vector<Eigen::Vector3d>& q,
    const std::optional<Eigen::Matrix3d>& gyro_rotation,
    const std::optional<Eigen::Isometry3d>& T_world_prev,
    const std::optional<Eigen::Isometry3d>& T_world_cur) {
  CameraMotionEstimate e;
  if (T_world_prev && T_world_cur) {
    e.motion = RigidMotion::from(T_world_cur->inverse() * *T_world_prev);
    e.source = CameraMotionSource::Poses;
    previous_ = e.motion;
    return e;
  }
  std::optional<RegistrationResult> r;
  if (gyro_rotation) {
    r = translationWithRotation(p, q, *gyro_rotation);
    if (r) e.source = CameraMotionSource::ImuRotationRegistration;
  }
  // Without a gyro, or when the gyro's rotation leaves most pairs unexplained (extrinsics that
  // do not hold, a saturated gyro): the full 6-DoF registration, which keeps the better one.
  if (!r || 2 * r->inliers.size() < p.size()) {
    std::vector<RigidMotion> extra{previous_};
    if (r) extra.push_back(r->motion);
    auto full = registerRansac(p, q, params_.ransac, rng_, {}, extra);
    if (full && (!r || full->inliers.size() > r->inliers.size())) {
      r = std::move(full);
      e.source = CameraMotionSource::Registration;
    }
  }
  if (r && int(r->inliers.size()) >= params_.min_inliers) {
    e.motion = r->motion;
    recent_.push_back(r->motion.t);
    if (recent_.size() > kRecentTranslations) recent_.pop_front();
    e.inliers = int(r->inliers.size());
    if (e.source == CameraMotionSource::Registration) {
      double sum = 0;
      for (int i : r->inliers) sum += (r->motion.apply(p[size_t(i)]) - q[size_t(i)]).squaredNorm();
      lastSigma_ = std::sqrt(sum / double(r->inliers.size())) / std::sqrt(double(r->inliers.size()));
    }
    e.translation_sigma = lastSigma_;
  } else if (gyro_rotation) {
    e.motion = {*gyro_rotation,
                recent_.empty() ? previous_.t : core::componentwiseUpperMedian(recent_)};
    e.source = CameraMotionSource::ImuRotationConstantVelocity;
  } else {
    e.motion = previous_;
    e.source = CameraMotionSource::ConstantVelocity;
  }
  previous_ = e.motion;
  return e;
}

}  // namespace dynslam::frontend
