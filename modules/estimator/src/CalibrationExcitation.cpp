#include "dynslam/estimator/CalibrationExcitation.h"

#include <algorithm>
#include <cmath>

namespace dynslam::estimator {

CalibrationExcitation measureExcitation(const std::vector<KeyframeMotion>& keyframes) {
  CalibrationExcitation out;
  if (keyframes.size() < 2) return out;
  // Velocities in the body frame: a constant-rate orbit keeps them constant although the world
  // velocity turns, and a shift in time is then a rotation about the orbit's centre.
  std::vector<Eigen::Vector3d> rates, velocities;
  Eigen::Vector3d rate_mean = Eigen::Vector3d::Zero(), velocity_mean = Eigen::Vector3d::Zero();
  for (const KeyframeMotion& k : keyframes) {
    rates.push_back(k.angular_velocity_body);
    velocities.push_back(k.q_world_body.conjugate() * k.velocity_world);
    rate_mean += rates.back();
    velocity_mean += velocities.back();
    const double angle = keyframes.front().q_world_body.angularDistance(k.q_world_body);
    out.rotation_deg = std::max(out.rotation_deg, angle * 180 / M_PI);
  }
  rate_mean /= double(keyframes.size());
  velocity_mean /= double(keyframes.size());
  for (std::size_t i = 0; i < keyframes.size(); ++i) {
    out.rate_change = std::max(out.rate_change, (rates[i] - rate_mean).norm());
    out.velocity_change = std::max(out.velocity_change, (velocities[i] - velocity_mean).norm());
  }
  return out;
}

}  // namespace dynslam::estimator
