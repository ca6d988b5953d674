#pragma once
// Multi-object tracking by one Kalman box filter per object (method.md section 2).
//
// Each detector frame: every track's filter predicts to the frame's time; the depth IoU rho of
// each (predicted track, detection) pair of the same category is computed; the Hungarian
// algorithm picks the assignment with the largest total rho, and a pair is accepted only if
// rho > rho_min. Matched tracks update their filter. Unmatched confirmed tracks coast (predict
// only, the box keeping its size: the area rate is held at 0 while coasting, as a linear
// extrapolation of the area over a second of hiding shrinks or blows up the box) for up to
// max_age detector frames, so an object hidden behind another keeps its ID and is taken up
// again when it reappears (paper Fig. 10); then they are Lost, as they are once less than half
// of their predicted box is inside the image. Unmatched detections start Tentative tracks,
// Confirmed after min_hits matched frames; a Tentative track that misses a frame is dropped (a
// false positive rarely repeats at the same place and depth). IDs count up from 1 and are never
// given to another object (reid_memory, below, gives a returning object its own back).
//
// Optionally (rho_min_coasting < rho_min, not in the paper), tracks that were already coasting
// get a second round against the detections left over, accepted above rho_min_coasting: after
// a second of coasting the predicted box of a walker has drifted by a fraction of its width
// (gait, turns), and the paper's 0.7 then rejects the person it hid (bench-tracking measures
// both).
//
// Pairs at or below rho_min are removed before the assignment (their gain set to 0) rather than
// after it: otherwise maximising the total could pick two sub-threshold pairs over one good
// pair (0.69 + 0.69 > 0.8), and the good pair would be lost.
#include <dynslam/core/Perception.h>
#include <dynslam/tracking/BoxNoiseModel.h>

#include <opencv2/core/mat.hpp>
#include <opencv2/core/types.hpp>

#include <functional>
#include <string>
#include <vector>

