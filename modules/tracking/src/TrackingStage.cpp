#include "dynslam/tracking/TrackingStage.h"

#include "dynslam/tracking/Appearance.h"

#include <mrpt/config/CConfigFileBase.h>

namespace dynslam::tracking {
namespace {

// One ini key per field; the key is the field's name without the struct prefix.
#define TRACKING_READ(type, field, key) field = c.read_##type(s, key, field)
#define TRACKING_WRITE(field, key, comment) core::writeKey(c, s, key, field, comment)

void requirePositive(double value, const char* key, const std::string& section,
                     const std::string& source) {
  if (!(value > 0))
    throw core::ConfigError("[" + section + "] " + key + " = " + std::to_string(value) + " in " +
                            source + ": must be > 0");
}

}  // namespace

void TrackingOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& c,
                                         const std::string& s) {
  auto& t = tracker;
  auto& n = tracker.noise;
  TRACKING_READ(double, t.rho_min, "rho_min");
  TRACKING_READ(double, t.rho_min_coasting, "rho_min_coasting");
  TRACKING_READ(int, t.max_age, "max_age");
  TRACKING_READ(int, t.min_hits, "min_hits");
  t.reset_at_border = core::readBool(c, s, "reset_at_border", t.reset_at_border);
  TRACKING_READ(double, t.reid_max_distance, "reid_max_distance");
  TRACKING_READ(double, t.reid_max_shift, "reid_max_shift");
  TRACKING_READ(double, t.appearance_memory, "appearance_memory");
  TRACKING_READ(double, t.reid_memory, "reid_memory");
  TRACKING_READ(double, t.reid_at_track_depth, "reid_at_track_depth");
  t.descriptor_own_surface =
      core::readBool(c, s, "descriptor_own_surface", t.descriptor_own_surface);
  TRACKING_READ(double, t.identity_check, "identity_check");
  TRACKING_READ(int, t.identity_repair, "identity_repair");
  t.alternative_depth = core::readBool(c, s, "alternative_depth", t.alternative_depth);
  t.alternative_depth_tracks =
      core::readBool(c, s, "alternative_depth_tracks", t.alternative_depth_tracks);
  TRACKING_READ(double, t.depth_gate, "depth_gate");
  TRACKING_READ(int, t.depth_gate_frames, "depth_gate_frames");
  TRACKING_READ(double, t.depth_gate_speed, "depth_gate_speed");
  TRACKING_READ(double, t.innovation_gate, "innovation_gate");
  TRACKING_READ(int, t.revival_takes_identity, "revival_takes_identity");
  TRACKING_READ(double, n.meas_center_px, "meas_center_px");
  TRACKING_READ(double, n.meas_area_rel, "meas_area_rel");
  TRACKING_READ(double, n.meas_depth_rel, "meas_depth_rel");
  TRACKING_READ(double, n.meas_ratio, "meas_ratio");
  TRACKING_READ(double, n.accel_center_px, "accel_center_px");
  TRACKING_READ(double, n.accel_area_rel, "accel_area_rel");
  TRACKING_READ(double, n.accel_depth, "accel_depth");
  TRACKING_READ(double, n.ratio_walk, "ratio_walk");
  TRACKING_READ(double, n.init_rate_center_px, "init_rate_center_px");
  TRACKING_READ(double, n.init_rate_area_rel, "init_rate_area_rel");
  TRACKING_READ(double, n.init_rate_depth, "init_rate_depth");
}

