#pragma once
// Scene-flow classification of the tracked features (method.md section 3) with the adaptive
// rigid point sets of the dynamic objects (section 4). Per frame, in phases:
//  1. membership: a feature belongs to the object whose mask holds it (ObjectMembership.h). One
//     that no mask holds but that was on a tracked object last frame stays with it while the
//     track lives, unless that object's mask box holds the pixel: a missed detection or a box a
//     few pixels short does not throw the object's features into the background;
//  2. the camera's motion since the previous frame (CameraMotion.h), registered on the features
//     outside every box, not merely every mask (background_outside_boxes): a mask misses part
//     of a walker, and a few such near features outvote the far wall, whose depth noise admits
//     any centimetre-sized translation;
//  3. each object's speed: the size of its features' scene flow F (Eq. 11) over up to
//     speed_window frames, divided by the time it spans; dynamic when above speed_threshold by
//     speed_noise_sigmas of its own noise (far or one-frame flows are noisy). An object judged
//     still turns dynamic after start_moving_frames such frames in a row (a walker's surface in
//     a standing person's mask reads "moving" for a frame or two). Objects without enough flow
//     keep their last decision; a new track takes the majority of the objects its features were
//     on (trackers re-number objects), else it is not dynamic: no scene flow says it moves.
//     Objects beyond the depth range are judged from their pixels (far_object_min_depth,
//     FarPointMotion.h);
//  4. rigid sets: dynamic objects update their AdaptiveRigidPointSet from the frame-to-frame
//     pairs;
//  5. classes: background and non-moving objects Static (a parked car, a standing person);
//     dynamic rigid objects Rigid, except the pairs their registration rejected (NonRigid);
//     dynamic non-rigid objects Rigid inside the rigid set, NonRigid outside it. Per-feature
//     rules correct what a mask that took another object's surface says (still_feature_speed
//     and the keys after it, moving_feature_speed, max_nonrigid_flow_speed);
//  6. forgetting: points older than the window, objects not decided for kObjectMemoryS.
// Each departure from the method is settable back to it. Keys, ranges, meanings: describe() in
// DynamicClassificationStage.cpp, docs/parameters.md; why each and its measured gain:
// docs/design.md, docs/notes/frontend.md (2026-11-28, front-end settings' history).
#include <dynslam/core/Frame.h>
#include <dynslam/frontend/CameraMotion.h>
#include <dynslam/frontend/RigidPointSet.h>

#include <cstdint>
#include <deque>
#include <map>
#include <optional>
#include <unordered_map>
#include <unordered_set>
#include <vector>

namespace dynslam::frontend {

struct ObjectRegion;  // ObjectMembership.h

enum class SpeedStatistic { MedianFlow, MeanNorm };

/// [DynamicClassification]'s settings. Keys, ranges, meanings: describe() in
/// DynamicClassificationStage.cpp; docs/parameters.md.
struct DynamicClassifierParams {
  double speed_threshold = 0.1;
  int speed_window = 10;
  SpeedStatistic speed_statistic = SpeedStatistic::MedianFlow;
  double speed_noise_sigmas = 2.0;
  int min_flow_features = 3;
  int start_moving_frames = 2;
  double still_feature_speed = 0.2;
  bool still_feature_in_still_box = true;
  bool unmeasured_feature_by_depth = true;
  bool still_carried_outside_box = true;
  double still_above_feet_fraction = 0.25;
  double moving_feature_speed = 0.8;
  double moving_feature_max_speed = 2.5;
  double max_nonrigid_flow_speed = 2.5;
  int depth_window = 5;
  bool background_outside_boxes = true;
  double far_object_min_depth = 6.0;
  double far_object_pixel_sigma = 0.5;
  RigidPointSetParams rigid;  ///< the objects' rigid sets (method.md section 4)
  CameraMotionParams camera;  ///< the background registration
  /// The camera motion's and the rigid sets' depth noise: DynamicClassifier sets their own
  /// depth_sigma_z2 from it.
  double depth_sigma_z2 = 0.0015;
  int seed = 1;
};

/// Counters for the stage's log and the bench.
struct ClassifierCounts {
  size_t frames = 0, features = 0, object_features = 0, dynamic_objects = 0, rigid_sets = 0;
  std::map<CameraMotionSource, size_t> camera_sources;
};

class DynamicClassifier {
 public:
  /// Throws std::invalid_argument naming a parameter that breaks a rule between keys
  /// (depth_window odd, moving_feature_max_speed above moving_feature_speed); the ranges of
  /// single keys are checked where the options are read (DynamicClassificationOptions).
  explicit DynamicClassifier(DynamicClassifierParams params = {});

  /// Fills frame.features[*].object_id and feature_class, frame.object_motions and
  /// frame.rigid_sets. Reads frame.features (ids, pixels, depths), object_masks, tracks, imu,
  /// the sensor extrinsics and T_world_camera. Frames must come in order.
  void process(core::Frame& frame);

  const CameraMotionEstimate& lastCameraMotion() const { return camera_; }
  const ClassifierCounts& counts() const { return counts_; }
  const DynamicClassifierParams& params() const { return params_; }
  // Object ids are never reused, and a street sees thousands of tracks a minute: what is kept per
  // object is forgotten once the object has not been decided for this long (s). That is longer
  // than a track coasts (max_age, seconds) and than a lost id can be revived (reid_memory 10 s in
  // the shipped inis); a revived id older than this is decided as a new track is.
  static constexpr double kObjectMemoryS = 30.0;
  /// Objects whose decision is kept (those decided within the last kObjectMemoryS).
  std::size_t rememberedObjects() const { return objects_.size(); }