namespace dynslam::tracking {

struct KalmanBoxTrackerParams {
  double rho_min = 0.7;  ///< accept a (track, detection) pair only if its depth IoU exceeds this
  /// A second round for tracks that were already coasting, with this (lower) threshold: their
  /// prediction drifts with the time hidden. >= rho_min: no second round (the paper's rule).
  double rho_min_coasting = 0.7;
  /// Detector frames a confirmed track coasts unmatched before it is Lost: 2 s at 30 Hz, as a
  /// person hidden for 1 s goes without detection for about 1.3 s (partly hidden before and
  /// after) and the prediction must still be there when it comes back.
  int max_age = 60;
  int min_hits = 3;  ///< matched frames (the first included) that confirm a track
  /// A detection touching the image border is cut by it: its size, aspect ratio and its centre
  /// along the cut axis follow the border, not the object's motion (a person walking out of
  /// the image shrinks to a sliver whose centre slows down and stops). The method's filter
  /// extrapolates those rates and its aspect ratio, held constant, lags: the predicted box
  /// collapses (e.g. 37 x 160 px against a 49 x 442 px detection) and the person gets a new ID
  /// every few frames along the border. true: on such a detection the filter restarts area,
  /// aspect ratio and the cut axis' centre from the measurement, with zero rates (the next
  /// prediction is the box as seen). bench-tracking, indoor_people_high, true depth, defaults
  /// otherwise: 132 -> 93 tracks started, MOTA 0.866 -> 0.898. false: the method as printed.
  bool reset_at_border = true;
  /// The appearance cue (Appearance.h; not the method, off by default). > 0: a third round
  /// after the depth-IoU ones, for the confirmed tracks still unmatched that were already
  /// coasting: an unmatched detection of the same category is taken when the descriptors
  /// (Bhattacharyya, 0..1) are closer than this, its centre lies within reid_max_shift box
  /// heights of the prediction and its depth within a factor 1.5 of the track's. Best
  /// appearance first (Hungarian). A track matched on the frame before is left to coast one
  /// frame first: when the detector misses a person just as another of similar colours steps
  /// out from behind them, taking that one swapped their identities (bench-tracking,
  /// indoor_people_high: IDF1 0.81 -> 0.88 at 0.7); a track that fails rho_min for good is
  /// taken up by reid_memory once the person's new track is confirmed.
  double reid_max_distance = 0.0;
  double reid_max_shift = 1.5;
  /// With reid_max_distance > 0, s a lost confirmed track's descriptor is remembered (not the
  /// method). A new track that becomes confirmed takes the id of the remembered track, or of a
  /// confirmed track coasting now, whose descriptor is closest to its own if closer than
  /// reid_max_distance, wherever it is: the person came back after the prediction had drifted
  /// off (people turn while hidden) or out of the image. 0: no memory.
  double reid_memory = 0.0;
  /// Not the method (0 = off): in the appearance round (reid_max_distance) a detection given
  /// another detection's surface (givenAnothersSurface) is also compared by its colours at the
  /// coasting track's depth (appearance_at); when those are closer than this, they decide and
  /// the depth factor is waived. A person stepping out from behind another is often given the
  /// occluder's depth; its descriptor then shows the occluder and the detection started a new
  /// identity. bench-tracking with the segmentation's depth, 24 seeds: IDF1 0.710 -> 0.729 at
  /// 0.5 (true depth unchanged); the whole system's camera APE moved on 6 of 18 runs, 4 worse
  /// by 9-19 %, 2 better by 4 and 24 % (README "Perception"), so the shipped inis leave it off
  /// until more runs say which way it goes. Not for reid_memory's revival:
  /// there a new track's box that hides a coasting person took that person's identity.
  double reid_at_track_depth = 0.0;
  /// Not the method: a matched detection's descriptor updates (or starts) its track's only when
  /// the detection's depth is its own surface: not another detection's (givenAnothersSurface)
  /// and not that of another track seen on the last frame or coasting since then, whose
  /// predicted box covers more than a fifth of the detection's (depths within 15 %). The
  /// descriptor is taken in the depth band of the detection's depth (Appearance.h); on another's
  /// surface it shows the other's clothes. When the detector missed a near person just as a
  /// partly hidden one stepped out beside it with its surface, the new track's first descriptor
  /// showed the near person and reid_memory's revival gave it the near person's id, whose next
  /// detection then started a new track (bench-tracking --trace, segmentation depth, seed 2,
  /// frames 587-589). Tracks coasting longer are left out: their prediction drifts, and the
  /// person they lost is the likeliest one to be standing there, whose revival the test then
  /// held up. bench-tracking, 24 seeds: IDF1 0.707 -> 0.802 with the segmentation's depth, 0.899
  /// -> 0.900 with true depth. On in params/sim_perception*.ini; off in sim_vio.ini, where the
  /// camera's APE was 9 % worse on the street (7 of 9 seeds) and unchanged indoors (README
  /// "Perception").
  bool descriptor_own_surface = false;
  /// Not the method: a detection whose segmentation had two clusters matches a track by
  /// whichever of the two depths (d_t, d_alt) gives the larger depth IoU, and updates the
  /// track's depth with that one. The cluster choice of a partly hidden person flips between
  /// the person, the occluder and the wall from frame to frame; the track's depth says which
  /// is the person. A new track starts from d_t. d_alt counts only where the chosen cluster is
  /// the surface (d_t) of another detection whose box overlaps, or where d_alt is the nearer
  /// cluster and nobody else's; otherwise a track whose depth once went to the wall or to an
  /// occluder would keep taking that surface through d_alt.
  bool alternative_depth = false;
  /// Not the method (with alternative_depth): d_alt also counts where d_t is the surface of a
  /// track seen on one of the last two frames whose predicted box overlaps the detection's
  /// but too little to be its own (box IoU <= rho_min). The occluder's detection was missed:
  /// the segmentation gave the person behind it the occluder's surface and there is no other
  /// detection to tell, so its track (depth IoU under rho_min at that depth) lost it and a new
  /// track started on the occluder's depth (bench-tracking, segmentation depth, choreography
  /// 13 seed 2, frame 123). bench-tracking, segmentation depth: IDF1 0.7209 -> 0.7300 over
  /// choreographies 2-13 x detector seeds 1-4 (32 runs better, 14 worse), 0.8429 -> 0.8508 on
  /// choreography 1 x 24 seeds; ID switches 48.1 -> 43.9 and 38.6 -> 35.4 per run. On in
  /// params/sim_perception*.ini; off in sim_vio.ini and sim_frontend.ini, where the camera's APE
  /// was not better (indoor 0.00638 -> 0.00657 m over 18 seeds, street 0.0687 -> 0.0698 m over 9;
  /// README "Perception").
  bool alternative_depth_tracks = false;
  /// Not the method (0 = off): a confirmed track's depth is not updated by a matched depth more
  /// than this fraction off the last depth it took (the box still is), for up to
  /// depth_gate_frames frames in a row; then the measurement counts again, so a track that is
  /// itself on a wrong surface comes back. A person walks a few cm between frames; a jump of tens
  /// of per cent is the segmentation taking an occluder's surface for a partly hidden person, and a
  /// track that followed it (the depth IoU still accepts the box) chose that surface again in
  /// [Retrack] for as long as the occlusion lasted.
  double depth_gate = 0.0;
  int depth_gate_frames = 5;
  /// Not the method (m/s, 0 = off; with depth_gate): the gate also lets through a depth that a
  /// person walking at this speed could have reached since the track last took a depth
  /// (depth_gate_speed x the time since), so a track that coasted while its person walked
  /// towards or away from the camera takes the person's depth again on coming back. Held
  /// there, the track's depth stayed where its person was hidden, and the next frame a
  /// neighbour's track nearer that depth took the person (bench-tracking, true depth,
  /// choreography 4 seed 2, frame 438). bench-tracking, 1.5: IDF1 with true depth 0.8786 ->
  /// 0.8937 over choreographies 2-13 x seeds 1-4 (19 better, 6 worse), 0.9286 -> 0.9381 on
  /// choreography 1 x 24 seeds; with the segmentation's depth 0.7772 -> 0.7726 and 0.8729 ->
  /// 0.8736 (the gate's surface flips pass too), so no shipped ini sets it (README "Perception").
  double depth_gate_speed = 0.0;
  /// Not the method (0 = off): a (track, detection) pair is also refused when the squared
  /// Mahalanobis distance of the detection's box centre from the track's predicted one (the
  /// filter's position covariance plus meas_center_px^2) exceeds this (chi-square, 2 degrees of
  /// freedom: 9.2 is the 99 % quantile). The depth IoU of two boxes that overlap by half says
  /// nothing of where the track was heading: when the person a track follows disappears behind
  /// another just as a third steps out beside it, the track took the third one (40 px against
  /// the way it walked, at IoU 0.6) and the two identities swapped for good. The covariance grows
  /// while a track coasts, so the gate widens with the time hidden.
  double innovation_gate = 0.0;
  /// Not the method (0 = off; needs identity_check and reid_memory): an id whose identity
  /// descriptor was built from at least this many views is that identity in the revival. A new
  /// track is compared with it (not with the old track's running descriptor, which follows
  /// whoever that track took last), and a revived track takes it with the id, as a swap and a
  /// repair already move the identity with the id; ids with younger identities are compared and
  /// revived as before, and the new track keeps its own first views as identity. A wrong revival
  /// (a track that took another person hid its own person's id: that person's new track got the
  /// other's coasting or lost id) put two identities of one person on two ids, and
  /// identity_check, which reads each id's identity, could not see the swap (bench-tracking, true
  /// depth, choreography 8 seed 4: two people on each other's ids for 400 frames; with this,
  /// swapped back at once). An identity of a few views is no identity: taking any (1) undid early
  /// mix-ups that the ids had kept consistently in mid-run, which IDF1 counts against.
  /// bench-tracking, choreographies 2-13 x detector seeds 1-4, at 10: IDF1 with the
  /// segmentation's depth 0.7300 -> 0.7772, with true depth 0.8421 -> 0.8786 (README
  /// "Perception"). On in params/sim_perception*.ini, where identity_check is; the whole-system
  /// inis have identity_check off.
  int revival_takes_identity = 0;
  /// Not the method (0 = off): each confirmed track also keeps a slow "identity" descriptor,
  /// updated (weight 0.95 on the old) only by views within distance 0.35 of it. When two
  /// confirmed tracks both take a descriptor on one frame and each one's running descriptor is
  /// nearer the other's identity, summed over the two, by more than this, their ids (and
  /// identities) are swapped: the association gave each the other's person at a crossing, and
  /// the ids go back to the people. The identity is not updated by the other person's views (too
  /// far from it), so the running descriptor, which follows the person seen within a few
  /// frames, shows the swap. Without it a swap lasted until the next crossing: one on
  /// bench-tracking's seed 6 (segmentation depth) held two people on each other's tracks for
  /// 370 frames. bench-tracking, 24 seeds, 0.1: IDF1 with the segmentation's depth 0.802 ->
  /// 0.828, with true depth 0.8995 -> 0.903.
  double identity_check = 0.0;
  /// Not the method (0 = off; needs identity_check and reid_memory > 0): a confirmed track whose
  /// last this many views in a row were all inconsistent with its identity descriptor (farther
  /// than 0.35) follows another person than the one its id was given to. When its running
  /// descriptor then lies within 0.35 of the identity of a remembered lost id, and nearer it
  /// than its own identity by identity_check, it takes that id and identity; its old id and
  /// identity are remembered in their place, for that person's next new track to be revived
  /// into. identity_check's pair test cannot undo a swap into a track whose person has a new
  /// track by now: both identities then describe that person (bench-tracking seed 17, segmentation
  /// depth: person 4 on person 1's id for 340 frames). bench-tracking, 24 seeds, 10: IDF1 with
  /// the segmentation's depth 0.828 -> 0.844, with true depth 0.903 -> 0.921, no seed worse.
  int identity_repair = 0;
  /// Weight of the track's descriptor when a matched detection updates it (running average).
  double appearance_memory = 0.8;
  BoxNoiseParams noise;
};

/// One detection as the tracker sees it.
struct BoxObservation {
  cv::Rect2f box;
  double depth = 0;  ///< object depth d, m; <= 0 when unknown (IoU alone then)
  std::string category;
  core::MotionModel model = core::MotionModel::NonRigid;
  cv::Mat appearance = {};  ///< Appearance.h descriptor; empty when not computed
  /// The descriptor the detection's box would give at another object depth (Appearance.h's
  /// depth band there); empty function: not available. Read by reid_at_track_depth only, for
  /// few detections, so computed on demand.
  std::function<cv::Mat(double depth)> appearance_at = {};
  /// Another depth the object may have (core::ObjectMask::d_alt), m; 0 = none. Used only with
  /// KalmanBoxTrackerParams::alternative_depth.
  double depth_alt = 0;
};

/// True when observation j's depth is the surface of another observation whose box overlaps its
/// own (the two depths within 15 %): a partly hidden person given the occluder's depth, or two
/// people side by side. reid_at_track_depth reads appearance_at of such observations only.
bool givenAnothersSurface(const std::vector<BoxObservation>& observations, size_t j);

/// How a track came by its observation on the last update(): a reading aid (bench-tracking
/// tallies identity switches by it), not an input to anything.
enum class TrackMatch {
  None,             ///< coasting, or after a predict() without an update()
  Overlap,          ///< the depth-IoU round (rho_min)
  CoastingOverlap,  ///< the second depth-IoU round of coasting tracks (rho_min_coasting)
  Appearance,       ///< the appearance round (reid_max_distance)
  Started,          ///< a new track started on it
  Revived,          ///< matched in any round, then given a remembered or coasting id (reid_memory)
  Swapped,          ///< matched in any round, then its id swapped with another track's
  Repaired,         ///< matched in any round, then given a lost id (identity_repair)
};

class KalmanBoxTracker {
 public:
  explicit KalmanBoxTracker(KalmanBoxTrackerParams params = {});

