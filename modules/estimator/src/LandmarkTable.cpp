#include "dynslam/estimator/LandmarkTable.h"

namespace dynslam::estimator {

void LandmarkTable::observe(std::int64_t id, std::int64_t keyframe,
                            const LandmarkObservation& observation, double default_depth) {
  auto [it, inserted] = landmarks_.try_emplace(id);
  Landmark& l = it->second;
  if (inserted) {
    l.anchor = keyframe;
    l.inverse_depth = 1.0 / (observation.depth > 0 ? observation.depth : default_depth);
  }
  l.observations[keyframe] = observation;
}

}  // namespace dynslam::estimator
