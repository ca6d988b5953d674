#pragma once
// Keyframe selection by parallax and time (issue 6 item 4, as VINS-Fusion): a frame becomes a
// keyframe when the features it shares with the last keyframe moved far enough on average, when
// too few of them are still tracked, or when too long has passed since the last keyframe.
#include <Eigen/Core>

#include <cstdint>
#include <map>
#include <vector>

namespace dynslam::estimator {

/// [Estimator] keyframe_parallax_px, keyframe_max_interval, keyframe_min_shared: ranges and
/// meanings in EstimatorOptions::describe() (EstimatorOptions.cpp), docs/parameters.md.
struct KeyframeSelectorParams {
  double min_parallax_px = 10.0;
  double max_interval_s = 0.5;  ///< the IMU factor between keyframes stays short
  /// 20 as VINS-Fusion's tracker: with more, a crowd that leaves few static features makes every
  /// frame a keyframe, the window shrinks to a fraction of a second and its velocity and gyro
  /// bias follow the few features (docs/notes/estimator.md, 2026-11-28 (keyframe_min_shared)).
  int min_shared = 20;
};

class KeyframeSelector {
 public:
  explicit KeyframeSelector(KeyframeSelectorParams params = {}) : params_(params) {}

  /// Why a frame is (or is not) a keyframe, for logs and tests.
  enum class Reason { First, Parallax, Interval, FewShared, NotKeyframe };

  /// Decides for a frame at time t with these features (id -> pixel); `shared` (optional)
  /// receives how many of them the last keyframe had.
  Reason decide(double t, const std::map<std::int64_t, Eigen::Vector2d>& features,
                int* shared = nullptr) const;
  /// The reason as keyframes.csv writes it: first, parallax, interval, few_shared, none.
  static const char* name(Reason reason);
  /// Records that the frame became a keyframe.
  void accept(double t, const std::map<std::int64_t, Eigen::Vector2d>& features);

 private:
  KeyframeSelectorParams params_;
  bool has_keyframe_ = false;
  double keyframe_t_ = 0;
  std::map<std::int64_t, Eigen::Vector2d> keyframe_features_;
};

}  // namespace dynslam::estimator