  /// Predicts every track to time t (s). The first call only sets the clock; a t at or before
  /// the last one predicts nothing.
  void predict(double t);

  /// Associates the observations made at the time of the last predict() with the tracks and
  /// updates them (see above). `image`, when not empty, is the image the boxes were clipped
  /// to: predicted boxes are clipped to it before the depth IoU, and a coasting track whose
  /// predicted box is less than half inside it is dropped (the object has left the view).
  void update(const std::vector<BoxObservation>& observations, const cv::Size& image = {});

  /// The live tracks (Confirmed and Tentative) after the last predict() or update(): boxes and
  /// depths from the filters (predicted while coasting, not clipped to the image), `detection`
  /// = the observation index matched by the last update(), -1 while coasting or after a
  /// predict() without an update().
  std::vector<core::Track> tracks() const;
  /// Per track, in the order of tracks(): how it came by its observation (TrackMatch).
  std::vector<TrackMatch> matches() const;

  const KalmanBoxTrackerParams& params() const { return params_; }
  int tracksStarted() const { return next_id_ - 1; }
  int tracksLost() const { return lost_; }
  /// New tracks that took a remembered or coasting track's id (reid_memory).
  int tracksRevived() const { return revived_; }
  /// Pairs of tracks whose ids identity_check swapped back.
  int identitiesSwapped() const { return swapped_; }
  /// Tracks identity_repair gave a lost id.
  int identitiesRepaired() const { return repaired_; }

