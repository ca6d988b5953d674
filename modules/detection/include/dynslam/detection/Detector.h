#pragma once
// A 2-D object detector: boxes of the classes the class map keeps, in the colour image's pixels.
// It takes the whole frame, not only the image, so that the ground-truth detector can find the
// simulator's objects by the frame's stamp.
#include <dynslam/core/Frame.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace dynslam::detection {

/// A detector that cannot work: a missing or unreadable model, a frame without what it needs.
struct DetectorError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class Detector {
 public:
  virtual ~Detector() = default;

  /// Boxes clipped to the image, already mapped (category, motion model) and filtered by the
  /// class map; none overlaps another of its category beyond the detector's NMS threshold.
  /// May be called from a thread other than the constructing one (one call at a time).
  virtual std::vector<core::Detection> detect(const core::Frame& frame) = 0;
};

}  // namespace dynslam::detection
