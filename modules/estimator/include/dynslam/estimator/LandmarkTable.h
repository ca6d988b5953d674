#pragma once
// The static landmarks of the sliding window: each tracked static feature, anchored at the
// first keyframe of the window that saw it, parameterised by its inverse depth there (the
// StaticReprojectionFactor's block), with its observations in the window's keyframes.
#include <Eigen/Core>

#include <cstdint>
#include <iterator>
#include <map>

namespace dynslam::estimator {

struct LandmarkObservation {
  Eigen::Vector2d pixel = Eigen::Vector2d::Zero();
  double depth = 0;                                    ///< measured depth at the pixel, m; 0 = none
  Eigen::Vector2d velocity = Eigen::Vector2d::Zero();  ///< image velocity, px/s (the time offset)
};

struct Landmark {
  std::int64_t anchor = -1;  ///< keyframe id of the first observation in the window
  double inverse_depth = 0;  ///< 1 / depth in the anchor camera; the estimator's block
  /// Observations by keyframe id (the anchor's included), in keyframe order.
  std::map<std::int64_t, LandmarkObservation> observations;

  const LandmarkObservation& anchorObservation() const { return observations.at(anchor); }
};

class LandmarkTable {
 public:
  /// Records feature `id` seen in keyframe `keyframe` (ids increase with time). A new landmark is
  /// anchored there, with its inverse depth from the measured depth (or `default_depth`).
  void observe(std::int64_t id, std::int64_t keyframe, const LandmarkObservation& observation,
               double default_depth);

  /// Drops every observation in keyframe `keyframe` (it left the window). Landmarks anchored
  /// there move their anchor, with `reanchor(landmark, new anchor)` giving the inverse depth
  /// there from the current estimate: to their next observation, keeping the others, or with
  /// `restart` to their newest, dropping the others (LandmarkReanchoring in SlidingWindow.h).
  /// Landmarks with no observation left are deleted.
  template <typename Reanchor>
  void removeKeyframe(std::int64_t keyframe, Reanchor reanchor, bool restart = false) {
    for (auto it = landmarks_.begin(); it != landmarks_.end();) {
      Landmark& l = it->second;
      if (l.anchor == keyframe && l.observations.size() > 1) {
        // The new anchor's inverse depth comes from the old anchor, so before erasing it.
        const std::int64_t next = restart ? std::prev(l.observations.end())->first
                                          : std::next(l.observations.begin())->first;
        l.inverse_depth = reanchor(l, next);
        l.anchor = next;
        if (restart) {
          const LandmarkObservation newest = l.observations.at(next);
          l.observations = {{next, newest}};
        }
      }
      l.observations.erase(keyframe);
      if (l.observations.empty()) {
        it = landmarks_.erase(it);
        continue;
      }
      ++it;
    }
  }

  /// Deletes landmark `id` with all its observations; false when there is none.
  bool erase(std::int64_t id) { return landmarks_.erase(id) > 0; }

  std::map<std::int64_t, Landmark>& all() { return landmarks_; }
  const std::map<std::int64_t, Landmark>& all() const { return landmarks_; }

 private:
  std::map<std::int64_t, Landmark> landmarks_;
};

}  // namespace dynslam::estimator