 private:
  struct Tracked {
    core::Track track;  // id, state, category, model, detection, hits, misses
    KalmanBoxFilter filter;
    cv::Mat appearance = {};       // running average of the matched detections' descriptors
    int depth_gated = 0;           // frames in a row the depth gate held the depth (depth_gate)
    double last_depth = 0;         // m; the last measured depth the track took (depth_gate)
    double last_depth_t = 0;       // s; when it took it (depth_gate_speed)
    bool revival_pending = false;  // confirmed without a descriptor: reid_memory waits for one
    TrackMatch match = TrackMatch::None;  // how it came by its observation (matches())
    cv::Mat identity = {};                // identity_check: the slow descriptor (updateIdentity)
    int identity_views = 0;               // views `identity` took (revival_takes_identity)
    bool described_now = false;           // `appearance` took this update()'s detection
    int inconsistent_views = 0;           // identity_repair: views in a row far from `identity`
  };

  /// The measurement of a matched observation: box and the depth `depth` (<= 0: none), or,
  /// when depth_gate holds it, the box with the track's own depth as unknown.
  BoxMeasurement measurementFor(Tracked& tr, const cv::Rect2f& box, double depth,
                                BoxMeasurementCovariance& R) const;

  /// The depth of `o` that `tr` is compared with and updated by: o.depth, or with
  /// alternative_depth the one of o.depth and o.depth_alt nearer (in ratio) the track's depth.
  double depthFor(const Tracked& tr, const BoxObservation& o) const;
  /// One assignment round: the tracks without an observation yet (only those already coasting
  /// when `coastingOnly`) against the observations not used yet, by the Hungarian algorithm on
  /// the depth IoU, pairs accepted when rho > threshold. Predicted boxes are clipped to `image`
  /// (when given) as detections are.
  void associate(const std::vector<BoxObservation>& observations, const cv::Size& image,
                 double threshold, bool coastingOnly, std::vector<int>& observationOf,
                 std::vector<char>& observationUsed) const;
  /// Records `round` as the match of the tracks given an observation since the last call.
  void noteRound(const std::vector<int>& observationOf, TrackMatch round);
  /// innovation_gate: the squared Mahalanobis distance of `box`'s centre from `predicted`'s
  /// (the track's predicted box, clipped as the detection is).
  double centreInnovation2(const Tracked& tr, const cv::Rect2f& predicted,
                           const cv::Rect2f& box) const;
  void startTrack(const BoxObservation& observation, int index);
  /// reid_max_distance > 0: the appearance round for coasting tracks (see there);
  /// `onAnothersSurface`: givenAnothersSurface per observation (read with reid_at_track_depth).
  void reidentify(const std::vector<BoxObservation>& observations,
                  const std::vector<char>& onAnothersSurface, std::vector<int>& observationOf,
                  std::vector<char>& observationUsed) const;
  /// reset_at_border: restarts what the image border cut from the measurement (see there).
  void restartCutComponents(KalmanBoxFilter& filter, const cv::Rect2f& box, const BoxMeasurement& z,
                            const cv::Size& image) const;
  /// descriptor_own_surface: per observation, whether its depth is the surface of another
  /// observation (`onAnothersSurface`, givenAnothersSurface per observation) or of another
  /// recent track (see there), given the association so far.
  std::vector<char> onOthersSurface(const std::vector<BoxObservation>& observations,
                                    const std::vector<int>& observationOf,
                                    std::vector<char> onAnothersSurface) const;
  /// reid_memory: tracked_[index] (just confirmed, or confirmed before and given its first
  /// descriptor now) takes the id of the remembered or coasting track of closest appearance,
  /// when close enough; that one is forgotten (a coasting one is
  /// marked Lost, to be removed by the caller).
  void reviveIdentity(size_t index);
  /// identity_check: `descriptor` (a view the running descriptor took) updates the track's
  /// identity descriptor when it is consistent with it.
  void updateIdentity(Tracked& tr, const cv::Mat& descriptor) const;
  /// identity_check: swaps the ids (and identity descriptors) of two confirmed tracks described
  /// this frame whose views each match the other's identity better (see there).
  void checkIdentities();
  /// identity_repair: gives tracked_[index] the id whose identity matches it (see there).
  void repairIdentity(size_t index);
  /// The appearance distance of a track's descriptor `a` (the track at `depth`) to observation
  /// `o`: to o's own descriptor, or with reid_at_track_depth the smaller of that and the one to
  /// o's colours at `depth`; `atDepth` tells whether the latter decided.
  double reidDistance(const cv::Mat& a, double depth, const BoxObservation& o, bool& atDepth) const;
  bool remembers() const { return params_.reid_memory > 0 && params_.reid_max_distance > 0; }
  /// True when the unmatched track `t` is to be dropped now.
  bool loseAfterMiss(const Tracked& t, const cv::Size& image) const;

  struct Remembered {
    int id = 0;
    std::string category;
    cv::Mat appearance;
    double lost_at = 0;     // s
    cv::Mat identity = {};  // identity_check's descriptor; empty without
    int identity_views = 0;  // views that identity took
  };
  /// The index in remembered_ of the entry of t's category whose descriptor (`descriptorOf` the
  /// entry: its identity, its running descriptor or either) lies nearest t's running
  /// descriptor, if nearer than `best` (then lowered to its distance); -1 otherwise.
  int closestRemembered(const Tracked& t,
                        const std::function<const cv::Mat&(const Remembered&)>& descriptorOf,
                        double& best) const;

  KalmanBoxTrackerParams params_;
  std::vector<Tracked> tracked_;
  std::vector<Remembered> remembered_;  // lost confirmed tracks, reid_memory
  int revived_ = 0;
  int swapped_ = 0;
  int repaired_ = 0;
  double last_t_ = 0;
  bool clock_set_ = false;
  int next_id_ = 1;
  int lost_ = 0;
};

}  // namespace dynslam::tracking