void TrackingOptions::saveToConfigFile(mrpt::config::CConfigFileBase& c,
                                       const std::string& s) const {
  const auto& t = tracker;
  const auto& n = tracker.noise;
  TRACKING_WRITE(t.rho_min, "rho_min", "accept a track-detection pair only if depth IoU > this");
  TRACKING_WRITE(t.rho_min_coasting, "rho_min_coasting",
                 "2nd round for coasting tracks above this; >= rho_min: none (paper)");
  TRACKING_WRITE(t.max_age, "max_age", "detector frames a confirmed track coasts unmatched");
  TRACKING_WRITE(t.min_hits, "min_hits", "matched frames that confirm a new track");
  TRACKING_WRITE(t.reset_at_border, "reset_at_border",
                 "boxes cut by the image border restart size and cut centre (not the method)");
  TRACKING_WRITE(t.reid_max_distance, "reid_max_distance",
                 "> 0: coasting tracks re-found by colour histogram below this (not the method)");
  TRACKING_WRITE(t.reid_max_shift, "reid_max_shift", "box heights; re-finding's reach");
  TRACKING_WRITE(t.appearance_memory, "appearance_memory",
                 "weight of a track's colour histogram against a new detection's");
  TRACKING_WRITE(t.reid_memory, "reid_memory",
                 "s; with reid: a new track takes a lost or coasting track's id by colour");
  TRACKING_WRITE(
      t.reid_at_track_depth, "reid_at_track_depth",
      "0 = off; with reid: a coasting track also takes a detection given another's "
      "surface whose colours at the track's depth are closer than this (not the method)");
  TRACKING_WRITE(t.descriptor_own_surface, "descriptor_own_surface",
                 "with reid: a track's colours only from detections on their own surface, not "
                 "another detection's or recent track's (not the method)");
  TRACKING_WRITE(t.identity_check, "identity_check",
                 "0 = off; with reid: two tracks whose recent colours each match the other's "
                 "slow identity descriptor better by more than this swap ids (not the method)");
  TRACKING_WRITE(t.identity_repair, "identity_repair",
                 "0 = off; with identity_check: a track this many views in a row off its "
                 "identity takes the lost id whose identity it matches (not the method)");
  TRACKING_WRITE(t.alternative_depth, "alternative_depth",
                 "match by the nearer of the mask's two cluster depths where the chosen "
                 "one is another detection's surface, or the other is nearer and nobody's "
                 "(not the method)");
  TRACKING_WRITE(t.alternative_depth_tracks, "alternative_depth_tracks",
                 "with alternative_depth: also where the chosen depth is the surface of a "
                 "recent track overlapping the box that cannot be its own (not the method)");
  TRACKING_WRITE(t.depth_gate, "depth_gate",
                 "0 = off; a confirmed track ignores a matched depth this fraction off the "
                 "last depth it took (the box still counts; not the method)");
  TRACKING_WRITE(t.depth_gate_frames, "depth_gate_frames",
                 "frames in a row depth_gate may hold a track's depth");
  TRACKING_WRITE(t.depth_gate_speed, "depth_gate_speed",
                 "m/s, 0 = off; depth_gate also lets through a depth a person walking this fast "
                 "could have reached since the track last took one (not the method)");
  TRACKING_WRITE(t.innovation_gate, "innovation_gate",
                 "0 = off; refuse a pair whose box centre's squared Mahalanobis distance from "
                 "the prediction exceeds this (chi-square, 2 dof; not the method)");
  TRACKING_WRITE(t.revival_takes_identity, "revival_takes_identity",
                 "0 = off; with identity_check, an id whose identity descriptor took at least "
                 "this many views is compared by it in the revival and keeps it when revived "
                 "(not the method)");
  TRACKING_WRITE(n.meas_center_px, "meas_center_px", "px; sigma of the measured box centre");
  TRACKING_WRITE(n.meas_area_rel, "meas_area_rel", "sigma of the measured area / area");
  TRACKING_WRITE(n.meas_depth_rel, "meas_depth_rel", "sigma of the measured depth / depth");
  TRACKING_WRITE(n.meas_ratio, "meas_ratio", "sigma of the measured aspect ratio w/h");
  TRACKING_WRITE(n.accel_center_px, "accel_center_px", "px/s^2/sqrt(Hz); centre acceleration");
  TRACKING_WRITE(n.accel_area_rel, "accel_area_rel", "1/s^2/sqrt(Hz); area accel. / area");
  TRACKING_WRITE(n.accel_depth, "accel_depth", "m/s^2/sqrt(Hz); depth acceleration");
  TRACKING_WRITE(n.ratio_walk, "ratio_walk", "1/sqrt(s); random walk of the aspect ratio");
  TRACKING_WRITE(n.init_rate_center_px, "init_rate_center_px", "px/s; new track's centre rate");
  TRACKING_WRITE(n.init_rate_area_rel, "init_rate_area_rel", "1/s; new track's area rate / area");
  TRACKING_WRITE(n.init_rate_depth, "init_rate_depth", "m/s; new track's depth rate sigma");
}

