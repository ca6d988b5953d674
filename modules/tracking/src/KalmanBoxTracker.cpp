#include "dynslam/tracking/KalmanBoxTracker.h"

#include <dynslam/core/HungarianAssignment.h>
#include "dynslam/tracking/Appearance.h"
#include "dynslam/tracking/DepthIoU.h"

#include <Eigen/Cholesky>

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

namespace {

/// True when more than a fifth of `box` lies inside `other`: enough of another object in a box
/// to show in its descriptor.
bool coveredBy(const cv::Rect2f& box, const cv::Rect2f& other) {
  return (other & box).area() > 0.2f * box.area();
}

/// True when more than a fifth of observation j's box is covered by the box of a nearer
/// observation: its descriptor then shows a part of the object only (the occluder's pixels are
/// left out by the depth band, Appearance.h), and a track's descriptor is updated from whole
/// views only.
bool occluded(const std::vector<BoxObservation>& observations, size_t j) {
  const BoxObservation& o = observations[j];
  for (size_t k = 0; k < observations.size(); ++k) {
    const BoxObservation& n = observations[k];
    if (k == j || !(n.depth > 0 && o.depth > 0 && n.depth < o.depth)) continue;
    if (coveredBy(o.box, n.box)) return true;
  }
  return false;
}

// Tracks seen on one of the last this many frames count as a surface on this one
// (descriptor_own_surface, alternative_depth_tracks). A track coasting longer has a drifting
// prediction, and the person it lost is the likeliest one standing there. Measured:
// docs/notes/perception.md, 2026-11-28 (descriptor_own_surface).
constexpr int kRecentMisses = 1;

// Cluster means of one surface measured in two boxes agree within a few per cent; two people a
// pace apart differ by 20 % and more (docs/notes/perception.md, 2026-11-28, surfaces).
constexpr double kSameSurfaceRatio = 0.85;

/// True when `depth` is the surface at `surface` (m): within kSameSurfaceRatio of it and nearer
/// it than `otherDepth`.
bool isSurface(double surface, double depth, double otherDepth) {
  const double same = core::depthRatio(surface, depth);
  return same >= kSameSurfaceRatio && same > core::depthRatio(surface, otherDepth);
}

/// True when `depth` is the surface of another observation whose box overlaps observation j's
/// (isSurface of its d_t).
bool surfaceOfAnother(const std::vector<BoxObservation>& observations, size_t j, double depth,
                      double otherDepth) {
  for (size_t k = 0; k < observations.size(); ++k) {
    const BoxObservation& n = observations[k];
    if (k == j || !(n.depth > 0) || (n.box & observations[j].box).area() <= 0) continue;
    if (isSurface(n.depth, depth, otherDepth)) return true;
  }
  return false;
}

/// A track's predicted box clipped to `image` (when given), as detectors clip theirs.
cv::Rect2f clippedToImage(const cv::Rect2f& box, const cv::Size& image) {
  return image.empty() ? box : box & cv::Rect2f(0, 0, float(image.width), float(image.height));
}

}  // namespace

bool givenAnothersSurface(const std::vector<BoxObservation>& observations, size_t j) {
  return observations[j].depth > 0 && surfaceOfAnother(observations, j, observations[j].depth, 0.0);
}

