#include "dynslam/frontend/FeatureTrackingStage.h"

#include <mrpt/config/CConfigFileBase.h>

#include "dynslam/core/Median.h"

#include <algorithm>
#include <stdexcept>

namespace dynslam::frontend {
namespace {

#define FT_READ(type, field, key) field = c.read_##type(s, key, field)
#define FT_WRITE(field, key, comment) core::writeKey(c, s, key, field, comment)

}  // namespace

void FeatureTrackingOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& c,
                                                const std::string& s) {
  auto& t = tracker;
  auto& g = tracker.corners;
  FT_READ(int, t.max_features, "max_features");
  FT_READ(double, g.min_distance_px, "min_distance_px");
  FT_READ(double, g.quality_level, "quality_level");
  FT_READ(double, g.min_eigenvalue, "min_eigenvalue");
  FT_READ(int, g.block_size, "block_size");
  FT_READ(int, g.grid_cols, "grid_cols");
  FT_READ(int, g.grid_rows, "grid_rows");
  FT_READ(int, g.border_px, "border_px");
  FT_READ(int, g.level, "corner_level");
  FT_READ(int, t.klt_window_px, "klt_window_px");
  FT_READ(int, t.klt_pyramid_levels, "klt_pyramid_levels");
  FT_READ(int, t.klt_predicted_levels, "klt_predicted_levels");
  FT_READ(int, t.klt_max_iterations, "klt_max_iterations");
  FT_READ(double, t.klt_epsilon, "klt_epsilon");
  FT_READ(double, t.max_fb_error_px, "max_fb_error_px");
  FT_READ(double, t.max_klt_residual_ratio, "max_klt_residual_ratio");
  t.residual_gate_region = residualGateRegionFromString(
      c.read_string(s, "residual_gate_region", toString(t.residual_gate_region)));
  FT_READ(double, t.residual_gate_margin_px, "residual_gate_margin_px");
  FT_READ(int, t.occlusion_edge.radius_px, "occlusion_edge_radius_px");
  FT_READ(double, t.occlusion_edge.min_gap_m, "occlusion_edge_min_gap_m");
  FT_READ(double, t.occlusion_edge.gap_ratio, "occlusion_edge_gap_ratio");
  t.occlusion_edge_objects_only =
      core::readBool(c, s, "occlusion_edge_objects_only", t.occlusion_edge_objects_only);
  FT_READ(int, t.depth_edge_radius_px, "depth_edge_radius_px");
  t.flow_init = flowInitFromString(c.read_string(s, "flow_init", toString(t.flow_init)));
  t.fundamental_ransac = core::readBool(c, s, "fundamental_ransac", t.fundamental_ransac);
  FT_READ(double, t.fundamental_threshold_px, "fundamental_threshold_px");
  FT_READ(double, t.fundamental_confidence, "fundamental_confidence");
}

void FeatureTrackingOptions::saveToConfigFile(mrpt::config::CConfigFileBase& c,
                                              const std::string& s) const {
  const auto& t = tracker;
  const auto& g = tracker.corners;
  FT_WRITE(t.max_features, "max_features", "features per frame: tracked + new corners");
  FT_WRITE(g.min_distance_px, "min_distance_px", "px; minimum spacing between any two features");
  FT_WRITE(g.quality_level, "quality_level",
           "Shi-Tomasi: keep corners with min eigenvalue >= this * the best of their cell");
  FT_WRITE(g.min_eigenvalue, "min_eigenvalue",
           "Shi-Tomasi: and >= this on the scored level (cornerMinEigenVal units; noise "
           "peaks ~6e-5 at corner_level 1, ~4e-4 at 0: use ~1e-3 there)");
  FT_WRITE(g.block_size, "block_size", "px; Shi-Tomasi gradient covariance window");
  FT_WRITE(g.grid_cols, "grid_cols", "grid cells across; new corners go to the emptiest first");
  FT_WRITE(g.grid_rows, "grid_rows", "grid cells down");
  FT_WRITE(g.border_px, "border_px", "px; no new corner this close to the image edge");
  FT_WRITE(g.level, "corner_level",
           "score corners on this KLT pyramid level (0 full resolution, 1 half: 4x cheaper)");
  FT_WRITE(t.klt_window_px, "klt_window_px", "px; KLT window side (odd)");
  FT_WRITE(t.klt_pyramid_levels, "klt_pyramid_levels",
           "KLT pyramid levels above the image when the flow is not predicted");
  FT_WRITE(t.klt_predicted_levels, "klt_predicted_levels",
           "KLT pyramid levels when the flow is predicted (gyro or previous motion)");
  FT_WRITE(t.klt_max_iterations, "klt_max_iterations", "KLT iterations per pyramid level");
  FT_WRITE(t.klt_epsilon, "klt_epsilon", "px; KLT stops when an update moves less");
  FT_WRITE(t.max_fb_error_px, "max_fb_error_px",
           "px; forward-backward check: tracked back, a point must land this close");
  FT_WRITE(t.max_klt_residual_ratio, "max_klt_residual_ratio",
           "not the method: drop a track whose KLT residual (mean absolute grey difference over "
           "the window) is above this times the frame's median (0: off)");
  core::writeKey(
      c, s, "residual_gate_region", toString(t.residual_gate_region),
      "where the residual gate applies: near_nonrigid (tracks outside the masks near a non-rigid "
      "object's box) or everywhere");
  FT_WRITE(t.residual_gate_margin_px, "residual_gate_margin_px",
           "px around a non-rigid object's box within which near_nonrigid gates");
  FT_WRITE(t.occlusion_edge.radius_px, "occlusion_edge_radius_px",
           "not the method: px; no track or new corner where a nearer surface (by the gap "
           "below) lies this close: it would follow that surface's silhouette (0: off)");
  FT_WRITE(t.occlusion_edge.min_gap_m, "occlusion_edge_min_gap_m",
           "m; a surface nearer by more than max(this, occlusion_edge_gap_ratio x depth) is an "
           "occluding edge");
  FT_WRITE(t.occlusion_edge.gap_ratio, "occlusion_edge_gap_ratio",
           "the occluding edge's depth gap relative to the pixel's depth");
  FT_WRITE(t.occlusion_edge_objects_only, "occlusion_edge_objects_only",
           "only the object masks' readings count as the nearer surface (false: any reading)");
  FT_WRITE(t.depth_edge_radius_px, "depth_edge_radius_px",
           "not the method: px; the estimator leaves out a feature's depth where a reading "
           "nearer or farther by the occlusion edge's gap, or none, lies this close (0: off)");
  core::writeKey(c, s, "flow_init", toString(t.flow_init),
          "KLT start: gyro (rotation K R K^-1; previous_motion without gyro samples), "
          "previous_motion (constant velocity per point) or none");
  FT_WRITE(t.fundamental_ransac, "fundamental_ransac",
           "RANSAC on the fundamental matrix over features outside every object mask");
  FT_WRITE(t.fundamental_threshold_px, "fundamental_threshold_px",
           "px; RANSAC inlier distance to the epipolar line");
  FT_WRITE(t.fundamental_confidence, "fundamental_confidence", "RANSAC confidence in (0, 1)");
}

