#include "dynslam/estimator/KeyframeSelector.h"

namespace dynslam::estimator {

KeyframeSelector::Reason KeyframeSelector::decide(
    double t, const std::map<std::int64_t, Eigen::Vector2d>& features, int* sharedOut) const {
  if (sharedOut) *sharedOut = 0;
  if (!has_keyframe_) return Reason::First;
  int shared = 0;
  double parallax = 0;
  for (const auto& [id, pixel] : features) {
    const auto it = keyframe_features_.find(id);
    if (it == keyframe_features_.end()) continue;
    ++shared;
    parallax += (pixel - it->second).norm();
  }
  if (sharedOut) *sharedOut = shared;
  if (shared < params_.min_shared) return Reason::FewShared;
  if (parallax / shared >= params_.min_parallax_px) return Reason::Parallax;
  if (t - keyframe_t_ >= params_.max_interval_s) return Reason::Interval;
  return Reason::NotKeyframe;
}

const char* KeyframeSelector::name(Reason reason) {
  switch (reason) {
    case Reason::First:
      return "first";
    case Reason::Parallax:
      return "parallax";
    case Reason::Interval:
      return "interval";
    case Reason::FewShared:
      return "few_shared";
    case Reason::NotKeyframe:
      break;
  }
  return "none";
}

void KeyframeSelector::accept(double t, const std::map<std::int64_t, Eigen::Vector2d>& features) {
  has_keyframe_ = true;
  keyframe_t_ = t;
  keyframe_features_ = features;
}

}  // namespace dynslam::estimator