namespace {

/// A recent track's predicted box and depth: a surface a detection may have been given.
struct TrackSurface {
  cv::Rect2f box;
  double depth = 0;
};

/// alternative_depth_tracks: true when `depth` (of a detection's `box`) is the surface of one of
/// `tracks` (isSurface of its depth) whose box overlaps
/// the detection's, as surfaceOfAnother asks of detections, but too little to be its own track
/// (box IoU <= maxOwnIoU, so its depth IoU cannot pass rho_min): the occluder of a partly
/// hidden person whose own detection the detector missed on this frame. (Asking the track's
/// box to cover a fifth of the detection's, as onOthersSurface does, gained less:
/// docs/notes/perception.md, 2026-11-28, alternative_depth_tracks.)
bool surfaceOfTrack(const std::vector<TrackSurface>& tracks, const cv::Rect2f& box, double depth,
                    double otherDepth, double maxOwnIoU) {
  for (const TrackSurface& t : tracks) {
    if ((t.box & box).area() <= 0 || boxIoU(t.box, box) > maxOwnIoU) continue;
    if (isSurface(t.depth, depth, otherDepth)) return true;
  }
  return false;
}

/// The observations with d_alt kept only where a track may take it: where the cluster the
/// segmentation chose is another detection's surface (a partly hidden person given its
/// occluder's depth), or where d_alt is the nearer cluster and nobody else's (a person given the
/// wall behind it). Otherwise a track whose depth had once gone to the wrong surface kept taking
/// that surface through d_alt and never came back (docs/notes/perception.md, 2026-11-28,
/// alternative_depth).
std::vector<BoxObservation> withOwnedAlternatives(std::vector<BoxObservation> observations,
                                                  const std::vector<TrackSurface>& tracks,
                                                  double maxOwnIoU) {
  // surfaceOfAnother reads the others' d_t only: d_alt can be cleared as the loop goes.
  for (size_t j = 0; j < observations.size(); ++j) {
    BoxObservation& o = observations[j];
    if (!(o.depth > 0 && o.depth_alt > 0)) continue;
    const bool usable =
        surfaceOfAnother(observations, j, o.depth, o.depth_alt) ||
        surfaceOfTrack(tracks, o.box, o.depth, o.depth_alt, maxOwnIoU) ||
        (o.depth_alt < o.depth && !surfaceOfAnother(observations, j, o.depth_alt, o.depth));
    if (!usable) o.depth_alt = 0;
  }
  return observations;
}

/// One assignment round: the tracks `trackTakes` admits that have no observation yet against the
/// observations `observationTakes` admits that are not used yet, by the Hungarian algorithm on
/// `gain(track, observation)` (0: the pair is refused; pairs of different categories always
/// are), a pair kept when its gain is > 0.
template <class Tracks, class TrackTakes, class ObservationTakes, class Gain>
void assignRound(const Tracks& tracked, const std::vector<BoxObservation>& observations,
                 TrackTakes trackTakes, ObservationTakes observationTakes, Gain gain,
                 std::vector<int>& observationOf, std::vector<char>& observationUsed) {
  std::vector<int> rows, cols;
  for (size_t i = 0; i < tracked.size(); ++i)
    if (observationOf[i] < 0 && trackTakes(tracked[i])) rows.push_back(int(i));
  for (size_t j = 0; j < observations.size(); ++j)
    if (!observationUsed[j] && observationTakes(observations[j])) cols.push_back(int(j));
  if (rows.empty() || cols.empty()) return;
  Eigen::MatrixXd g = Eigen::MatrixXd::Zero(rows.size(), cols.size());
  for (size_t r = 0; r < rows.size(); ++r)
    for (size_t c = 0; c < cols.size(); ++c) {
      const BoxObservation& o = observations[cols[c]];
      if (o.category == tracked[rows[r]].track.category) g(r, c) = gain(tracked[rows[r]], o);
    }
  const std::vector<int> assigned = core::solveMaxGainAssignment(g);
  for (size_t r = 0; r < rows.size(); ++r)
    if (assigned[r] >= 0 && g(r, assigned[r]) > 0) {
      observationOf[rows[r]] = cols[assigned[r]];
      observationUsed[cols[assigned[r]]] = 1;
    }
}

}  // namespace

double KalmanBoxTracker::depthFor(const Tracked& tr, const BoxObservation& o) const {
  const double d = tr.filter.state()(kD);
  if (!params_.alternative_depth || !(o.depth_alt > 0) || !(o.depth > 0) || !(d > 0))
    return o.depth;
  return core::depthRatio(o.depth_alt, d) > core::depthRatio(o.depth, d) ? o.depth_alt : o.depth;
}

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

