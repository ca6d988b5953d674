#include "dynslam/frontend/FeatureTrackingStage.h"

#include "dynslam/core/Median.h"

#include <algorithm>
#include <stdexcept>

namespace dynslam::frontend {
namespace {

constexpr core::Keyword<FlowInit> kFlowInits[] = {{"gyro", FlowInit::Gyro},
                                                  {"previous_motion", FlowInit::PreviousMotion},
                                                  {"none", FlowInit::None}};
constexpr core::Keyword<ResidualGateRegion> kGateRegions[] = {
    {"near_nonrigid", ResidualGateRegion::NearNonRigid},
    {"everywhere", ResidualGateRegion::Everywhere}};

/// The corner detector's keys (GridCornerParams).
void describeCorners(core::OptionVisitor& v, GridCornerParams& c) {
  using core::Range;
  const Range off = Range::atLeast(0), atLeast1 = Range::atLeast(1);
  const Range openUnit{0, 1, true, true}, level = Range::closed(0, 8);
  v.key("min_distance_px", c.min_distance_px, atLeast1,
        "px; minimum spacing between any two features");
  v.key("quality_level", c.quality_level, openUnit,
        "Shi-Tomasi: keep corners with min eigenvalue >= this * the best of their cell");
  v.key("min_eigenvalue", c.min_eigenvalue, off,
        "Shi-Tomasi: and >= this on the scored level (cornerMinEigenVal units; noise peaks "
        "~6e-5 at corner_level 1, ~4e-4 at 0: use ~1e-3 there)");
  v.key("block_size", c.block_size, atLeast1, "px; Shi-Tomasi gradient covariance window");
  v.key("grid_cols", c.grid_cols, atLeast1,
        "grid cells across; new corners go to the emptiest first");
  v.key("grid_rows", c.grid_rows, atLeast1, "grid cells down");
  v.key("border_px", c.border_px, off, "px; no new corner this close to the image edge");
  v.key("corner_level", c.level, level,
        "score corners on this KLT pyramid level, <= klt_pyramid_levels (0 full resolution, 1 "
        "half: 4x cheaper)");
}

}  // namespace

void FeatureTrackingOptions::describe(core::OptionVisitor& v) {
  using core::Range;
  auto& t = tracker;
  auto& e = tracker.occlusion_edge;
  const Range off = Range::atLeast(0), positive = Range::above(0), atLeast1 = Range::atLeast(1);
  const Range openUnit{0, 1, true, true}, level = Range::closed(0, 8);
  v.key("max_features", t.max_features, atLeast1, "features per frame: tracked + new corners");
  describeCorners(v, t.corners);
  v.key("klt_window_px", t.klt_window_px, Range::atLeast(3), "px; KLT window side (odd)");
  v.key("klt_pyramid_levels", t.klt_pyramid_levels, level,
        "KLT pyramid levels above the image when the flow is not predicted");
  v.key("klt_predicted_levels", t.klt_predicted_levels, level,
        "KLT pyramid levels when the flow is predicted (gyro or previous motion), <= "
        "klt_pyramid_levels");
  v.key("max_fb_error_px", t.max_fb_error_px, positive,
        "px; forward-backward check: tracked back, a point must land this close");
  v.key("max_klt_residual_ratio", t.max_klt_residual_ratio, off,
        "0 = off, else >= 1; not the method: drop a track whose KLT residual (mean absolute grey "
        "difference over the window) is above this times the frame's median");
  v.key("residual_gate_region", t.residual_gate_region, kGateRegions,
        "where the residual gate applies: near_nonrigid (tracks outside the masks near a "
        "non-rigid object's box) or everywhere");
  v.key("residual_gate_margin_px", t.residual_gate_margin_px, off,
        "px around a non-rigid object's box within which near_nonrigid gates");
  v.key("occlusion_edge_radius_px", e.radius_px, off,
        "0 = off; not the method: px; no track or new corner where a nearer surface (by the gap "
        "below) lies this close: it would follow that surface's silhouette");
  v.key("occlusion_edge_min_gap_m", e.min_gap_m, positive,
        "m; a surface nearer by more than max(this, occlusion_edge_gap_ratio x depth) is an "
        "occluding edge");
  v.key("occlusion_edge_gap_ratio", e.gap_ratio, off,
        "the occluding edge's depth gap relative to the pixel's depth");
  v.key("occlusion_edge_objects_only", t.occlusion_edge_objects_only,
        "only the object masks' readings count as the nearer surface (false: any reading)");
  v.key("depth_edge_radius_px", t.depth_edge_radius_px, off,
        "0 = off; not the method: px; the estimator leaves out a feature's depth where a reading "
        "nearer or farther by the occlusion edge's gap, or none, lies this close");
  v.key("flow_init", t.flow_init, kFlowInits,
        "KLT start: gyro (rotation K R K^-1; previous_motion without gyro samples), "
        "previous_motion (constant velocity per point) or none");
  v.key("fundamental_ransac", t.fundamental_ransac,
        "RANSAC on the fundamental matrix over features outside every object mask");
  v.key("fundamental_threshold_px", t.fundamental_threshold_px, positive,
        "px; RANSAC inlier distance to the epipolar line");
  v.key("fundamental_confidence", t.fundamental_confidence, openUnit, "RANSAC confidence");
}

void FeatureTrackingStage::configure(const core::IniConfig& cfg, const std::string& section) {
  core::loadOptionsStrict(options_, cfg, section);
  try {
    tracker_.emplace(options_.tracker);
  } catch (const std::invalid_argument& e) {  // a rule between keys (FeatureTracker)
    throw core::ConfigError("[" + section + "] in " + cfg.source() + ": " + e.what());
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
  trackingMs_.add(s.ms_pyramid + s.ms_klt + s.ms_ransac);
  extractionMs_.add(s.ms_detect);
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
          {"tracking_ms_median", core::upperMedian(trackingMs_.samples())},
          {"extraction_ms_median", core::upperMedian(extractionMs_.samples())}};
}

}  // namespace dynslam::frontend