 private:
  struct Observation {
    std::size_t frame = 0;  ///< counter of processed frames
    double t = 0;
    Eigen::Vector3d P;  ///< camera frame of that frame
  };

  struct FrameWork;  // what one frame's phases hand on to the next (DynamicClassifier.cpp)

  // process()'s phases, in their order.
  /// Each feature's object: the mask holding it, else carried over (carriedRegion), else a
  /// depthless box's (far_object_min_depth); every feature starts Static.
  void assignMembership(core::Frame& frame, FrameWork& w);
  /// The region of the object a feature no mask holds stays on (last frame's, while its track
  /// lives and its mask box does not hold the pixel), or nullptr; `outsideBox`: the pixel lies
  /// outside the track's box.
  const ObjectRegion* carriedRegion(const core::Feature& f, FrameWork& w, bool& outsideBox) const;
  /// Camera-frame points (window depth), their last frame's points, the background pairs.
  void placeFeatures(const core::Frame& frame, FrameWork& w) const;
  /// camera_ since the previous frame, and the chain of poses over the window.
  void estimateCameraMotion(const core::Frame& frame, FrameWork& w);
  /// Each object feature's scene-flow speed over the window, summed per object.
  void measureObjectSpeeds(const core::Frame& frame, FrameWork& w);
  /// Each object's decision (start_moving_frames), appended to frame.object_motions.
  void decideObjects(core::Frame& frame, FrameWork& w);
  /// A new track's decision: the majority of its features' objects of the last frame.
  bool newTrackDecision(const core::Frame& frame, int id, const FrameWork& w) const;
  /// far_object_min_depth: decides the objects of the depthless boxes from their features
  /// without depth, appends their ObjectMotionState, and keeps each such feature's lower bound
  /// of its own speed over the window (m/s, FarPointMotion.h; -1: not measured).
  void decideFarObjects(core::Frame& frame, FrameWork& w);
  /// The dynamic objects' rigid sets, appended to frame.rigid_sets.
  void updateRigidSets(core::Frame& frame, FrameWork& w);
  /// What decides a feature's class.
  enum class Verdict {
    MovingOnItsOwn,  ///< NonRigid: moving in a still object's mask, or a far object's mover
    StillOffObject,  ///< Static, and off the object it was carried on
    Static,          ///< background, a still object's, or kept Static by a feature rule
    ByRigidSet,      ///< a dynamic object's: Rigid or NonRigid by its rigid set
  };
  Verdict verdictOf(const core::Frame& frame, size_t i, const FrameWork& w) const;
  /// Every feature's class, and the features Static for the next frame.
  void classifyFeatures(core::Frame& frame, FrameWork& w);
  /// The frame's points and memberships for the next one; forgets what is too old.
  void rememberFrame(const core::Frame& frame, FrameWork& w);

  /// Object `id`'s last decision (dynamic or not), if it is remembered.
  std::optional<bool> lastDecision(int id) const;
  /// Records object `id`'s decision of this frame (time `t`, s).
  void remember(int id, bool dynamic, double t);
  /// Drops what is kept per object for the objects not decided since time `t` (s).
  void forgetObjectsUnseenSince(double t);
  /// Summed variance (m^2) of the camera translations of the frames after `frame` up to now.
  double cameraVarianceSince(std::size_t frame) const;
  /// T_{C(cur) <- C(frame)} from the chain of estimated camera motions.
  Eigen::Isometry3d cameraFromPast(std::size_t frame) const;

  DynamicClassifierParams params_;
  CameraMotionEstimator cameraEstimator_;
  CameraMotionEstimate camera_;
  ClassifierCounts counts_;
  std::size_t frame_ = 0;  ///< counter of this frame
  std::optional<double> prevT_;
  std::optional<Eigen::Isometry3d> prevPose_;
  /// T_{O <- C(frame)}: camera poses in the frame of the first one, last speed_window + 1.
  std::deque<std::pair<std::size_t, Eigen::Isometry3d>> odometry_;
  /// Variance of each frame's camera translation (m^2), frame counter -> value, same span.
  std::deque<std::pair<std::size_t, double>> cameraVar_;
  std::unordered_map<std::int64_t, std::deque<Observation>> history_;  ///< per feature id
  struct PixelObservation {
    std::size_t frame = 0;
    double t = 0;
    cv::Point2f pixel;
  };
  /// Per depthless feature id, its pixels over the window (far_object_min_depth > 0 only).
  std::unordered_map<std::int64_t, std::deque<PixelObservation>> pixelHistory_;
  /// What is kept of an object between frames (forgotten after kObjectMemoryS).
  struct ObjectMemory {
    bool dynamic = false;  ///< its last decision
    int moving_run = 0;    ///< measured frames in a row over the threshold, up to that one
    double decided_t = 0;  ///< when it was last decided (s)
  };
  std::map<int, ObjectMemory> objects_;         ///< per object id
  std::map<int, AdaptiveRigidPointSet> sets_;   ///< per object id
  std::map<std::int64_t, int> objectOf_;        ///< feature id -> object id, last frame
  std::unordered_set<std::int64_t> wasStatic_;  ///< features classified Static last frame
};

const char* toString(CameraMotionSource source);

}  // namespace dynslam::frontend
