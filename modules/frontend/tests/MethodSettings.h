#pragma once
// The settings the tests of the method's own behaviour run with (method.md sections 3-4): the
// departures the code ships as its defaults (docs/design.md) turned off, as params/paper.ini
// turns them off. A test of a departure starts from these and sets that one.
#include <dynslam/frontend/DynamicClassifier.h>
#include <dynslam/frontend/FeatureTracker.h>
#include <dynslam/frontend/RigidPointSet.h>

namespace dynslam::frontend::testing {

/// Shi-Tomasi/KLT as VINS-Fusion's tracker does it: 150 features, no residual gate, no
/// occlusion or depth edges; a 15 px KLT window (method.md names none; the tests' figures were
/// measured with it).
inline FeatureTrackerParams methodTracking() {
  FeatureTrackerParams p;
  p.max_features = 150;
  p.klt_window_px = 15;
  p.max_klt_residual_ratio = 0;
  p.occlusion_edge.radius_px = 0;
  p.depth_edge_radius_px = 0;
  return p;
}

/// methodTracking() as [FeatureTracking] lines.
inline const char* const kMethodTrackingIni =
    "max_features = 150\nklt_window_px = 15\nmax_klt_residual_ratio = 0\n"
    "occlusion_edge_radius_px = 0\ndepth_edge_radius_px = 0\n";

/// The precise registration as Kabsch on the RANSAC inliers: no rotation prior, no refinement
/// on the rays.
inline RigidPointSetParams methodRigidSet() {
  RigidPointSetParams p;
  p.rotation_prior_sigma = 0;
  p.pixel_sigma_px = 0;
  return p;
}

/// Per object by its features' scene flow, each feature by its object's decision and rigid set
/// (methodRigidSet()): the rules on single features, on starting to move and on objects beyond
/// the depth range off. The speed is measured as by default (window, median flow, window depth,
/// noise margin), which on the tests' noise-free scene agrees with the method's frame-to-frame
/// mean (TheMethodsFrameToFrameSettingsAgreeOnCleanData).
inline DynamicClassifierParams methodClassification() {
  DynamicClassifierParams p;
  p.still_feature_speed = 0;
  p.still_feature_in_still_box = false;
  p.unmeasured_feature_by_depth = false;
  p.still_carried_outside_box = false;
  p.still_above_feet_fraction = 0;
  p.start_moving_frames = 1;
  p.moving_feature_speed = 0;
  p.max_nonrigid_flow_speed = 0;
  p.far_object_min_depth = 0;
  p.rigid = methodRigidSet();
  return p;
}

}  // namespace dynslam::frontend::testing