void TrackingStage::configure(const core::IniConfig& cfg, const std::string& section) {
  core::loadOptionsStrict(options_, cfg, section);
  const auto& t = options_.tracker;
  const auto& n = t.noise;
  if (!(t.rho_min >= 0 && t.rho_min < 1))
    throw core::ConfigError("[" + section + "] rho_min = " + std::to_string(t.rho_min) + " in " +
                            cfg.source() + ": must be in [0, 1)");
  if (!(t.rho_min_coasting >= 0 && t.rho_min_coasting < 1))
    throw core::ConfigError("[" + section +
                            "] rho_min_coasting = " + std::to_string(t.rho_min_coasting) + " in " +
                            cfg.source() + ": must be in [0, 1)");
  if (t.max_age < 0)
    throw core::ConfigError("[" + section + "] max_age = " + std::to_string(t.max_age) + " in " +
                            cfg.source() + ": must be >= 0");
  if (!(t.reid_memory >= 0))
    throw core::ConfigError("[" + section + "] reid_memory = " + std::to_string(t.reid_memory) +
                            " in " + cfg.source() + ": must be >= 0 (s; 0: no memory)");
  if (t.min_hits < 1)
    throw core::ConfigError("[" + section + "] min_hits = " + std::to_string(t.min_hits) + " in " +
                            cfg.source() + ": must be >= 1");
  if (t.identity_repair < 0)
    throw core::ConfigError("[" + section +
                            "] identity_repair = " + std::to_string(t.identity_repair) + " in " +
                            cfg.source() + ": must be >= 0 (views; 0: off)");
  if (t.revival_takes_identity < 0)
    throw core::ConfigError("[" + section + "] revival_takes_identity = " +
                            std::to_string(t.revival_takes_identity) + " in " + cfg.source() +
                            ": must be >= 0 (views; 0: off)");
  if (!(t.depth_gate_speed >= 0))
    throw core::ConfigError("[" + section +
                            "] depth_gate_speed = " + std::to_string(t.depth_gate_speed) + " in " +
                            cfg.source() + ": must be >= 0 (m/s; 0: off)");
  if (t.depth_gate_frames < 0)
    throw core::ConfigError("[" + section +
                            "] depth_gate_frames = " + std::to_string(t.depth_gate_frames) +
                            " in " + cfg.source() + ": must be >= 0");
  const std::pair<double, const char*> unitInterval[] = {
      {t.reid_max_distance, "reid_max_distance"},
      {t.appearance_memory, "appearance_memory"},
      {t.depth_gate, "depth_gate"},
      {t.reid_at_track_depth, "reid_at_track_depth"}};
  for (const auto& [value, key] : unitInterval)
    if (!(value >= 0 && value <= 1))
      throw core::ConfigError("[" + section + "] " + key + " = " + std::to_string(value) + " in " +
                              cfg.source() + ": must be in [0, 1]");
  if (!(t.identity_check >= 0 && t.identity_check <= 2))
    throw core::ConfigError("[" + section +
                            "] identity_check = " + std::to_string(t.identity_check) + " in " +
                            cfg.source() + ": must be in [0, 2] (a sum of two distances; 0: off)");
  if (!(t.innovation_gate >= 0))
    throw core::ConfigError("[" + section +
                            "] innovation_gate = " + std::to_string(t.innovation_gate) + " in " +
                            cfg.source() + ": must be >= 0 (0: off)");
  const std::pair<double, const char*> positive[] = {{t.reid_max_shift, "reid_max_shift"},
                                                     {n.meas_center_px, "meas_center_px"},
                                                     {n.meas_area_rel, "meas_area_rel"},
                                                     {n.meas_depth_rel, "meas_depth_rel"},
                                                     {n.meas_ratio, "meas_ratio"},
                                                     {n.accel_center_px, "accel_center_px"},
                                                     {n.accel_area_rel, "accel_area_rel"},
                                                     {n.accel_depth, "accel_depth"},
                                                     {n.ratio_walk, "ratio_walk"},
                                                     {n.init_rate_center_px, "init_rate_center_px"},
                                                     {n.init_rate_area_rel, "init_rate_area_rel"},
                                                     {n.init_rate_depth, "init_rate_depth"}};
  for (const auto& [value, key] : positive) requirePositive(value, key, section, cfg.source());
  tracker_ = KalmanBoxTracker(t);
}

void TrackingStage::process(core::Frame& frame) {
  ++frames_;
  tracker_.predict(frame.t);
  if (frame.detections_fresh) {
    ++detectorFrames_;
    const auto& p = tracker_.params();
    const bool usesAppearance = p.reid_max_distance > 0;
    std::vector<BoxObservation> observations;
    observations.reserve(frame.detections.size());
    for (size_t i = 0; i < frame.detections.size(); ++i)
      observations.push_back(observeDetection(frame, i, usesAppearance));
    if (usesAppearance && p.reid_at_track_depth > 0)
      for (size_t i = 0; i < observations.size(); ++i)
        observations[i].appearance_at = [rgb = frame.rgb, depth = frame.depth,
                                         box = frame.detections[i].box](double d) {
          return bodyHistogram(rgb, box, depth, d);
        };
    const cv::Size image = !frame.rgb.empty() ? frame.rgb.size() : frame.depth.size();
    tracker_.update(observations, image);
  }
  frame.tracks = tracker_.tracks();
  // Link each detection's mask to the track that took the detection, for later stages.
  for (auto& mask : frame.object_masks) {
    mask.track = -1;
    for (size_t i = 0; i < frame.tracks.size(); ++i)
      if (mask.detection >= 0 && frame.tracks[i].detection == mask.detection) mask.track = int(i);
  }
}

void TrackingStage::finish() {
  MRPT_LOG_INFO_STREAM(frames_ << " frames (" << detectorFrames_ << " with fresh detections), "
                               << tracker_.tracksStarted() << " tracks started, "
                               << tracker_.tracksLost() << " lost, " << tracker_.tracksRevived()
                               << " revived, " << tracker_.identitiesSwapped()
                               << " pairs of ids swapped back, " << tracker_.identitiesRepaired()
                               << " ids repaired");
}

}  // namespace dynslam::tracking
