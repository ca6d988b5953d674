// KalmanBoxTracker: the appearance cue (not the method; Appearance.h): the appearance round,
// the tracks' descriptors, identity checks and the revival of remembered ids.
#include "dynslam/tracking/KalmanBoxTracker.h"

#include "AssignmentRound.h"
#include "DepthSurfaces.h"
#include "dynslam/tracking/Appearance.h"

#include <algorithm>
#include <cmath>

namespace dynslam::tracking {
namespace {

// A view farther from an identity than this is someone else's or an occluded one: views of one
// person one frame apart lie well within it (docs/notes/perception.md, 2026-11-28,
// identity_check).
constexpr double kConsistentWithIdentity = 0.35;

// The appearance round's reach, in box heights: a person re-found by colour has walked on while
// hidden, but not across the image. 1 and 2 measured the same as 1.5 (docs/notes/perception.md,
// 2026-11-28, removed keys).
constexpr double kReidMaxShift = 1.5;

// A track's running descriptor keeps this weight on the old at each view: it follows the person
// seen within a few frames (0.6-0.95 measured no better; docs/notes/perception.md, 2026-11-28,
// removed keys).
constexpr double kAppearanceMemory = 0.8;

}  // namespace

/// reid_max_distance > 0: the appearance round. A confirmed track still unmatched that was
/// already coasting takes an unmatched detection of its category whose descriptor is closer
/// than reid_max_distance, whose centre lies within kReidMaxShift box heights of the
/// prediction and whose depth within a factor 1.5 of the track's; best appearance first. A
/// track matched on the frame before coasts one frame first: a person of similar colours
/// stepping out from behind it as the detector missed it would take its id.
/// `onAnothersSurface`: givenAnothersSurface per observation (read with reid_at_track_depth).
void KalmanBoxTracker::reidentify(const std::vector<BoxObservation>& observations,
                                  const std::vector<char>& onAnothersSurface,
                                  Association& a) const {
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
        const bool near = std::hypot(shift.x, shift.y) <= kReidMaxShift * height;
        return distance < params_.reid_max_distance && depthAgrees && near ? 1.0 - distance : 0.0;
      },
      a.observationOf, a.observationUsed);
}

/// The appearance distance of a track's descriptor `a` (the track at `depth`) to observation
/// `o`: to o's own descriptor, or with reid_at_track_depth the smaller of that and the one to
/// o's colours at `depth` when below reid_at_track_depth; `atDepth` tells whether the latter
/// decided (the depth factor is then waived). Not in the revival: there a new track's box that
/// hid a coasting person took that person's identity.
double KalmanBoxTracker::reidDistance(const cv::Mat& a, double depth, const BoxObservation& o,
                                      bool& atDepth) const {
  const double own = appearanceDistance(a, o.appearance);
  atDepth = false;
  if (!(params_.reid_at_track_depth > 0) || !(depth > 0) || !o.appearance_at) return own;
  const double there = appearanceDistance(a, o.appearance_at(depth));
  atDepth = there < params_.reid_at_track_depth && there < own;
  return atDepth ? there : own;
}

/// descriptor_own_surface: per observation, whether its depth is the surface of another
/// observation (`others` on entry: givenAnothersSurface per observation) or of another track
/// seen on the last frame or coasting since then (kRecentMisses) whose predicted box covers
/// more than a fifth of the observation's, depths within 15 %, given the association so far.
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

/// `descriptor` (a matched observation's) updates tr's running descriptor (kAppearanceMemory on
/// the old) and, with identity_check, its identity.
void KalmanBoxTracker::takeDescriptor(Tracked& tr, const cv::Mat& descriptor) const {
  tr.appearance = tr.appearance.empty()
                      ? descriptor.clone()
                      : kAppearanceMemory * tr.appearance + (1 - kAppearanceMemory) * descriptor;
  tr.described_now = true;
  if (params_.identity_check > 0) updateIdentity(tr, descriptor);
}

/// identity_check: `descriptor` (a view the running descriptor took) updates the track's slow
/// identity descriptor when it lies within kConsistentWithIdentity of it, and counts as an
/// inconsistent view otherwise.
void KalmanBoxTracker::updateIdentity(Tracked& tr, const cv::Mat& descriptor) const {
  // The identity follows slow changes of a person's colours (turning, lighting) over tens of
  // frames; the running descriptor (kAppearanceMemory) over a few.
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

/// identity_check, then identity_repair for the confirmed tracks described this frame whose
/// last identity_repair views were all inconsistent with their identity.
void KalmanBoxTracker::checkAndRepairIdentities() {
  if (!(params_.identity_check > 0)) return;
  checkIdentities();
  if (params_.identity_repair > 0)
    for (size_t i = 0; i < tracked_.size(); ++i)
      if (tracked_[i].described_now && tracked_[i].track.state == core::TrackState::Confirmed &&
          tracked_[i].inconsistent_views >= params_.identity_repair)
        repairIdentity(i);
}

/// identity_check: swaps the ids (and identity descriptors) of two confirmed tracks described
/// this frame when each one's running descriptor is nearer the other's identity, summed over the
/// two, by more than identity_check.
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

/// identity_repair: tracked_[index] takes the remembered lost id whose identity lies within
/// kConsistentWithIdentity of its running descriptor and nearer it than its own identity by
/// identity_check; its old id and identity are remembered in their place, for its person's next
/// new track to be revived into.
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

/// reid_memory: forgets the tracks lost more than reid_memory ago, revives `confirmed`
/// (indices in tracked_) and removes the coasting tracks a revival took the id of.
void KalmanBoxTracker::reviveIdentities(const std::vector<size_t>& confirmed) {
  if (!remembers()) return;
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

int KalmanBoxTracker::closestRemembered(
    const Tracked& t, const std::function<const cv::Mat&(const Remembered&)>& descriptorOf,
    double& best) const {
  // The index in remembered_ of the entry of t's category whose descriptor (`descriptorOf` the
  // entry) lies nearest t's running descriptor, if nearer than `best` (then lowered); else -1.
  int found = -1;
  for (size_t k = 0; k < remembered_.size(); ++k) {
    const Remembered& r = remembered_[k];
    if (r.category != t.track.category) continue;
    const double d = appearanceDistance(descriptorOf(r), t.appearance);
    if (d < best) best = d, found = int(k);
  }
  return found;
}

/// reid_memory: tracked_[index] (just confirmed, or confirmed before and given its first
/// descriptor now) takes the id of the remembered or coasting confirmed track of closest
/// appearance, when closer than reid_max_distance, wherever it is; that one is forgotten (a
/// coasting one is marked Lost, to be removed by the caller).
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
    tracked_[coasting].track.state = core::TrackState::Lost;  // removed by reviveIdentities
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

}  // namespace dynslam::tracking
