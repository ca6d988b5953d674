#include "dynslam/frontend/DynamicClassificationStage.h"

#include <mrpt/config/CConfigFileBase.h>

#include <stdexcept>

namespace dynslam::frontend {
namespace {

constexpr core::Keyword<SpeedStatistic> kStatistics[] = {
    {"median_flow", SpeedStatistic::MedianFlow}, {"mean_norm", SpeedStatistic::MeanNorm}};

}  // namespace

void DynamicClassificationOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& c,
                                                      const std::string& s) {
  auto& p = classifier;
  p.speed_threshold = c.read_double(s, "speed_threshold", p.speed_threshold);
  p.speed_window = c.read_int(s, "speed_window", p.speed_window);
  p.speed_statistic = core::readKeyword(c, s, "speed_statistic", p.speed_statistic, kStatistics);
  p.min_flow_features = c.read_int(s, "min_flow_features", p.min_flow_features);
  p.start_moving_frames = c.read_int(s, "start_moving_frames", p.start_moving_frames);
  p.speed_noise_sigmas = c.read_double(s, "speed_noise_sigmas", p.speed_noise_sigmas);
  p.still_feature_speed = c.read_double(s, "still_feature_speed", p.still_feature_speed);
  p.still_feature_in_still_box =
      core::readBool(c, s, "still_feature_in_still_box", p.still_feature_in_still_box);
  p.still_carried_outside_box =
      core::readBool(c, s, "still_carried_outside_box", p.still_carried_outside_box);
  p.still_above_feet_fraction =
      c.read_double(s, "still_above_feet_fraction", p.still_above_feet_fraction);
  p.unmeasured_feature_by_depth =
      core::readBool(c, s, "unmeasured_feature_by_depth", p.unmeasured_feature_by_depth);
  p.moving_feature_speed = c.read_double(s, "moving_feature_speed", p.moving_feature_speed);
  p.moving_feature_max_speed =
      c.read_double(s, "moving_feature_max_speed", p.moving_feature_max_speed);
  p.max_nonrigid_flow_speed =
      c.read_double(s, "max_nonrigid_flow_speed", p.max_nonrigid_flow_speed);
  p.depth_window = c.read_int(s, "depth_window", p.depth_window);
  p.far_object_min_depth = c.read_double(s, "far_object_min_depth", p.far_object_min_depth);
  p.far_object_pixel_sigma = c.read_double(s, "far_object_pixel_sigma", p.far_object_pixel_sigma);
  p.background_outside_boxes =
      core::readBool(c, s, "background_outside_boxes", p.background_outside_boxes);
  p.rigid.ransac.iterations = c.read_int(s, "rigid_iterations", p.rigid.ransac.iterations);
  p.rigid.ransac.sample_size = c.read_int(s, "rigid_sample_size", p.rigid.ransac.sample_size);
  p.rigid.ransac.inlier_threshold =
      c.read_double(s, "rigid_inlier_threshold", p.rigid.ransac.inlier_threshold);
  p.rigid.min_members = c.read_int(s, "rigid_min_members", p.rigid.min_members);
  p.rigid.noise_gates = core::readBool(c, s, "rigid_noise_gates", p.rigid.noise_gates);
  p.rigid.rotation_prior_sigma =
      c.read_double(s, "rigid_rotation_prior_sigma", p.rigid.rotation_prior_sigma);
  p.rigid.pixel_sigma_px = c.read_double(s, "rigid_pixel_sigma", p.rigid.pixel_sigma_px);
  p.rigid.ray_gate_sigmas = c.read_double(s, "rigid_ray_gate", p.rigid.ray_gate_sigmas);
  p.camera.ransac.iterations = c.read_int(s, "camera_iterations", p.camera.ransac.iterations);
  p.camera.ransac.inlier_threshold =
      c.read_double(s, "camera_inlier_threshold", p.camera.ransac.inlier_threshold);
  p.camera.min_inliers = c.read_int(s, "camera_min_inliers", p.camera.min_inliers);
  p.camera.depth_sigma_z2 = c.read_double(s, "depth_sigma_z2", p.camera.depth_sigma_z2);
  p.rigid.depth_sigma_z2 = p.camera.depth_sigma_z2;
  p.seed = std::uint32_t(c.read_int(s, "seed", int(p.seed)));
}

