#pragma once
// Which of a frame's tracked features go where in the sliding window (method.md section 5 and
// the paper's Table 9 ablations), by the estimator's dynamic_handling and factor switches:
//   none   - every feature a static landmark, whatever its class (VINS-Mono);
//   remove - Static features off every detected object as landmarks, the others dropped: like
//            Dynamic-VINS, which masks detected people and cars out whether they move or not;
//   full   - Static features as landmarks, NonRigid ones as constant-velocity points (r_D) when
//            nonrigid_factors, Rigid ones as points of their object (r_O, r_om) when
//            rigid_factors; a class whose factors are off is dropped. Static features on an
//            object (a standing person, a parked car) are landmarks, as the front-end found
//            them still: with both factor switches off that is remove without the masking.
#include <dynslam/core/Features.h>
#include <dynslam/estimator/SlidingWindow.h>

#include <Eigen/Core>

#include <cstdint>
#include <map>
#include <vector>

namespace dynslam::estimator {

enum class DynamicHandling { None, Remove, Full };

struct RoutedFeatures {
  std::vector<FeatureObservation> landmarks;  ///< constrain the camera as static points
  /// The landmarks' pixels at the state time (moved by the time offset; keyframes, PnP).
  std::map<std::int64_t, Eigen::Vector2d> pixels;
  std::vector<FeatureObservation> nonrigid;     ///< r_D
  std::vector<RigidObjectInput> rigid_objects;  ///< r_O / r_om, one entry per object
  /// Features that are not landmarks this frame (empty with none): those classified as moving,
  /// and with remove the still ones on a detected object. Whatever the window holds of them as
  /// static landmarks was taken from frames in which they were not known to be so.
  std::vector<std::int64_t> not_landmarks;
};

/// `time_offset_s`: the camera-IMU time offset now (SlidingWindow::timeOffset()), which moves
/// RoutedFeatures::pixels; the observations keep the measured pixel and its velocity.
RoutedFeatures routeFeatures(const std::vector<core::Feature>& features, DynamicHandling handling,
                             bool nonrigid_factors, bool rigid_factors, double time_offset_s = 0.0);

}  // namespace dynslam::estimator
