#pragma once
// The one exception type of the evaluation module: bad input data or options (no matching
// timestamps, trajectories of different length, an empty pair list, a degenerate alignment).
#include <stdexcept>

namespace dynslam::evaluation {

struct EvaluationError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace dynslam::evaluation