double KalmanBoxTracker::centreInnovation2(const Tracked& tr, const cv::Rect2f& predicted,
                                           const cv::Rect2f& box) const {
  // The centres (u, v) as the filter measures them.
  const Eigen::Vector2d y =
      boxMeasurement(box, 0).head<2>() - boxMeasurement(predicted, 0).head<2>();
  const double r = params_.noise.meas_center_px;
  const Eigen::Matrix2d S =
      tr.filter.covariance().block<2, 2>(kU, kU) + r * r * Eigen::Matrix2d::Identity();
  return y.dot(S.llt().solve(y));
}

void KalmanBoxTracker::associate(const std::vector<BoxObservation>& observations,
                                 const cv::Size& image, double threshold, bool coastingOnly,
                                 std::vector<int>& observationOf,
                                 std::vector<char>& observationUsed) const {
  assignRound(
      tracked_, observations,
      [&](const Tracked& tr) { return !coastingOnly || tr.track.misses > 0; },
      [](const BoxObservation&) { return true; },
      [&](const Tracked& tr, const BoxObservation& o) {
        // Detectors clip their boxes to the image: compare like with like.
        const cv::Rect2f predicted = clippedToImage(tr.filter.box(), image);
        const double value = depthIoU(predicted, tr.filter.state()(kD), o.box, depthFor(tr, o));
        if (!(value > threshold)) return 0.0;
        return params_.innovation_gate > 0 &&
                       centreInnovation2(tr, predicted, o.box) > params_.innovation_gate
                   ? 0.0
                   : value;
      },
      observationOf, observationUsed);
}

std::vector<char> KalmanBoxTracker::onOthersSurface(const std::vector<BoxObservation>& observations,
                                                    const std::vector<int>& observationOf,
                                                    std::vector<char> others) const {
  for (size_t j = 0; j < observations.size(); ++j) {
    const BoxObservation& o = observations[j];
    if (!(o.depth > 0)) continue;
    for (size_t i = 0; i < tracked_.size() && !others[j]; ++i) {
      const Tracked& tr = tracked_[i];
      const double d = tr.filter.state()(kD);
      others[j] = observationOf[i] != int(j) && tr.track.misses <= kRecentMisses && d > 0 &&
                  core::depthRatio(d, o.depth) >= kSameSurfaceRatio &&
                  coveredBy(o.box, tr.filter.box());
    }
  }
  return others;
}

namespace {

// A view farther from an identity than this is someone else's or an occluded one: views of one
// person one frame apart lie well within it (docs/notes/perception.md, 2026-11-28, identity_check).
constexpr double kConsistentWithIdentity = 0.35;

}  // namespace

void KalmanBoxTracker::updateIdentity(Tracked& tr, const cv::Mat& descriptor) const {
  // The identity follows slow changes of a person's colours (turning, lighting) over tens of
  // frames; the running descriptor (appearance_memory 0.8) over a few.
  constexpr double kIdentityMemory = 0.95;
  if (tr.identity.empty()) {
    tr.identity = descriptor.clone();
    tr.identity_views = 1;
  } else if (appearanceDistance(tr.identity, descriptor) < kConsistentWithIdentity) {
    tr.identity = kIdentityMemory * tr.identity + (1 - kIdentityMemory) * descriptor;
    ++tr.identity_views;
    tr.inconsistent_views = 0;
  } else {
    ++tr.inconsistent_views;
  }
}

void KalmanBoxTracker::repairIdentity(size_t index) {
  Tracked& t = tracked_[index];
  t.inconsistent_views = 0;
  // Only lost ids: giving a track a coasting track's id (whose person is likelier just hidden
  // than on this track) lost more than it won (docs/notes/perception.md, 2026-11-28,
  // identity_repair). With identity_check every remembered track has an identity: a track's first
  // descriptor starts it (updateIdentity), and only described tracks are remembered.
  double best = std::min(kConsistentWithIdentity,
                         appearanceDistance(t.identity, t.appearance) - params_.identity_check);
  const int found = closestRemembered(
      t, [](const Remembered& r) -> const cv::Mat& { return r.identity; }, best);
  if (found < 0) return;
  Remembered old{t.track.id, t.track.category, t.appearance, last_t_, t.identity, t.identity_views};
  Remembered& r = remembered_[found];
  t.track.id = r.id;
  t.identity = r.identity;
  t.identity_views = r.identity_views;
  r = std::move(old);  // the id this track gives up, for its person to be revived into
  t.match = TrackMatch::Repaired;
  ++repaired_;
}