void DynamicClassificationOptions::saveToConfigFile(mrpt::config::CConfigFileBase& c,
                                                    const std::string& s) const {
  const auto& p = classifier;
  core::writeKey(c, s, "speed_threshold", p.speed_threshold,
        "m/s; an object moving faster (scene flow / time) is dynamic (method.md: 0.1)");
  core::writeKey(c, s, "speed_window", p.speed_window,
        "frames the scene flow spans at most (1: frame to frame, the method; see the header)");
  core::writeKey(c, s, "speed_statistic", std::string(core::wordOf(p.speed_statistic, kStatistics)),
                 "median_flow: |median flow vector|; mean_norm: mean |F| (method.md's wording)");
  core::writeKey(c, s, "speed_noise_sigmas", p.speed_noise_sigmas,
        "dynamic when speed > speed_threshold + this * the speed's noise (0: the method)");
  core::writeKey(c, s, "still_feature_speed", p.still_feature_speed,
                 "m/s; a static feature slower than this stays static in any mask (0: off)");
  core::writeKey(c, s, "still_feature_in_still_box", p.still_feature_in_still_box,
                 "true: ... and so does one that was not static, inside the box of another "
                 "object judged not to move (not the method)");
  core::writeKey(c, s, "still_carried_outside_box", p.still_carried_outside_box,
                 "true: a feature on an object only by last frame's membership, outside its "
                 "track's box and slower than still_feature_speed is static, off the object "
                 "(not the method)");
  core::writeKey(c, s, "still_above_feet_fraction", p.still_above_feet_fraction,
                 "a feature slower than still_feature_speed in a non-rigid object's mask, above "
                 "this fraction of its box from the bottom, is static: a walker's only still "
                 "parts are its planted feet (not the method; 0: off)");
  core::writeKey(c, s, "unmeasured_feature_by_depth", p.unmeasured_feature_by_depth,
                 "true: a feature with no scene flow yet in a moving object's mask is static "
                 "inside the box of an object judged not to move whose depth is nearer its own "
                 "(not the method)");
  core::writeKey(c, s, "moving_feature_speed", p.moving_feature_speed,
                 "m/s; a feature faster than this in a still object's mask is non-rigid (0: off)");
  core::writeKey(c, s, "moving_feature_max_speed", p.moving_feature_max_speed,
                 "m/s; ... and slower than this (faster: a depth jump or a slid track)");
  core::writeKey(c, s, "max_nonrigid_flow_speed", p.max_nonrigid_flow_speed,
                 "m/s; a person's feature whose flow is faster (by speed_noise_sigmas of its "
                 "depth noise) is a depth jump: no speed, not in the object's (not the method; "
                 "0: off)");
  core::writeKey(c, s, "min_flow_features", p.min_flow_features,
        "features with flow an object needs for a speed; fewer: last decision kept");
  core::writeKey(c, s, "start_moving_frames", p.start_moving_frames,
                 "an object judged still turns dynamic on this many measured frames in a row "
                 "over the threshold (not the method; 1: at once)");
  core::writeKey(c, s, "depth_window", p.depth_window,
        "px; a feature's 3-D point uses the robust median depth of this window (1: its pixel)");
  core::writeKey(c, s, "far_object_min_depth", p.far_object_min_depth,
                 "m; the depth range: an object with too little depth is judged from its "
                 "depthless features' pixels, taken this far at least (0: off)");
  core::writeKey(c, s, "far_object_pixel_sigma", p.far_object_pixel_sigma,
                 "px; tracking noise of a pixel position, for far_object_min_depth's speed noise");
  core::writeKey(c, s, "background_outside_boxes", p.background_outside_boxes,
                 "camera translation from features outside every box, not just every mask");
  core::writeKey(c, s, "rigid_iterations", p.rigid.ransac.iterations,
        "RANSAC hypotheses of the rigid point sets (method.md: 100)");
  core::writeKey(c, s, "rigid_sample_size", p.rigid.ransac.sample_size,
        "point pairs per hypothesis (method.md: 4)");
  core::writeKey(c, s, "rigid_inlier_threshold", p.rigid.ransac.inlier_threshold,
        "m; |R p + t - q| below this joins the rigid set (method.md tau: 0.03)");
  core::writeKey(c, s, "rigid_min_members", p.rigid.min_members,
        "fewer inliers than this: no rigid set on the object this frame");
  core::writeKey(c, s, "rigid_noise_gates", p.rigid.noise_gates,
        "true: a pair noisier than tau gets 3 sigma of its depth noise as gate; false: tau");
  core::writeKey(c, s, "rigid_rotation_prior_sigma", p.rigid.rotation_prior_sigma,
                 "rad per frame; > 0: a rigid set's own rotation is predicted to stay, and the "
                 "registered one blended with it by their variances (not the method; 0: off)");
  core::writeKey(c, s, "rigid_pixel_sigma", p.rigid.pixel_sigma_px,
                 "px; > 0: a rigid set's motion is refined with each point's noise along its ray "
                 "(depth) and across it (this pixel noise), not the method (0: off, Kabsch)");
  core::writeKey(c, s, "rigid_ray_gate", p.rigid.ray_gate_sigmas,
                 "sigmas; with rigid_pixel_sigma, a rigid set's motion is refitted on the members "
                 "within this of the refined motion by their own noise along and across the ray");
  core::writeKey(c, s, "camera_iterations", p.camera.ransac.iterations,
        "RANSAC hypotheses of the camera motion from background points");
  core::writeKey(c, s, "camera_inlier_threshold", p.camera.ransac.inlier_threshold,
        "m; inlier threshold of the camera-motion registration");
  core::writeKey(c, s, "camera_min_inliers", p.camera.min_inliers,
        "fewer background inliers: IMU rotation / constant velocity instead");
  core::writeKey(c, s, "depth_sigma_z2", p.camera.depth_sigma_z2,
        "1/m; depth noise sigma = this * z^2: gates/weights the camera translation's pairs and "
        "weighs the rigid sets' precise registration (0: unweighted)");
  core::writeKey(c, s, "seed", int(p.seed), "seed of the RANSAC draws (runs are repeatable)");
}

