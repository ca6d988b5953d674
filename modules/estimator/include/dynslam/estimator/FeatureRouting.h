#pragma once
// Which of a frame's tracked features go where in the sliding window (method.md section 5 and
// the paper's Table 9 ablations), by the estimator's dynamic_handling and factor switches:
//   none   - every feature a static landmark, whatever its class (VINS-Mono);
//   remove - Static features as landmarks, the others dropped (Dynamic-VINS);
//   full   - Static features as landmarks, NonRigid ones as constant-velocity points (r_D) when
//            nonrigid_factors, Rigid ones as points of their object (r_O, r_om) when
//            rigid_factors; a class whose factors are off is dropped as in remove.
#include <dynslam/core/Features.h>
#include <dynslam/estimator/SlidingWindow.h>

#include <Eigen/Core>

#include <cstdint>
#include <map>
#include <vector>

namespace dynslam::estimator {

enum class DynamicHandling { None, Remove, Full };

struct RoutedFeatures {
  std::vector<FeatureObservation> landmarks;       ///< constrain the camera as static points
  std::map<std::int64_t, Eigen::Vector2d> pixels;  ///< the landmarks' pixels (keyframes, PnP)
  std::vector<FeatureObservation> nonrigid;        ///< r_D
  std::vector<RigidObjectInput> rigid_objects;     ///< r_O / r_om, one entry per object
  /// Features classified as moving (not Static; empty with none): whatever the window holds of
  /// them as static landmarks was taken from frames in which they were not known to move.
  std::vector<std::int64_t> moving;
};

RoutedFeatures routeFeatures(const std::vector<core::Feature>& features, DynamicHandling handling,
                             bool nonrigid_factors, bool rigid_factors);

}  // namespace dynslam::estimator
