#include "dynslam/tracking/TrackingStage.h"

#include "dynslam/tracking/Appearance.h"

namespace dynslam::tracking {

namespace {

using core::Range;

/// The depth-IoU association and the tracks' lifecycle (method.md section 2), and the gates on it.
void describeAssociation(core::OptionVisitor& v, KalmanBoxTrackerParams& t) {
  v.key("rho_min", t.rho_min, Range::closedOpen(0, 1),
        "accept a track-detection pair only if depth IoU > this");
  v.key("rho_min_coasting", t.rho_min_coasting, Range::closedOpen(0, 1),
        "2nd round for coasting tracks above this, below rho_min; the default (>= rho_min): "
        "none, as the paper");
  v.key("max_age", t.max_age, Range::atLeast(0),
        "detector frames a confirmed track coasts unmatched");
  v.key("min_hits", t.min_hits, Range::atLeast(1), "matched frames that confirm a new track");
  v.key("reset_at_border", t.reset_at_border,
        "boxes cut by the image border restart size and cut centre (not the method)");
  v.key("innovation_gate", t.innovation_gate, Range::atLeast(0),
        "0 = off; refuse a pair whose box centre's squared Mahalanobis distance from the "
        "prediction exceeds this (chi-square, 2 dof; not the method)");
}

/// The appearance cue (Appearance.h): re-finding, revival and identity checks.
void describeAppearance(core::OptionVisitor& v, KalmanBoxTrackerParams& t) {
  const Range unit = Range::closed(0, 1), off = Range::atLeast(0);
  v.key("reid_max_distance", t.reid_max_distance, unit,
        "> 0: coasting tracks re-found by colour histogram below this (not the method)");
  v.key("reid_memory", t.reid_memory, off,
        "s; with reid: a new track takes a lost or coasting track's id by colour");
  v.key("reid_at_track_depth", t.reid_at_track_depth, unit,
        "0 = off; with reid: a coasting track also takes a detection given another's surface "
        "whose colours at the track's depth are closer than this (not the method)");
  v.key("descriptor_own_surface", t.descriptor_own_surface,
        "with reid: a track's colours only from detections on their own surface, not another "
        "detection's or recent track's (not the method)");
  v.key("identity_check", t.identity_check, Range::closedOpen(0, 2),
        "0 = off; with reid: two tracks whose recent colours each match the other's slow "
        "identity descriptor better by more than this swap ids (not the method)");
  v.key("identity_repair", t.identity_repair, off,
        "0 = off; with identity_check: a track this many views in a row off its identity "
        "takes the lost id whose identity it matches (not the method)");
  v.key("revival_takes_identity", t.revival_takes_identity, off,
        "0 = off; with identity_check, an id whose identity descriptor took at least this many "
        "views is compared by it in the revival and keeps it when revived (not the method)");
}

/// Which depth a track takes from a matched detection.
void describeDepth(core::OptionVisitor& v, KalmanBoxTrackerParams& t) {
  v.key("alternative_depth", t.alternative_depth,
        "match by the nearer of the mask's two cluster depths where the chosen one is another "
        "detection's surface, or the other is nearer and nobody's (not the method)");
  v.key("alternative_depth_tracks", t.alternative_depth_tracks,
        "with alternative_depth: also where the chosen depth is the surface of a recent track "
        "overlapping the box that cannot be its own (not the method)");
  v.key("depth_gate", t.depth_gate, Range::closed(0, 1),
        "0 = off; a confirmed track ignores a matched depth this fraction off the last depth it "
        "took (the box still counts; not the method)");
  v.key("depth_gate_frames", t.depth_gate_frames, Range::atLeast(1),
        "frames in a row depth_gate may hold a track's depth");
  v.key("depth_gate_speed", t.depth_gate_speed, Range::atLeast(0),
        "m/s, 0 = off; depth_gate also lets through a depth a person walking this fast could "
        "have reached since the track last took one (not the method)");
}

/// The box filter's noise (BoxNoiseModel.h): R, Q and a new track's P.
void describeNoise(core::OptionVisitor& v, BoxNoiseParams& n) {
  const Range positive = Range::above(0);
  v.key("meas_center_px", n.meas_center_px, positive, "px; sigma of the measured box centre");
  v.key("meas_area_rel", n.meas_area_rel, positive, "sigma of the measured area / area");
  v.key("meas_depth_rel", n.meas_depth_rel, positive, "sigma of the measured depth / depth");
  v.key("meas_ratio", n.meas_ratio, positive, "sigma of the measured aspect ratio w/h");
  v.key("accel_center_px", n.accel_center_px, positive, "px/s^2/sqrt(Hz); centre acceleration");
  v.key("accel_area_rel", n.accel_area_rel, positive, "1/s^2/sqrt(Hz); area accel. / area");
  v.key("accel_depth", n.accel_depth, positive, "m/s^2/sqrt(Hz); depth acceleration");
  v.key("ratio_walk", n.ratio_walk, positive, "1/sqrt(s); random walk of the aspect ratio");
  v.key("init_rate_center_px", n.init_rate_center_px, positive, "px/s; new track's centre rate");
  v.key("init_rate_area_rel", n.init_rate_area_rel, positive, "1/s; new track's area rate / area");
  v.key("init_rate_depth", n.init_rate_depth, positive, "m/s; new track's depth rate sigma");
}

/// Settings that act only through another: set alone, they would silently do nothing. A setting
/// whose off value is not 0 counts as set when it differs from its default.
void describeRequirements(core::OptionVisitor& v, const KalmanBoxTrackerParams& t) {
  const KalmanBoxTrackerParams defaults;
  v.requires("rho_min_coasting", t.rho_min_coasting != defaults.rho_min_coasting,
             "rho_min > rho_min_coasting", t.rho_min_coasting < t.rho_min);
  const bool reid = t.reid_max_distance > 0;
  v.requires("reid_memory", t.reid_memory > 0, "reid_max_distance > 0", reid);
  v.requires("reid_at_track_depth", t.reid_at_track_depth > 0, "reid_max_distance > 0", reid);
  v.requires("descriptor_own_surface", t.descriptor_own_surface, "reid_max_distance > 0", reid);
  v.requires("identity_check", t.identity_check > 0, "reid_max_distance > 0", reid);
  v.requires("identity_repair", t.identity_repair > 0, "identity_check > 0 and reid_memory > 0",
             t.identity_check > 0 && t.reid_memory > 0);
  v.requires("revival_takes_identity", t.revival_takes_identity > 0,
             "identity_check > 0 and reid_memory > 0", t.identity_check > 0 && t.reid_memory > 0);
  v.requires("alternative_depth_tracks", t.alternative_depth_tracks, "alternative_depth = true",
             t.alternative_depth);
  v.requires("depth_gate_frames", t.depth_gate_frames != defaults.depth_gate_frames,
             "depth_gate > 0", t.depth_gate > 0);
  v.requires("depth_gate_speed", t.depth_gate_speed > 0, "depth_gate > 0", t.depth_gate > 0);
}

}  // namespace

void TrackingOptions::describe(core::OptionVisitor& v) {
  describeAssociation(v, tracker);
  describeAppearance(v, tracker);
  describeDepth(v, tracker);
  describeNoise(v, tracker.noise);
  describeRequirements(v, tracker);
}

void TrackingStage::configure(const core::IniConfig& cfg, const std::string& section) {
  core::loadOptionsStrict(options_, cfg, section);
  tracker_ = KalmanBoxTracker(options_.tracker);
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
