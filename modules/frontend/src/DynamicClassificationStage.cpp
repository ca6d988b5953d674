#include "dynslam/frontend/DynamicClassificationStage.h"

#include <stdexcept>

namespace dynslam::frontend {
namespace {

constexpr core::Keyword<SpeedStatistic> kStatistics[] = {
    {"median_flow", SpeedStatistic::MedianFlow}, {"mean_norm", SpeedStatistic::MeanNorm}};

/// The keys of the object decisions and of the feature rules, in the reference's order.
void describeClassification(core::OptionVisitor& v, DynamicClassifierParams& p) {
  using core::Range;
  const Range off = Range::atLeast(0), positive = Range::above(0), atLeast1 = Range::atLeast(1);
  v.key("speed_threshold", p.speed_threshold, off,
        "m/s; an object moving faster (scene flow / time) is dynamic (method.md: 0.1)");
  v.key("speed_window", p.speed_window, atLeast1,
        "frames the scene flow spans at most (1: frame to frame, the method)");
  v.key("speed_statistic", p.speed_statistic, kStatistics,
        "median_flow: |median flow vector|; mean_norm: mean |F| (method.md's wording)");
  v.key("speed_noise_sigmas", p.speed_noise_sigmas, off,
        "dynamic when speed > speed_threshold + this * the speed's noise (0: the method)");
  v.key("still_feature_speed", p.still_feature_speed, off,
        "m/s, 0 = off; a static feature slower than this stays static in any mask (not the "
        "method)");
  v.key("still_feature_in_still_box", p.still_feature_in_still_box,
        "... and so does one that was not static, inside the box of another object judged not "
        "to move (not the method)");
  v.key("still_carried_outside_box", p.still_carried_outside_box,
        "a feature on an object only by last frame's membership, outside its track's box and "
        "slower than still_feature_speed is static, off the object (not the method)");
  v.key("still_above_feet_fraction", p.still_above_feet_fraction, Range::closedOpen(0, 1),
        "0 = off; a feature slower than still_feature_speed in a non-rigid object's mask, above "
        "this fraction of its box from the bottom, is static: a walker's only still parts are "
        "its planted feet (not the method)");
  v.key("unmeasured_feature_by_depth", p.unmeasured_feature_by_depth,
        "a feature with no scene flow yet in a moving object's mask is static inside the box of "
        "an object judged not to move whose depth is nearer its own (not the method)");
  v.key("moving_feature_speed", p.moving_feature_speed, off,
        "m/s, 0 = off; a feature faster than this in a still object's mask is non-rigid (not "
        "the method)");
  v.key("moving_feature_max_speed", p.moving_feature_max_speed, positive,
        "m/s, > moving_feature_speed; ... and slower than this (faster: a depth jump or a slid "
        "track)");
  v.key("max_nonrigid_flow_speed", p.max_nonrigid_flow_speed, off,
        "m/s, 0 = off; a person's feature whose flow is faster (by speed_noise_sigmas of its "
        "depth noise) is a depth jump: no speed, not in the object's (not the method)");
  v.key("min_flow_features", p.min_flow_features, atLeast1,
        "features with flow an object needs for a speed; fewer: last decision kept");
  v.key("start_moving_frames", p.start_moving_frames, atLeast1,
        "an object judged still turns dynamic on this many measured frames in a row over the "
        "threshold (1: at once, the method)");
  v.key("depth_window", p.depth_window, atLeast1,
        "px, odd; a feature's 3-D point uses the robust median depth of this window (1: its "
        "pixel, the method)");
  v.key("far_object_min_depth", p.far_object_min_depth, off,
        "m, 0 = off; the depth range: an object with too little depth is judged from its "
        "depthless features' pixels, taken this far at least (not the method)");
  v.key("far_object_pixel_sigma", p.far_object_pixel_sigma, positive,
        "px; tracking noise of a pixel position, for far_object_min_depth's speed noise");
  v.key("background_outside_boxes", p.background_outside_boxes,
        "camera translation from features outside every box, not just every mask");
}

/// The keys of the rigid sets' and the camera motion's registrations.
void describeRegistrations(core::OptionVisitor& v, DynamicClassifierParams& p) {
  using core::Range;
  const Range off = Range::atLeast(0), positive = Range::above(0), atLeast1 = Range::atLeast(1);
  v.key("rigid_iterations", p.rigid.ransac.iterations, atLeast1,
        "RANSAC hypotheses of the rigid point sets (method.md: 100)");
  v.key("rigid_sample_size", p.rigid.ransac.sample_size, Range::atLeast(3),
        "point pairs per hypothesis (method.md: 4)");
  v.key("rigid_inlier_threshold", p.rigid.ransac.inlier_threshold, positive,
        "m; |R p + t - q| below this joins the rigid set (method.md tau: 0.03)");
  v.key("rigid_min_members", p.rigid.min_members, Range::atLeast(3),
        "fewer inliers than this: no rigid set on the object this frame");
  v.key("rigid_noise_gates", p.rigid.noise_gates,
        "a pair noisier than tau gets 3 sigma of its depth noise as gate (false: tau, the "
        "method)");
  v.key("rigid_rotation_prior_sigma", p.rigid.rotation_prior_sigma, off,
        "rad per frame, 0 = off; a rigid set's own rotation is predicted to stay, and the "
        "registered one blended with it by their variances (not the method)");
  v.key("rigid_pixel_sigma", p.rigid.pixel_sigma_px, off,
        "px, 0 = off (Kabsch); a rigid set's motion is refined with each point's noise along "
        "its ray (depth) and across it (this pixel noise; not the method)");
  v.key("rigid_ray_gate", p.rigid.ray_gate_sigmas, positive,
        "sigmas; with rigid_pixel_sigma, a rigid set's motion is refitted on the members within "
        "this of the refined motion by their own noise along and across the ray");
  v.key("camera_iterations", p.camera.ransac.iterations, atLeast1,
        "RANSAC hypotheses of the camera motion from background points");
  v.key("camera_inlier_threshold", p.camera.ransac.inlier_threshold, positive,
        "m; inlier threshold of the camera-motion registration");
  v.key("camera_min_inliers", p.camera.min_inliers, Range::atLeast(3),
        "fewer background inliers: IMU rotation / constant velocity instead");
  v.key("depth_sigma_z2", p.depth_sigma_z2, off,
        "1/m; depth noise sigma = this * z^2: gates/weights the camera translation's pairs and "
        "weighs the rigid sets' precise registration (0: unweighted)");
  v.key("seed", p.seed, off, "seed of the RANSAC draws (runs are repeatable)");
}

}  // namespace

void DynamicClassificationOptions::describe(core::OptionVisitor& v) {
  auto& p = classifier;
  describeClassification(v, p);
  describeRegistrations(v, p);

  // Settings that act only through another: set alone, they would silently do nothing.
  const bool still = p.still_feature_speed > 0, noise = p.depth_sigma_z2 > 0;
  v.requires("still_feature_in_still_box", p.still_feature_in_still_box, "still_feature_speed > 0",
             still);
  v.requires("still_carried_outside_box", p.still_carried_outside_box, "still_feature_speed > 0",
             still);
  v.requires("still_above_feet_fraction", p.still_above_feet_fraction > 0,
             "still_feature_speed > 0", still);
  v.requires("rigid_noise_gates", p.rigid.noise_gates, "depth_sigma_z2 > 0", noise);
  v.requires("rigid_rotation_prior_sigma", p.rigid.rotation_prior_sigma > 0, "depth_sigma_z2 > 0",
             noise);
  v.requires("rigid_pixel_sigma", p.rigid.pixel_sigma_px > 0, "depth_sigma_z2 > 0", noise);
}

void DynamicClassificationStage::configure(const core::IniConfig& cfg, const std::string& section) {
  core::loadOptionsStrict(options_, cfg, section);
  try {
    classifier_ = std::make_unique<DynamicClassifier>(options_.classifier);
  } catch (const std::invalid_argument& e) {  // a rule between keys (DynamicClassifier)
    throw core::ConfigError("[" + section + "] in " + cfg.source() + ": " + e.what());
  }
}

void DynamicClassificationStage::process(core::Frame& frame) { classifier_->process(frame); }

void DynamicClassificationStage::finish() {
  if (!classifier_) return;
  const auto& c = classifier_->counts();
  std::string sources;
  for (const auto& [source, n] : c.camera_sources)
    sources +=
        std::string(sources.empty() ? "" : ", ") + toString(source) + " " + std::to_string(n);
  MRPT_LOG_INFO_STREAM(c.frames << " frames, " << c.features << " features (" << c.object_features
                                << " on objects), " << c.dynamic_objects
                                << " dynamic object-frames, " << c.rigid_sets
                                << " rigid sets; camera motion: " << sources);
}

std::vector<std::pair<std::string, double>> DynamicClassificationStage::statistics() const {
  if (!classifier_) return {};
  const auto& c = classifier_->counts();
  std::vector<std::pair<std::string, double>> out = {
      {"frames", double(c.frames)},
      {"features", double(c.features)},
      {"object_features", double(c.object_features)},
      {"dynamic_object_frames", double(c.dynamic_objects)},
      {"rigid_sets", double(c.rigid_sets)}};
  for (const auto& [source, n] : c.camera_sources)
    out.emplace_back("camera_motion_" + std::string(toString(source)), double(n));
  return out;
}

}  // namespace dynslam::frontend
