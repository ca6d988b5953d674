#pragma once
// Multi-object tracking by one Kalman box filter per object (method.md section 2).
//
// Each detector frame: every track's filter predicts to the frame's time; the depth IoU rho of
// each (predicted track, detection) pair of the same category is computed; the Hungarian
// algorithm picks the assignment with the largest total rho, and a pair is accepted only if
// rho > rho_min. Matched tracks update their filter. Unmatched confirmed tracks coast (predict
// only) for up to max_age detector frames, so an object hidden behind another keeps its ID and
// is taken up again when it reappears (paper Fig. 10); then they are Lost, as they are once less
// than half of their predicted box is inside the image. Unmatched detections start Tentative
// tracks, Confirmed after min_hits matched frames. IDs count up from 1 and are never given to
// another object (reid_memory gives a returning object its own back).
//
// Always, beyond the method's text:
// - a coasting track's box keeps its size and depth (area and depth rates held at 0): a linear
//   extrapolation over a second of hiding shrinks or blows up the box, and a shrunk box is
//   never taken up again;
// - a Tentative track that misses a frame is dropped (a false positive rarely repeats at the
//   same place and depth);
// - pairs at or below the threshold are removed before the assignment (their gain set to 0)
//   rather than after it: otherwise maximising the total could pick two sub-threshold pairs over
//   one good pair (0.69 + 0.69 > 0.8), and the good pair would be lost.
// The settings that depart from the method, each off in params/paper.ini, add rounds after the
// depth-IoU one (rho_min_coasting, reid_max_distance), ids given back by appearance (reid_memory,
// identity_check, identity_repair, revival_takes_identity) and gates on what a match may change
// (innovation_gate, depth_gate, alternative_depth, reset_at_border): docs/design.md lists them
// with their measured gains.
#include <dynslam/core/Perception.h>
#include <dynslam/tracking/BoxNoiseModel.h>

#include <opencv2/core/mat.hpp>
#include <opencv2/core/types.hpp>

#include <functional>
#include <string>
#include <vector>

namespace dynslam::tracking {

/// The tracker's settings. Keys, ranges and meanings: TrackingOptions::describe()
/// (TrackingStage.cpp) and docs/parameters.md. The defaults are the shipped, best-measured
/// configuration (what params/sim_vio.ini runs); params/paper.ini sets the method's values.
/// Why each setting that departs from the method, with its measured history:
/// docs/notes/perception.md, 2026-11-28.
struct KalmanBoxTrackerParams {
  double rho_min = 0.5;
  /// A coasting track's prediction drifts with the time hidden (a walker's gait and turns), so
  /// the paper's threshold rejects the person it hid.
  double rho_min_coasting = 0.7;
  /// 2 s at 30 Hz: a person hidden for 1 s goes without detection for about 1.3 s (partly hidden
  /// before and after), and the prediction must still be there when it comes back.
  int max_age = 60;
  int min_hits = 2;
  /// A box cut by the image border follows the border, not the object: the method's filter
  /// extrapolates its shrinking and its fixed aspect ratio lags, so the prediction collapses.
  bool reset_at_border = true;
  double reid_max_distance = 0.7;
  /// People turn while hidden, or leave the image: a returning person's new track is given the
  /// id its colours match once it is confirmed.
  double reid_memory = 10.0;
  /// A person stepping out from behind another is often given the occluder's depth, and its own
  /// descriptor then shows the occluder.
  double reid_at_track_depth = 0.0;
  /// A descriptor taken on another's surface shows the other's clothes, and the revival then
  /// gave the new track the other's id.
  bool descriptor_own_surface = false;
  /// A partly hidden person's cluster choice flips between the person, the occluder and the
  /// wall; the track's depth says which is the person. d_alt counts only where the chosen
  /// cluster is another detection's surface or d_alt is the nearer cluster and nobody else's:
  /// otherwise a track once on a wrong surface would keep taking it.
  bool alternative_depth = true;
  /// The occluder's detection was missed: only its track tells that d_t is its surface.
  bool alternative_depth_tracks = false;
  /// A jump of tens of per cent between frames is the segmentation taking an occluder's
  /// surface, and a track that followed it chose that surface again in [Retrack].
  double depth_gate = 0.15;
  int depth_gate_frames = 5;
  /// A track that coasted while its person walked towards or away from the camera takes the
  /// person's new depth on coming back.
  double depth_gate_speed = 0.0;
  /// The depth IoU of boxes overlapping by half says nothing of where a track was heading: a
  /// track took a person stepping out beside it against the way it walked. The covariance grows
  /// while a track coasts, so the gate widens with the time hidden.
  double innovation_gate = 50.0;
  /// A wrong revival put two identities of one person on two ids, a swap identity_check cannot
  /// see; an identity of a few views is no identity.
  int revival_takes_identity = 0;
  /// The slow identity descriptor is not updated by another person's views, so the running one
  /// shows a swap the association made at a crossing.
  double identity_check = 0.0;
  /// identity_check's pair test cannot undo a swap into a track whose person has a new track by
  /// now: both identities then describe that person.
  int identity_repair = 0;
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
  struct Remembered {
    int id = 0;
    std::string category;
    cv::Mat appearance;
    double lost_at = 0;      // s
    cv::Mat identity = {};   // identity_check's descriptor; empty without
    int identity_views = 0;  // views that identity took
  };
  /// The association of one update(): per track the observation it takes (-1: none), per
  /// observation whether a track took it.
  struct Association {
    std::vector<int> observationOf;
    std::vector<char> observationUsed;
  };

