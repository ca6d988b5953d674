#include "dynslam/estimator/GnssFixBuffer.h"

#include <algorithm>

namespace dynslam::estimator {

void GnssFixBuffer::add(double t, const Eigen::Vector3d& enu, double hdop) {
  if (!fixes_.empty() && t <= fixes_.back().t) return;
  fixes_.push_back({t, enu, hdop});
}

std::optional<GnssFixBuffer::Position> GnssFixBuffer::at(double t) const {
  const auto after = std::lower_bound(fixes_.begin(), fixes_.end(), t,
                                      [](const Fix& f, double time) { return f.t < time; });
  if (after == fixes_.end()) return std::nullopt;
  if (after->t == t) return Position{after->enu, after->hdop};
  if (after == fixes_.begin()) return std::nullopt;
  const Fix& before = *std::prev(after);
  if (after->t - before.t > max_gap_s_) return std::nullopt;
  const double a = (t - before.t) / (after->t - before.t);
  return Position{(1 - a) * before.enu + a * after->enu, std::max(before.hdop, after->hdop)};
}

void GnssFixBuffer::dropBefore(double t) {
  // Keep the last fix before t: it brackets t with the next one.
  while (fixes_.size() >= 2 && fixes_[1].t <= t) fixes_.pop_front();
}

}  // namespace dynslam::estimator
