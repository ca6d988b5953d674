#include "dynslam/estimator/GnssWorldAlignment.h"

#include <dynslam/core/Thinning.h>

#include <Eigen/SVD>

#include <algorithm>
#include <cmath>

namespace dynslam::estimator {
namespace {

Eigen::Vector3d centroid(const std::vector<Eigen::Vector3d>& points) {
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  for (const auto& p : points) c += p;
  return c / double(points.size());
}

Eigen::Matrix3Xd centred(const std::vector<Eigen::Vector3d>& points, const Eigen::Vector3d& c) {
  Eigen::Matrix3Xd m(3, points.size());
  for (size_t i = 0; i < points.size(); ++i) m.col(i) = points[i] - c;
  return m;
}

}  // namespace

void GnssWorldAlignment::addPair(const Eigen::Vector3d& world_antenna, const Eigen::Vector3d& enu) {
  if (aligned_) return;
  if (int(world_.size()) >= std::max(2, params_.max_pairs)) {
    core::keepEverySecond(world_);
    core::keepEverySecond(enu_);
  }
  world_.push_back(world_antenna);
  enu_.push_back(enu);
}

bool GnssWorldAlignment::tryAlign(const std::optional<Eigen::Vector3d>& world_gravity) {
  if (aligned_ || int(world_.size()) < params_.min_pairs) return aligned_;
  if (world_gravity && world_gravity->norm() > 0) return alignWithGravity(*world_gravity);
  return alignSe3();
}

bool GnssWorldAlignment::alignWithGravity(const Eigen::Vector3d& gravity) {
  // Tilt: the rotation taking ENU up onto the world's up (-gravity). Then yaw about world up.
  const Eigen::Vector3d up = -gravity.normalized();
  const Eigen::Matrix3d tilt =
      Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(), up).toRotationMatrix();
  const Eigen::Vector3d cw = centroid(world_), ce = centroid(enu_);
  const Eigen::Matrix3Xd W = centred(world_, cw), E = tilt * centred(enu_, ce);
  double span = 0, s = 0, c = 0;
  for (Eigen::Index i = 0; i < W.cols(); ++i) {
    const Eigen::Vector3d w = W.col(i) - up * up.dot(W.col(i));
    const Eigen::Vector3d e = E.col(i) - up * up.dot(E.col(i));
    span = std::max(span, e.norm());
    s += up.dot(e.cross(w));  // sin and cos of the yaw taking e onto w, weighted
    c += e.dot(w);
  }
  if (span < params_.min_span_m) return false;
  const Eigen::Matrix3d R = Eigen::AngleAxisd(std::atan2(s, c), up).toRotationMatrix() * tilt;
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = R;
  T.translation() = cw - R * ce;
  finish(T);
  return true;
}

bool GnssWorldAlignment::alignSe3() {
  const Eigen::Matrix3Xd E = centred(enu_, centroid(enu_));
  const Eigen::JacobiSVD<Eigen::Matrix3Xd> svd(E);
  const double width = svd.singularValues()(1) / std::sqrt(double(E.cols()));
  if (width < params_.min_width_m) return false;
  Eigen::Matrix3Xd src(3, enu_.size()), dst(3, world_.size());
  for (size_t i = 0; i < enu_.size(); ++i) {
    src.col(i) = enu_[i];
    dst.col(i) = world_[i];
  }
  finish(Eigen::Isometry3d(Eigen::umeyama(src, dst, false)));
  return true;
}

void GnssWorldAlignment::finish(const Eigen::Isometry3d& T) {
  T_world_enu_ = T;
  double sum = 0;
  for (size_t i = 0; i < world_.size(); ++i) sum += (T * enu_[i] - world_[i]).squaredNorm();
  rms_ = std::sqrt(sum / double(world_.size()));
  pairs_used_ = world_.size();
  aligned_ = true;
  world_.clear();
  enu_.clear();
}

}  // namespace dynslam::estimator
