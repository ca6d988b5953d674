#include "dynslam/estimator/KeyframeSelector.h"

namespace dynslam::estimator {

KeyframeSelector::Reason KeyframeSelector::decide(
    double t, const std::map<std::int64_t, Eigen::Vector2d>& features) const {
  if (!has_keyframe_) return Reason::First;
  int shared = 0;
  double parallax = 0;
  for (const auto& [id, pixel] : features) {
    const auto it = keyframe_features_.find(id);
    if (it == keyframe_features_.end()) continue;
    ++shared;
    parallax += (pixel - it->second).norm();
  }
  if (shared < params_.min_shared) return Reason::FewShared;
  if (parallax / shared >= params_.min_parallax_px) return Reason::Parallax;
  if (t - keyframe_t_ >= params_.max_interval_s) return Reason::Interval;
  return Reason::NotKeyframe;
}

void KeyframeSelector::accept(double t, const std::map<std::int64_t, Eigen::Vector2d>& features) {
  has_keyframe_ = true;
  keyframe_t_ = t;
  keyframe_features_ = features;
}

}  // namespace dynslam::estimator