void DynamicClassificationStage::configure(const core::IniConfig& cfg, const std::string& section) {
  try {
    core::loadOptionsStrict(options_, cfg, section);
  } catch (const std::invalid_argument& e) {  // a keyword key with another word
    throw core::ConfigError("[" + section + "] " + e.what() + " (in " + cfg.source() + ")");
  }
  const auto& p = options_.classifier;
  auto fail = [&](const std::string& key, const std::string& value, const std::string& rule) {
    throw core::ConfigError("[" + section + "] " + key + " = " + value + " in " + cfg.source() +
                            ": " + rule);
  };
  if (!(p.speed_threshold >= 0))
    fail("speed_threshold", std::to_string(p.speed_threshold), "must be >= 0");
  if (p.start_moving_frames < 1)
    fail("start_moving_frames", std::to_string(p.start_moving_frames), "must be >= 1");
  if (!(p.speed_noise_sigmas >= 0))
    fail("speed_noise_sigmas", std::to_string(p.speed_noise_sigmas), "must be >= 0");
  if (!(p.still_feature_speed >= 0))
    fail("still_feature_speed", std::to_string(p.still_feature_speed), "must be >= 0");
  if (!(p.still_above_feet_fraction >= 0 && p.still_above_feet_fraction < 1))
    fail("still_above_feet_fraction", std::to_string(p.still_above_feet_fraction),
         "must be in [0, 1)");
  if (!(p.moving_feature_speed >= 0))
    fail("moving_feature_speed", std::to_string(p.moving_feature_speed), "must be >= 0");
  if (!(p.moving_feature_max_speed > p.moving_feature_speed))
    fail("moving_feature_max_speed", std::to_string(p.moving_feature_max_speed),
         "must be > moving_feature_speed");
  if (!(p.max_nonrigid_flow_speed >= 0))
    fail("max_nonrigid_flow_speed", std::to_string(p.max_nonrigid_flow_speed), "must be >= 0");
  if (!(p.far_object_min_depth >= 0))
    fail("far_object_min_depth", std::to_string(p.far_object_min_depth), "must be >= 0");
  if (!(p.far_object_pixel_sigma > 0))
    fail("far_object_pixel_sigma", std::to_string(p.far_object_pixel_sigma), "must be > 0");
  if (p.speed_window < 1) fail("speed_window", std::to_string(p.speed_window), "must be >= 1");
  if (p.min_flow_features < 1)
    fail("min_flow_features", std::to_string(p.min_flow_features), "must be >= 1");
  if (p.depth_window < 1 || p.depth_window % 2 == 0)
    fail("depth_window", std::to_string(p.depth_window), "must be odd and >= 1");
  if (!(p.camera.depth_sigma_z2 >= 0))
    fail("depth_sigma_z2", std::to_string(p.camera.depth_sigma_z2), "must be >= 0");
  if (p.rigid.ransac.iterations < 1)
    fail("rigid_iterations", std::to_string(p.rigid.ransac.iterations), "must be >= 1");
  if (p.rigid.ransac.sample_size < 3)
    fail("rigid_sample_size", std::to_string(p.rigid.ransac.sample_size), "must be >= 3");
  if (!(p.rigid.ransac.inlier_threshold > 0))
    fail("rigid_inlier_threshold", std::to_string(p.rigid.ransac.inlier_threshold), "must be > 0");
  if (p.rigid.min_members < 3)
    fail("rigid_min_members", std::to_string(p.rigid.min_members), "must be >= 3");
  if (!(p.rigid.rotation_prior_sigma >= 0))
    fail("rigid_rotation_prior_sigma", std::to_string(p.rigid.rotation_prior_sigma),
         "must be >= 0");
  if (!(p.rigid.pixel_sigma_px >= 0))
    fail("rigid_pixel_sigma", std::to_string(p.rigid.pixel_sigma_px), "must be >= 0");
  if (!(p.rigid.ray_gate_sigmas > 0))
    fail("rigid_ray_gate", std::to_string(p.rigid.ray_gate_sigmas), "must be > 0");
  if (p.camera.ransac.iterations < 1)
    fail("camera_iterations", std::to_string(p.camera.ransac.iterations), "must be >= 1");
  if (!(p.camera.ransac.inlier_threshold > 0))
    fail("camera_inlier_threshold", std::to_string(p.camera.ransac.inlier_threshold),
         "must be > 0");
  if (p.camera.min_inliers < 3)
    fail("camera_min_inliers", std::to_string(p.camera.min_inliers), "must be >= 3");
  classifier_ = std::make_unique<DynamicClassifier>(p);
}

void DynamicClassificationStage::process(core::Frame& frame) { classifier_->process(frame); }

void DynamicClassificationStage::finish() {
  if (!classifier_) return;
  const auto& c = classifier_->counts();
  std::string sources;
  for (const auto& [source, n] : c.camera_sources)
    sources += std::string(sources.empty() ? "" : ", ") + toString(source) + " " +
               std::to_string(n);
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
