#pragma once
// Boxes and detector frames for the tracker's tests.
#include <dynslam/tracking/KalmanBoxTracker.h>

#include <opencv2/core.hpp>

#include <vector>

namespace dynslam::tracking::testing {

constexpr double kDt = 1.0 / 30;

/// The tracker as method.md section 2 states it (params/paper.ini's [Tracking]): the defaults
/// with every departure turned off, for the tests of the method's own behaviour and of one
/// departure at a time.
inline KalmanBoxTrackerParams paperParams() {
  KalmanBoxTrackerParams p;
  p.rho_min = 0.7;
  p.min_hits = 3;
  p.reset_at_border = false;
  p.reid_max_distance = 0;
  p.reid_memory = 0;
  p.alternative_depth = false;
  p.depth_gate = 0;
  p.innovation_gate = 0;
  return p;
}

inline BoxObservation person(float x, float y, float w, float h, double depth) {
  return {cv::Rect2f(x, y, w, h), depth, "person", core::MotionModel::NonRigid};
}

/// One detector frame at time k * kDt on a 640 x 480 image.
inline std::vector<core::Track> step(KalmanBoxTracker& tracker, int k,
                                     const std::vector<BoxObservation>& observations) {
  tracker.predict(k * kDt);
  tracker.update(observations, cv::Size(640, 480));
  return tracker.tracks();
}

inline const core::Track* findId(const std::vector<core::Track>& tracks, int id) {
  for (const auto& t : tracks)
    if (t.id == id) return &t;
  return nullptr;
}

}  // namespace dynslam::tracking::testing
