#include "dynslam/estimator/GnssAnchor.h"

namespace dynslam::estimator {

GnssAnchor::GnssAnchor(GnssAnchorParams params)
    : params_(params), fixes_(params.max_gap_s), alignment_(params.alignment) {}

void GnssAnchor::addFixes(const std::vector<core::GnssFix>& fixes) {
  for (const auto& f : fixes) fixes_.add(f.t, f.enu, f.hdop);
}

void GnssAnchor::keyframeAdded(double t) {
  latest_keyframe_ = t;
  pending_.push_back(t);
  // Without fixes (no receiver, or a long outage) keyframes would wait for ever: keep the last
  // few only (a fix arriving later than this many keyframes is of no use to the window).
  constexpr std::size_t kMaxPending = 32;
  while (pending_.size() > kMaxPending) pending_.pop_front();
}

Eigen::Matrix3d GnssAnchor::covariance(double hdop) const {
  const double h = params_.uere_horizontal_m * (hdop > 0 ? hdop : 1.0);
  const double v = params_.vertical_factor * h;
  return Eigen::Vector3d(h * h, h * h, v * v).asDiagonal();  // ENU axes
}

}  // namespace dynslam::estimator
