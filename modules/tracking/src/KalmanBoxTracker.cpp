// KalmanBoxTracker: prediction, update()'s phases and the lifecycle of one track. The rounds
// are in KalmanBoxTrackerAssociation.cpp (depth IoU) and KalmanBoxTrackerIdentity.cpp
// (appearance, identities, revival).
#include "dynslam/tracking/KalmanBoxTracker.h"

#include "DepthSurfaces.h"

#include <algorithm>
#include <cmath>

namespace dynslam::tracking {

KalmanBoxTracker::KalmanBoxTracker(KalmanBoxTrackerParams params) : params_(std::move(params)) {}

void KalmanBoxTracker::predict(double t) {
  const double dt = clock_set_ ? t - last_t_ : 0.0;
  if (!clock_set_ || dt > 0) {
    last_t_ = t;
    clock_set_ = true;
  }
  for (auto& tr : tracked_) {
    tr.track.detection = -1;
    tr.match = TrackMatch::None;
    if (dt <= 0) continue;
    const BoxState& x = tr.filter.state();
    // While coasting the box keeps its size and depth: over more than a few frames a linear
    // extrapolation of the area goes badly wrong (people turn round, boxes are clipped at the image
    // border), and a shrinking box is never re-associated. SORT only stops it from turning
    // negative. Measured: docs/notes/perception.md, 2026-11-28 (coasting).
    if (tr.track.misses > 0 || x(kS) + dt * x(kRateS) <= 0) tr.filter.stopAreaRate();
    if (tr.track.misses > 0) tr.filter.stopDepthRate();  // likewise for the depth
    tr.filter.predict(dt, processNoise(params_.noise, tr.filter.state(), dt));
  }
}

void KalmanBoxTracker::update(const std::vector<BoxObservation>& input, const cv::Size& image) {
  const std::vector<BoxObservation> observations = withUsableAlternatives(input, image);
  Association a{std::vector<int>(tracked_.size(), -1), std::vector<char>(observations.size(), 0)};
  for (auto& tr : tracked_) {
    tr.match = TrackMatch::None;
    tr.described_now = false;
  }
  associateByDepthIoU(observations, image, a);
  // givenAnothersSurface, for the keys that read it.
  std::vector<char> anothers(observations.size(), 0);
  if (params_.reid_at_track_depth > 0 || params_.descriptor_own_surface)
    for (size_t j = 0; j < observations.size(); ++j)
      anothers[j] = givenAnothersSurface(observations, j);
  if (params_.reid_max_distance > 0) reidentify(observations, anothers, a);
  noteRound(a.observationOf, TrackMatch::Appearance);
  const std::vector<char> othersSurface =
      params_.descriptor_own_surface ? onOthersSurface(observations, a.observationOf, anothers)
                                     : std::vector<char>(observations.size(), 0);
  const std::vector<size_t> toRevive =
      updateTracks(observations, a.observationOf, othersSurface, image);
  checkAndRepairIdentities();
  reviveIdentities(toRevive);
  for (size_t j = 0; j < observations.size(); ++j)
    if (!a.observationUsed[j]) startTrack(observations[j], int(j));
}

/// Matched tracks take their observation, unmatched ones count a miss and are dropped once
/// lost. Returns the indices in tracked_ of the tracks to try the revival for.
std::vector<size_t> KalmanBoxTracker::updateTracks(const std::vector<BoxObservation>& observations,
                                                   const std::vector<int>& observationOf,
                                                   const std::vector<char>& othersSurface,
                                                   const cv::Size& image) {
  std::vector<Tracked> kept;
  kept.reserve(tracked_.size() + observations.size());
  std::vector<size_t> toRevive;
  for (size_t i = 0; i < tracked_.size(); ++i) {
    Tracked& tr = tracked_[i];
    const int j = observationOf[i];
    if (j >= 0) {
      if (takeObservation(tr, observations, size_t(j), othersSurface[j], image))
        toRevive.push_back(kept.size());
      kept.push_back(std::move(tr));
    } else if (!missed(tr, image)) {
      kept.push_back(std::move(tr));
    }
  }
  tracked_ = std::move(kept);
  return toRevive;
}

/// `tr` takes observations[j]: filter update, descriptor (a whole view on its own surface),
/// hits and state. True when the revival is to be tried for it: confirmed now or before, and
/// with a descriptor (a track confirmed without one waits for its first).
bool KalmanBoxTracker::takeObservation(Tracked& tr, const std::vector<BoxObservation>& observations,
                                       size_t j, bool onOthersSurface, const cv::Size& image) {
  const BoxObservation& o = observations[j];
  BoxMeasurementCovariance R;
  const BoxMeasurement z = measurementFor(tr, o.box, depthFor(tr, o), R);
  tr.filter.update(z, R);
  if (params_.reset_at_border) restartCutComponents(tr.filter, o.box, z, image);
  tr.track.detection = int(j);
  if (!o.appearance.empty() && !onOthersSurface &&
      (tr.appearance.empty() || !occluded(observations, j)))
    takeDescriptor(tr, o.appearance);
  ++tr.track.hits;
  tr.track.misses = 0;
  const bool confirmedNow =
      tr.track.state != core::TrackState::Confirmed && tr.track.hits >= params_.min_hits;
  if (tr.track.hits >= params_.min_hits) tr.track.state = core::TrackState::Confirmed;
  tr.revival_pending = confirmedNow || tr.revival_pending;
  const bool revive = tr.revival_pending && !tr.appearance.empty();
  if (revive) tr.revival_pending = false;
  return revive;
}

/// `tr` took no observation: true when it is lost now (then counted and, with reid_memory,
/// remembered if it was a confirmed track with a descriptor).
bool KalmanBoxTracker::missed(Tracked& tr, const cv::Size& image) {
  ++tr.track.misses;
  if (!loseAfterMiss(tr, image)) return false;
  ++lost_;
  if (remembers() && tr.track.state == core::TrackState::Confirmed && !tr.appearance.empty())
    remembered_.push_back(
        {tr.track.id, tr.track.category, tr.appearance, last_t_, tr.identity, tr.identity_views});
  return true;
}

/// The measurement of a matched observation: box and the depth `depth` (<= 0: none), or, when
/// depth_gate holds it, the box with the track's own depth as unknown. The gate holds a
/// confirmed track's depth when `depth` is more than depth_gate off the last depth the track
/// took, and farther than a person walking at depth_gate_speed could have gone since, for up to
/// depth_gate_frames frames in a row; then the measurement counts again, so a track that is
/// itself on a wrong surface comes back.
BoxMeasurement KalmanBoxTracker::measurementFor(Tracked& tr, const cv::Rect2f& box, double depth,
                                                BoxMeasurementCovariance& R) const {
  const double predicted = tr.filter.state()(kD);
  // The jump is measured from the last depth the track took, not from its prediction: the
  // prediction runs on with the depth rate, and a person who turns round (0.04 m a frame
  // towards the camera, then away) soon differs from it by more than the gate, which then held
  // the depth on the wrong side until the track was lost (docs/notes/perception.md, 2026-11-28,
  // depth_gate).
  const double reference = tr.last_depth > 0 ? tr.last_depth : predicted;
  // depth_gate_speed: how far the person may have walked since the track last took a depth.
  const double walked =
      tr.last_depth > 0 ? params_.depth_gate_speed * (last_t_ - tr.last_depth_t) : 0.0;
  const bool gated =
      params_.depth_gate > 0 && depth > 0 && reference > 0 &&
      tr.track.state == core::TrackState::Confirmed &&
      std::abs(depth - reference) > std::max(params_.depth_gate * reference, walked) &&
      tr.depth_gated < params_.depth_gate_frames;
  tr.depth_gated = gated ? tr.depth_gated + 1 : 0;
  if (depth > 0 && !gated) {
    tr.last_depth = depth;
    tr.last_depth_t = last_t_;
  }
  BoxMeasurement z = boxMeasurement(box, gated ? 0.0 : depth);
  R = measurementNoise(params_.noise, z);        // a gated depth: the variance of an unknown one
  if (!(depth > 0) || gated) z(kD) = predicted;  // no depth, or held: leave d as it is
  return z;
}

/// reset_at_border: on a box touching the image border, restarts the filter's area, aspect ratio
/// and the cut axis' centre from the measurement, with zero rates (the next prediction is the
/// box as seen).
void KalmanBoxTracker::restartCutComponents(KalmanBoxFilter& filter, const cv::Rect2f& box,
                                            const BoxMeasurement& z, const cv::Size& image) const {
  if (image.empty()) return;
  constexpr float kTouch = 1.0f;  // px: detectors clip to the image, jitter may leave a pixel
  const bool cutX = box.x <= kTouch || box.x + box.width >= image.width - kTouch;
  const bool cutY = box.y <= kTouch || box.y + box.height >= image.height - kTouch;
  if (!cutX && !cutY) return;
  const BoxCovariance P0 = initialCovariance(params_.noise, z);
  filter.restartFrom({kS, kR}, z, P0);
  if (cutX) filter.restartFrom({kU}, z, P0);
  if (cutY) filter.restartFrom({kV}, z, P0);
}

/// True when the unmatched track `t` is to be dropped now: Tentative, coasting longer than
/// max_age, or with less than half of its predicted box inside the image.
bool KalmanBoxTracker::loseAfterMiss(const Tracked& t, const cv::Size& image) const {
  if (t.track.state != core::TrackState::Confirmed) return true;
  if (t.track.misses > params_.max_age) return true;
  if (image.empty()) return false;
  const cv::Rect2f box = t.filter.box();
  const double inside = (box & cv::Rect2f(0, 0, float(image.width), float(image.height))).area();
  return !(inside >= 0.5 * box.area() && box.area() > 0);
}

void KalmanBoxTracker::startTrack(const BoxObservation& observation, int index) {
  const BoxMeasurement z = boxMeasurement(observation.box, observation.depth);
  Tracked t{core::Track{}, KalmanBoxFilter(initialState(z), initialCovariance(params_.noise, z))};
  t.track.id = next_id_++;
  t.last_depth = observation.depth;
  t.last_depth_t = last_t_;
  t.track.state = params_.min_hits <= 1 ? core::TrackState::Confirmed : core::TrackState::Tentative;
  t.track.category = observation.category;
  t.track.model = observation.model;
  t.track.detection = index;
  t.track.hits = 1;
  t.match = TrackMatch::Started;
  tracked_.push_back(std::move(t));
}

/// Records `round` as the match of the tracks given an observation since the last call.
void KalmanBoxTracker::noteRound(const std::vector<int>& observationOf, TrackMatch round) {
  for (size_t i = 0; i < tracked_.size(); ++i)
    if (observationOf[i] >= 0 && tracked_[i].match == TrackMatch::None) tracked_[i].match = round;
}

std::vector<TrackMatch> KalmanBoxTracker::matches() const {
  std::vector<TrackMatch> out;
  out.reserve(tracked_.size());
  for (const auto& tr : tracked_) out.push_back(tr.match);
  return out;
}

std::vector<core::Track> KalmanBoxTracker::tracks() const {
  std::vector<core::Track> out;
  out.reserve(tracked_.size());
  for (const auto& tr : tracked_) {
    core::Track t = tr.track;
    t.box = tr.filter.box();
    t.depth = tr.filter.state()(kD);
    out.push_back(std::move(t));
  }
  return out;
}

}  // namespace dynslam::tracking