void KalmanBoxTracker::checkIdentities() {
  // Each candidate's distance of its view to its own identity, once: it enters every pair.
  std::vector<double> own(tracked_.size(), -1.0);  // < 0: not a candidate
  for (size_t i = 0; i < tracked_.size(); ++i) {
    const Tracked& t = tracked_[i];
    if (t.described_now && !t.identity.empty() && t.track.state == core::TrackState::Confirmed)
      own[i] = appearanceDistance(t.identity, t.appearance);
  }
  for (size_t a = 0; a < tracked_.size(); ++a)
    for (size_t b = a + 1; b < tracked_.size(); ++b) {
      Tracked& A = tracked_[a];
      Tracked& B = tracked_[b];
      if (own[a] < 0 || own[b] < 0 || A.track.category != B.track.category) continue;
      const double aAsB = appearanceDistance(B.identity, A.appearance);
      const double bAsA = appearanceDistance(A.identity, B.appearance);
      if (!(aAsB + bAsA + params_.identity_check < own[a] + own[b])) continue;
      std::swap(A.track.id, B.track.id);
      std::swap(A.identity, B.identity);
      std::swap(A.identity_views, B.identity_views);
      A.inconsistent_views = B.inconsistent_views = 0;  // counted against the other identity
      own[a] = aAsB;  // each view against the identity it has now, for the pairs still to come
      own[b] = bAsA;
      A.match = B.match = TrackMatch::Swapped;
      ++swapped_;
    }
}