void FeatureTrackingStage::configure(const core::IniConfig& cfg, const std::string& section) {
  try {
    core::loadOptionsStrict(options_, cfg, section);
    tracker_.emplace(options_.tracker);
  } catch (const std::invalid_argument& e) {
    throw core::ConfigError("[" + section + "] " + e.what() + " (in " + cfg.source() + ")");
  }
}

void FeatureTrackingStage::process(core::Frame& frame) {
  frame.features = tracker_->track(frame);
  const auto& s = tracker_->lastStats();
  ++frames_;
  features_ += frame.features.size();
  detected_ += size_t(s.detected);
  gyroFrames_ += s.gyro_used;
  incoming_ += size_t(s.incoming);
  lostKlt_ += size_t(s.lost_klt);
  lostFb_ += size_t(s.lost_fb);
  lostResidual_ += size_t(s.lost_residual);
  lostRansac_ += size_t(s.lost_ransac);
  lostOcclusion_ += size_t(s.lost_occlusion);
  trackingMs_.push_back(s.ms_pyramid + s.ms_klt + s.ms_ransac);
  extractionMs_.push_back(s.ms_detect);
  std::map<std::int64_t, int> alive;
  for (const auto& f : frame.features) alive.emplace(f.id, f.track_length);
  for (const auto& [id, length] : alive_)
    if (!alive.count(id)) {
      endedLengthSum_ += length;
      ++ended_;
    }
  alive_ = std::move(alive);
}

void FeatureTrackingStage::finish() {
  for (const auto& [id, length] : alive_) {
    endedLengthSum_ += length;
    ++ended_;
  }
  alive_.clear();
  MRPT_LOG_INFO_STREAM(frames_ << " frames, " << (frames_ ? features_ / frames_ : 0)
                               << " features per frame, " << detected_ << " corners detected, "
                               << gyroFrames_ << " frames with gyro-predicted flow, mean track "
                               << (ended_ ? endedLengthSum_ / double(ended_) : 0) << " frames");
}

std::vector<std::pair<std::string, double>> FeatureTrackingStage::statistics() const {
  const double in = double(std::max<size_t>(incoming_, 1));
  return {{"frames", double(frames_)},
          {"features_per_frame", frames_ ? double(features_) / double(frames_) : 0},
          {"corners_detected", double(detected_)},
          {"gyro_frames", double(gyroFrames_)},
          {"mean_track_length", ended_ ? endedLengthSum_ / double(ended_) : 0},
          {"lost_klt_fraction", double(lostKlt_) / in},
          {"lost_forward_backward_fraction", double(lostFb_) / in},
          {"lost_residual_fraction", double(lostResidual_) / in},
          {"lost_ransac_fraction", double(lostRansac_) / in},
          {"lost_occlusion_edge_fraction", double(lostOcclusion_) / in},
          {"tracking_ms_median", core::upperMedian(trackingMs_)},
          {"extraction_ms_median", core::upperMedian(extractionMs_)}};
}

}  // namespace dynslam::frontend