  // Each function is described where it is defined.
  // KalmanBoxTracker.cpp: update()'s phases and the lifecycle of one track.
  std::vector<size_t> updateTracks(const std::vector<BoxObservation>& observations,
                                   const std::vector<int>& observationOf,
                                   const std::vector<char>& othersSurface, const cv::Size& image);
  bool takeObservation(Tracked& tr, const std::vector<BoxObservation>& observations, size_t j,
                       bool onOthersSurface, const cv::Size& image);
  bool missed(Tracked& tr, const cv::Size& image);
  BoxMeasurement measurementFor(Tracked& tr, const cv::Rect2f& box, double depth,
                                BoxMeasurementCovariance& R) const;
  void restartCutComponents(KalmanBoxFilter& filter, const cv::Rect2f& box, const BoxMeasurement& z,
                            const cv::Size& image) const;
  bool loseAfterMiss(const Tracked& t, const cv::Size& image) const;
  void startTrack(const BoxObservation& observation, int index);
  void noteRound(const std::vector<int>& observationOf, TrackMatch round);

  // KalmanBoxTrackerAssociation.cpp: the depth-IoU rounds.
  std::vector<BoxObservation> withUsableAlternatives(const std::vector<BoxObservation>& input,
                                                     const cv::Size& image) const;
  void associateByDepthIoU(const std::vector<BoxObservation>& observations, const cv::Size& image,
                           Association& a);
  double depthFor(const Tracked& tr, const BoxObservation& o) const;
  void associate(const std::vector<BoxObservation>& observations, const cv::Size& image,
                 double threshold, bool coastingOnly, Association& a) const;
  double centreInnovation2(const Tracked& tr, const cv::Rect2f& predicted,
                           const cv::Rect2f& box) const;

  // KalmanBoxTrackerIdentity.cpp: appearance, identities and the revival.
  void reidentify(const std::vector<BoxObservation>& observations,
                  const std::vector<char>& onAnothersSurface, Association& a) const;
  double reidDistance(const cv::Mat& a, double depth, const BoxObservation& o, bool& atDepth) const;
  std::vector<char> onOthersSurface(const std::vector<BoxObservation>& observations,
                                    const std::vector<int>& observationOf,
                                    std::vector<char> onAnothersSurface) const;
  void takeDescriptor(Tracked& tr, const cv::Mat& descriptor) const;
  void updateIdentity(Tracked& tr, const cv::Mat& descriptor) const;
  void checkAndRepairIdentities();
  void checkIdentities();
  void repairIdentity(size_t index);
  void reviveIdentities(const std::vector<size_t>& confirmed);
  void reviveIdentity(size_t index);
  int closestRemembered(const Tracked& t,
                        const std::function<const cv::Mat&(const Remembered&)>& descriptorOf,
                        double& best) const;
  bool remembers() const { return params_.reid_memory > 0 && params_.reid_max_distance > 0; }

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