void KalmanBoxTracker::update(const std::vector<BoxObservation>& input, const cv::Size& image) {
  std::vector<TrackSurface> recent;  // alternative_depth_tracks' surfaces
  if (params_.alternative_depth && params_.alternative_depth_tracks)
    for (const Tracked& tr : tracked_)
      if (tr.track.misses <= kRecentMisses && tr.filter.state()(kD) > 0)
        recent.push_back({clippedToImage(tr.filter.box(), image), tr.filter.state()(kD)});
  const std::vector<BoxObservation> observations =
      params_.alternative_depth ? withOwnedAlternatives(input, recent, params_.rho_min) : input;
  std::vector<int> observationOf(tracked_.size(), -1);
  std::vector<char> observationUsed(observations.size(), 0);
  for (auto& tr : tracked_) {
    tr.match = TrackMatch::None;
    tr.described_now = false;
  }
  associate(observations, image, params_.rho_min, false, observationOf, observationUsed);
  noteRound(observationOf, TrackMatch::Overlap);
  if (params_.rho_min_coasting < params_.rho_min)
    associate(observations, image, params_.rho_min_coasting, true, observationOf, observationUsed);
  noteRound(observationOf, TrackMatch::CoastingOverlap);
  // givenAnothersSurface, for the keys that read it.
  std::vector<char> anothers(observations.size(), 0);
  if (params_.reid_at_track_depth > 0 || params_.descriptor_own_surface)
    for (size_t j = 0; j < observations.size(); ++j)
      anothers[j] = givenAnothersSurface(observations, j);
  if (params_.reid_max_distance > 0)
    reidentify(observations, anothers, observationOf, observationUsed);
  noteRound(observationOf, TrackMatch::Appearance);
  const std::vector<char> othersSurface =
      params_.descriptor_own_surface ? onOthersSurface(observations, observationOf, anothers)
                                     : std::vector<char>(observations.size(), 0);

  std::vector<Tracked> kept;
  kept.reserve(tracked_.size() + observations.size());
  std::vector<size_t> confirmed;  // indices in `kept` of the tracks to try the revival for
  for (size_t i = 0; i < tracked_.size(); ++i) {
    Tracked& tr = tracked_[i];
    const int j = observationOf[i];
    if (j >= 0) {
      const BoxObservation& o = observations[j];
      BoxMeasurementCovariance R;
      const BoxMeasurement z = measurementFor(tr, o.box, depthFor(tr, o), R);
      tr.filter.update(z, R);
      if (params_.reset_at_border) restartCutComponents(tr.filter, o.box, z, image);
      tr.track.detection = j;
      if (!o.appearance.empty() && !othersSurface[j] &&
          (tr.appearance.empty() || !occluded(observations, j))) {
        tr.appearance = tr.appearance.empty() ? o.appearance.clone()
                                              : params_.appearance_memory * tr.appearance +
                                                    (1 - params_.appearance_memory) * o.appearance;
        tr.described_now = true;
        if (params_.identity_check > 0) updateIdentity(tr, o.appearance);
      }
      ++tr.track.hits;
      tr.track.misses = 0;
      const bool confirmedNow =
          tr.track.state != core::TrackState::Confirmed && tr.track.hits >= params_.min_hits;
      if (tr.track.hits >= params_.min_hits) tr.track.state = core::TrackState::Confirmed;
      // The revival compares descriptors: a track confirmed without one waits for its first.
      tr.revival_pending = confirmedNow || tr.revival_pending;
      const bool revive = tr.revival_pending && !tr.appearance.empty();
      if (revive) tr.revival_pending = false;
      kept.push_back(std::move(tr));
      if (revive) confirmed.push_back(kept.size() - 1);
      continue;
    }
    ++tr.track.misses;
    if (loseAfterMiss(tr, image)) {
      ++lost_;
      if (remembers() && tr.track.state == core::TrackState::Confirmed && !tr.appearance.empty())
        remembered_.push_back({tr.track.id, tr.track.category, tr.appearance, last_t_, tr.identity,
                               tr.identity_views});
      continue;
    }
    kept.push_back(std::move(tr));
  }
  tracked_ = std::move(kept);
  if (params_.identity_check > 0) checkIdentities();
  if (params_.identity_check > 0 && params_.identity_repair > 0)
    for (size_t i = 0; i < tracked_.size(); ++i)
      if (tracked_[i].described_now && tracked_[i].track.state == core::TrackState::Confirmed &&
          tracked_[i].inconsistent_views >= params_.identity_repair)
        repairIdentity(i);
  if (remembers()) {
    remembered_.erase(std::remove_if(remembered_.begin(), remembered_.end(),
                                     [&](const Remembered& r) {
                                       return last_t_ - r.lost_at > params_.reid_memory;
                                     }),
                      remembered_.end());
    for (size_t i : confirmed) reviveIdentity(i);
    tracked_.erase(
        std::remove_if(tracked_.begin(), tracked_.end(),
                       [](const Tracked& t) { return t.track.state == core::TrackState::Lost; }),
        tracked_.end());
  }
  for (size_t j = 0; j < observations.size(); ++j)
    if (!observationUsed[j]) startTrack(observations[j], int(j));
}

double KalmanBoxTracker::reidDistance(const cv::Mat& a, double depth, const BoxObservation& o,
                                      bool& atDepth) const {
  const double own = appearanceDistance(a, o.appearance);
  atDepth = false;
  if (!(params_.reid_at_track_depth > 0) || !(depth > 0) || !o.appearance_at) return own;
  const double there = appearanceDistance(a, o.appearance_at(depth));
  atDepth = there < params_.reid_at_track_depth && there < own;
  return atDepth ? there : own;
}

