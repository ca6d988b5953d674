#include "dynslam/frontend/CameraMotion.h"

#include <algorithm>

namespace dynslam::frontend {
namespace {

double median(std::vector<double> v) {
  const auto mid = v.begin() + std::ptrdiff_t(v.size() / 2);
  std::nth_element(v.begin(), mid, v.end());
  return *mid;
}

}  // namespace

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

CameraMotionEstimate CameraMotionEstimator::estimate(
    const std::vector<Eigen::Vector3d>& p, const std::vector<Eigen::Vector3d>& q,
    const std::optional<Eigen::Matrix3d>& gyro_rotation,
    const std::optional<Eigen::Isometry3d>& T_world_prev,
    const std::optional<Eigen::Isometry3d>& T_world_cur) {
  CameraMotionEstimate e;
  if (T_world_prev && T_world_cur) {
    e.motion = RigidMotion::from(T_world_cur->inverse() * *T_world_prev);
    e.source = CameraMotionSource::Poses;
  } else {
    std::vector<RigidMotion> extra{previous_};
    if (gyro_rotation && !p.empty()) {
      // The IMU rotation with the translation that most background pairs agree on.
      Eigen::Vector3d t;
      for (int axis = 0; axis < 3; ++axis) {
        std::vector<double> d(p.size());
        for (size_t i = 0; i < p.size(); ++i) d[i] = (q[i] - *gyro_rotation * p[i])(axis);
        t(axis) = median(std::move(d));
      }
      extra.push_back({*gyro_rotation, t});
    }
    const auto r = registerRansac(p, q, params_.ransac, rng_, {}, extra);
    if (r && int(r->inliers.size()) >= params_.min_inliers) {
      e.motion = r->motion;
      e.source = CameraMotionSource::Registration;
      e.inliers = int(r->inliers.size());
    } else if (gyro_rotation) {
      e.motion = {*gyro_rotation, previous_.t};
      e.source = CameraMotionSource::ImuRotationConstantVelocity;
    } else {
      e.motion = previous_;
      e.source = CameraMotionSource::ConstantVelocity;
    }
  }
  previous_ = e.motion;
  return e;
}

}  // namespace dynslam::frontend
