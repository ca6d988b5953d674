#include "dynslam/sim/FloorPath.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace dynslam::sim {

FloorPath::FloorPath(std::vector<Eigen::Vector2d> waypoints, double speed, double start_offset_m,
                     Mode mode, double turn_length)
    : waypoints_(std::move(waypoints)),
      speed_(speed),
      offset_(start_offset_m),
      turn_length_(turn_length),
      mode_(mode) {
  if (waypoints_.empty()) throw std::invalid_argument("FloorPath needs at least one waypoint");
  if (!(turn_length_ > 0)) throw std::invalid_argument("FloorPath turn_length must be > 0");
  if (mode_ == Mode::Loop && waypoints_.size() > 1) waypoints_.push_back(waypoints_.front());
  cumulative_.push_back(0.0);
  for (size_t i = 1; i < waypoints_.size(); ++i)
    cumulative_.push_back(cumulative_.back() + (waypoints_[i] - waypoints_[i - 1]).norm());
}

Eigen::Vector2d FloorPath::pointAt(double s) const {
  const double len = length();
  if (len <= 0) return waypoints_.front();
  double u;
  if (mode_ == Mode::Loop) {
    u = std::fmod(s, len);
    if (u < 0) u += len;
  } else {
    // Back and forth: a loop of twice the length, mirrored on the way back.
    u = std::fmod(s, 2 * len);
    if (u < 0) u += 2 * len;
    if (u > len) u = 2 * len - u;
  }
  const auto it = std::upper_bound(cumulative_.begin(), cumulative_.end(), u);
  const size_t i =
      std::clamp<size_t>(static_cast<size_t>(it - cumulative_.begin()), 1, waypoints_.size() - 1);
  const double seg = cumulative_[i] - cumulative_[i - 1];
  const double a = seg > 0 ? (u - cumulative_[i - 1]) / seg : 0.0;
  return waypoints_[i - 1] + a * (waypoints_[i] - waypoints_[i - 1]);
}

void FloorPath::at(double t, Eigen::Vector2d& xy, double& heading) const {
  const double s = offset_ + distance(t);
  xy = pointAt(s);
  if (standing()) {
    heading = 0;
    return;
  }
  // Heading along the chord from turn_length behind to turn_length ahead: a smooth turn over
  // about that distance instead of an instant one.
  const Eigen::Vector2d ahead = pointAt(s + turn_length_), behind = pointAt(s - turn_length_);
  const Eigen::Vector2d dir = ahead - behind;
  heading = dir.norm() > 1e-6 ? std::atan2(dir.y(), dir.x()) : 0.0;
  if (dir.norm() < 0.75 * turn_length_) {  // at a reversal both points coincide: look ahead only
    const Eigen::Vector2d d2 = ahead - xy;
    if (d2.norm() > 1e-6) heading = std::atan2(d2.y(), d2.x());
  }
}

}  // namespace dynslam::sim