void KalmanBoxTracker::reidentify(const std::vector<BoxObservation>& observations,
                                  const std::vector<char>& onAnothersSurface,
                                  std::vector<int>& observationOf,
                                  std::vector<char>& observationUsed) const {
  assignRound(
      tracked_, observations,
      [](const Tracked& tr) {
        return !tr.appearance.empty() && tr.track.state == core::TrackState::Confirmed &&
               tr.track.misses > 0;
      },
      [](const BoxObservation& o) { return !o.appearance.empty(); },
      [&](const Tracked& tr, const BoxObservation& o) {
        const cv::Rect2f predicted = tr.filter.box();
        const double depth = tr.filter.state()(kD);
        // The colours at the track's depth count only for a detection given another's
        // surface: otherwise its depth is its own, and a box with something at the track's
        // depth is one that hides the track's person (docs/notes/perception.md, 2026-11-28,
        // reid_at_track_depth).
        bool atDepth = false;
        const size_t j = size_t(&o - observations.data());
        const double distance = onAnothersSurface[j]
                                    ? reidDistance(tr.appearance, depth, o, atDepth)
                                    : appearanceDistance(tr.appearance, o.appearance);
        const cv::Point2f shift =
            (o.box.tl() + o.box.br()) * 0.5f - (predicted.tl() + predicted.br()) * 0.5f;
        const double height = std::max(o.box.height, predicted.height);
        const bool depthAgrees = atDepth || !(depth > 0 && o.depth > 0) ||
                                 std::max(depth, o.depth) < 1.5 * std::min(depth, o.depth);
        const bool near = std::hypot(shift.x, shift.y) <= params_.reid_max_shift * height;
        return distance < params_.reid_max_distance && depthAgrees && near ? 1.0 - distance : 0.0;
      },
      observationOf, observationUsed);
}

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

int KalmanBoxTracker::closestRemembered(
    const Tracked& t, const std::function<const cv::Mat&(const Remembered&)>& descriptorOf,
    double& best) const {
  int found = -1;
  for (size_t k = 0; k < remembered_.size(); ++k) {
    const Remembered& r = remembered_[k];
    if (r.category != t.track.category) continue;
    const double d = appearanceDistance(descriptorOf(r), t.appearance);
    if (d < best) best = d, found = int(k);
  }
  return found;
}

void KalmanBoxTracker::reviveIdentity(size_t index) {
  Tracked& t = tracked_[index];
  if (t.appearance.empty()) return;
  // revival_takes_identity: an id whose identity took enough views is that identity: it is what
  // the new track is compared with, and it goes with the id, as on a swap or a repair.
  auto established = [&](const cv::Mat& identity, int views) {
    return params_.revival_takes_identity > 0 && !identity.empty() &&
           views >= params_.revival_takes_identity;
  };
  auto describedAs = [&](const cv::Mat& running, const cv::Mat& identity,
                         int views) -> const cv::Mat& {
    return established(identity, views) ? identity : running;
  };
  double best = params_.reid_max_distance;
  int coasting = -1;
  int remembered = closestRemembered(
      t,
      [&](const Remembered& r) -> const cv::Mat& {
        return describedAs(r.appearance, r.identity, r.identity_views);
      },
      best);
  for (size_t k = 0; k < tracked_.size(); ++k) {
    const Tracked& o = tracked_[k];
    if (k == index || o.track.state != core::TrackState::Confirmed || o.track.misses == 0 ||
        o.track.category != t.track.category || o.appearance.empty())
      continue;
    const double d =
        appearanceDistance(describedAs(o.appearance, o.identity, o.identity_views), t.appearance);
    if (d < best) best = d, coasting = int(k), remembered = -1;
  }
  auto takeIdentity = [&](const cv::Mat& identity, int views) {
    if (!established(identity, views)) return;
    t.identity = identity;
    t.identity_views = views;
    t.inconsistent_views = 0;  // counted against the identity it had
  };
  if (coasting >= 0) {
    t.track.id = tracked_[coasting].track.id;
    takeIdentity(tracked_[coasting].identity, tracked_[coasting].identity_views);
    tracked_[coasting].track.state = core::TrackState::Lost;  // removed by update()
  } else if (remembered >= 0) {
    t.track.id = remembered_[remembered].id;
    takeIdentity(remembered_[remembered].identity, remembered_[remembered].identity_views);
    remembered_.erase(remembered_.begin() + remembered);
  } else {
    return;
  }
  t.match = TrackMatch::Revived;
  ++revived_;
}

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
