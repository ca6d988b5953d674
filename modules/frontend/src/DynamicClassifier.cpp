#include "dynslam/frontend/DynamicClassifier.h"

#include "dynslam/frontend/FarPointMotion.h"
#include "dynslam/frontend/ObjectMembership.h"
#include "dynslam/frontend/SceneFlow.h"
#include "dynslam/frontend/WindowDepth.h"

#include <dynslam/core/Median.h>
#include <algorithm>
#include <set>
#include <stdexcept>
#include <string>

namespace dynslam::frontend {
namespace {

/// The object's speed from its features' scene-flow velocities (m/s each).
double objectSpeed(const std::vector<Eigen::Vector3d>& velocities, SpeedStatistic statistic) {
  if (statistic == SpeedStatistic::MeanNorm) {
    double sum = 0;
    for (const auto& v : velocities) sum += v.norm();
    return sum / double(velocities.size());
  }
  return core::componentwiseUpperMedian(velocities).norm();
}

/// The middle half of `box` in width and height. The far objects' features near their box's
/// edge are mostly the background around a small object or corners on its silhouette, which
/// slide with it (the whole box: docs/notes/frontend.md, 2026-11-28).
cv::Rect centralHalf(const cv::Rect& box) {
  return {box.x + box.width / 4, box.y + box.height / 4, box.width / 2, box.height / 2};
}

/// The entries of feature `id` in `history` within the last `window` frames before `now`, with
/// `latest` appended (moved out of `history`, which is rebuilt each frame).
template <class Entry>
std::deque<Entry> withLatest(std::unordered_map<std::int64_t, std::deque<Entry>>& history,
                             std::int64_t id, std::size_t window, std::size_t now, Entry latest) {
  std::deque<Entry> d;
  if (const auto h = history.find(id); h != history.end()) d = std::move(h->second);
  while (!d.empty() && d.front().frame + window <= now) d.pop_front();
  d.push_back(std::move(latest));
  return d;
}

/// Whether `pixel` lies in the box of an object other than `own` not judged to move: by its
/// latest decision (`decisionOf(id)`, a std::optional<bool>: this frame's, or the last one of an
/// object whose features all went to other masks), or for want of one (no scene flow says it
/// moves, as for a new track). With `z` > 0, only an object whose d_t is nearer `z` than
/// `ownDepth` counts.
template <class DecisionOf>
bool inStillObjectsBox(const std::vector<ObjectRegion>& regions, const DecisionOf& decisionOf,
                       int own, const cv::Point2f& pixel, double z = 0, double ownDepth = 0) {
  const cv::Point px(cvRound(pixel.x), cvRound(pixel.y));
  for (const auto& r : regions) {
    if (r.object_id == own || !r.roi.contains(px)) continue;
    if (z > 0 && !(r.depth > 0 && std::abs(z - r.depth) < std::abs(z - ownDepth))) continue;
    if (!decisionOf(r.object_id).value_or(false)) return true;
  }
  return false;
}

/// Whether `pixel` lies in the box of a mask or of a track.
bool inAnyBox(const core::Frame& frame, const cv::Point2f& pixel) {
  const cv::Point px(cvRound(pixel.x), cvRound(pixel.y));
  for (const auto& m : frame.object_masks)
    if (m.roi.contains(px)) return true;
  for (const auto& t : frame.tracks)
    if (t.box.contains(pixel)) return true;
  return false;
}

/// `p` with the settings of its parts that follow from its own, after checking the rules a
/// key's range cannot state.
DynamicClassifierParams withDerivedSettings(DynamicClassifierParams p) {
  const auto require = [](bool ok, const std::string& key, double value, const char* rule) {
    if (!ok) throw std::invalid_argument(key + " = " + std::to_string(value) + ": must be " + rule);
  };
  require(p.depth_window % 2 == 1, "depth_window", p.depth_window, "odd");
  require(p.moving_feature_max_speed > p.moving_feature_speed, "moving_feature_max_speed",
          p.moving_feature_max_speed, "> moving_feature_speed");
  p.camera.depth_sigma_z2 = p.rigid.depth_sigma_z2 = p.depth_sigma_z2;
  // The rigid sets see the window-depth points: their noise is the reading's over ~0.8 w.
  p.rigid.point_noise_reduction = 0.8 * std::max(1, p.depth_window);
  return p;
}

}  // namespace

/// What one frame's phases hand on to the next (process()).
struct DynamicClassifier::FrameWork {
  /// Per feature of the frame, by index.
  struct Feature {
    const ObjectRegion* region = nullptr;  ///< its object's mask, or carried membership
    const ObjectRegion* far = nullptr;     ///< the depthless box holding it (far objects)
    bool has_point = false;
    Eigen::Vector3d P;                      ///< camera frame
    const Observation* previous = nullptr;  ///< the feature's point in the previous frame
    double speed = -1;       ///< |scene flow| / time over the window, m/s; < 0: not measured
    double speed_sigma = 0;  ///< its depth noise, m/s
    bool carried_outside_box = false;  ///< membership carried over, pixel outside the track's box
  };
  std::size_t now = 0;                        ///< counter of this frame
  std::size_t window = 1;                     ///< speed_window, at least 1
  std::vector<ObjectRegion> regions;          ///< the masks' objects
  std::map<int, const core::Track*> tracks;   ///< by track id
  std::map<int, const ObjectRegion*> masked;  ///< tracks with a mask this frame
  std::map<int, ObjectRegion> maskless;       ///< tracks seen this frame without a mask
  std::vector<ObjectRegion> farBoxes;         ///< depthless boxes of unmasked tracks
  std::vector<Feature> features;
  std::vector<Eigen::Vector3d> bgPrev, bgCur;  ///< pairs outside every mask
  std::vector<char> boxed;                     ///< ... of which inside some box
  std::map<std::int64_t, int> nextObjectOf;
  std::map<int, const ObjectRegion*> seen;                 ///< objects with features this frame
  std::map<int, std::vector<Eigen::Vector3d>> velocities;  ///< per object, m/s
  std::map<int, double> velocityVar;   ///< depth-noise variances, summed over the features
  std::map<int, double> cameraVarSum;  ///< camera-translation variances, summed likewise
  std::map<int, bool> dynamic;         ///< this frame's decisions
  std::vector<double> farSpeed;        ///< decideFarObjects(), by feature index
  std::map<int, std::set<std::int64_t>> members, tested;  ///< rigid sets, per object

  bool isDynamic(int id) const {
    const auto d = dynamic.find(id);
    return d != dynamic.end() && d->second;
  }
};

void DynamicClassifier::decideFarObjects(core::Frame& frame, FrameWork& w) {
  w.farSpeed.assign(frame.features.size(), -1.0);
  const double zMin = params_.far_object_min_depth;
  const double f = 0.5 * (frame.intrinsics.fx + frame.intrinsics.fy);
  std::map<int, std::vector<double>> speeds;
  std::map<int, double> noiseVar;  // pixel and camera-translation variances, summed
  std::set<int> seen;
  for (size_t i = 0; i < frame.features.size(); ++i) {
    if (!w.features[i].far) continue;
    const int id = w.features[i].far->object_id;
    seen.insert(id);
    const auto h = pixelHistory_.find(frame.features[i].id);
    if (h == pixelHistory_.end()) continue;
    for (const auto& o : h->second) {  // oldest first: the longest span within the window
      if (o.frame + w.window < frame_ || o.frame >= frame_ || !(frame.t > o.t)) continue;
      const double dt = frame.t - o.t;
      const double v = farPointMinDisplacement(o.pixel, frame.features[i].pixel,
                                               cameraFromPast(o.frame), frame.intrinsics, zMin) /
                       dt;
      speeds[id].push_back(v);
      const double pixel = params_.far_object_pixel_sigma * zMin / f / dt;
      const double var = 2 * pixel * pixel + cameraVarianceSince(o.frame) / (dt * dt);
      noiseVar[id] += var;
      w.farSpeed[i] = v - params_.speed_noise_sigmas * std::sqrt(var);
      break;
    }
  }
  for (const int id : seen) {
    core::ObjectMotionState s;
    s.object_id = id;
    auto v = speeds.find(id);
    s.features = v == speeds.end() ? 0 : int(v->second.size());
    // One feature suffices: the noise term grows as features are fewer (a car 20 m away holds
    // one or two tracked corners, and min_flow_features left most such objects undecided).
    if (s.features >= 1) {
      const double n = double(s.features);
      s.speed = core::upperMedianInPlace(v->second);
      const double noise = std::sqrt(1.5625 * noiseVar[id] / n / n);
      s.dynamic = s.speed > params_.speed_threshold + params_.speed_noise_sigmas * noise;
    } else {
      s.dynamic = lastDecision(id).value_or(false);
    }
    remember(id, s.dynamic, frame.t);
    w.dynamic[id] = s.dynamic;
    counts_.dynamic_objects += s.dynamic;
    frame.object_motions.push_back(s);
  }
}

std::optional<bool> DynamicClassifier::lastDecision(int id) const {
  const auto o = objects_.find(id);
  return o == objects_.end() ? std::nullopt : std::optional<bool>(o->second.dynamic);
}

void DynamicClassifier::remember(int id, bool dynamic, double t) {
  ObjectMemory& o = objects_[id];
  o.dynamic = dynamic;
  o.decided_t = t;
}

void DynamicClassifier::forgetObjectsUnseenSince(double t) {
  for (auto it = objects_.begin(); it != objects_.end();)
    it = it->second.decided_t < t ? objects_.erase(it) : std::next(it);
}

const char* toString(CameraMotionSource source) {
  switch (source) {
    case CameraMotionSource::Poses:
      return "poses";
    case CameraMotionSource::ImuRotationRegistration:
      return "imu_rotation+registration";
    case CameraMotionSource::Registration:
      return "registration";
    case CameraMotionSource::ImuRotationConstantVelocity:
      return "imu_rotation+constant_velocity";
    case CameraMotionSource::ConstantVelocity:
      return "constant_velocity";
  }
  return "?";
}

DynamicClassifier::DynamicClassifier(DynamicClassifierParams params)
    : params_(withDerivedSettings(params)),
      cameraEstimator_(params_.camera, std::uint32_t(params_.seed)) {}

double DynamicClassifier::cameraVarianceSince(std::size_t frame) const {
  double sum = 0;
  for (const auto& [f, var] : cameraVar_)
    if (f > frame) sum += var;
  return sum;
}

Eigen::Isometry3d DynamicClassifier::cameraFromPast(std::size_t frame) const {
  for (const auto& [f, T_o_c] : odometry_)
    if (f == frame) return odometry_.back().second.inverse() * T_o_c;
  return Eigen::Isometry3d::Identity();  // not reached: history never outlives odometry_
}

void DynamicClassifier::process(core::Frame& frame) {
  ++counts_.frames;
  FrameWork w;
  w.now = frame_;
  w.window = size_t(std::max(1, params_.speed_window));
  assignMembership(frame, w);
  placeFeatures(frame, w);
  estimateCameraMotion(frame, w);
  measureObjectSpeeds(frame, w);
  decideObjects(frame, w);
  decideFarObjects(frame, w);
  updateRigidSets(frame, w);
  classifyFeatures(frame, w);
  rememberFrame(frame, w);
}

void DynamicClassifier::assignMembership(core::Frame& frame, FrameWork& w) {
  w.regions = objectRegions(frame);
  w.features.resize(frame.features.size());
  for (const auto& t : frame.tracks) w.tracks[t.id] = &t;
  for (const auto& r : w.regions) w.masked.emplace(r.object_id, &r);
  if (params_.far_object_min_depth > 0)
    for (auto& b : depthlessObjectBoxes(frame))
      if (!w.masked.count(b.object_id)) w.farBoxes.push_back(std::move(b));
  for (size_t i = 0; i < frame.features.size(); ++i) {
    auto& f = frame.features[i];
    auto& c = w.features[i];
    c.region = regionAt(w.regions, f.pixel);
    if (!c.region) c.region = carriedRegion(f, w, c.carried_outside_box);
    f.object_id = c.region ? c.region->object_id : -1;
    if (c.region) w.nextObjectOf[f.id] = f.object_id;
    f.feature_class = core::FeatureClass::Static;
    if (!c.region && !(f.depth > 0))
      for (const auto& b : w.farBoxes)
        if (centralHalf(b.roi).contains({cvRound(f.pixel.x), cvRound(f.pixel.y)})) {
          c.far = &b;
          f.object_id = b.object_id;  // on the object, though not in a mask (none was made)
          break;
        }
  }
  counts_.features += frame.features.size();
}

const ObjectRegion* DynamicClassifier::carriedRegion(const core::Feature& f, FrameWork& w,
                                                     bool& outsideBox) const {
  // No mask holds it, but it was on a tracked object last frame and that track is still
  // there: it stays with the object unless the object's mask says otherwise. A mask speaks
  // only for the pixels of its box: outside it (the detector missed the object and the track
  // coasts, or the box was cut short by a few pixels) membership carries over.
  const auto last = objectOf_.find(f.id);
  if (last == objectOf_.end()) return nullptr;
  const auto mask = w.masked.find(last->second);
  if (mask != w.masked.end() &&
      mask->second->roi.contains({cvRound(f.pixel.x), cvRound(f.pixel.y)}))
    return nullptr;
  const auto t = w.tracks.find(last->second);
  if (t == w.tracks.end()) return nullptr;
  outsideBox = !t->second->box.contains(f.pixel);
  return &w.maskless.try_emplace(t->first, ObjectRegion{t->first, t->second->model, {}, {}, 0.0})
              .first->second;
}

void DynamicClassifier::placeFeatures(const core::Frame& frame, FrameWork& w) const {
  const bool windowed =
      params_.depth_window > 1 && !frame.depth.empty() && frame.depth.type() == CV_32FC1;
  std::vector<double> buf;
  for (size_t i = 0; i < frame.features.size(); ++i) {
    const auto& f = frame.features[i];
    auto& c = w.features[i];
    const float z = windowed ? windowDepth(frame.depth, f.pixel, params_.depth_window / 2,
                                           params_.depth_sigma_z2, buf)
                             : f.depth;
    if (!(z > 0) || !(f.depth > 0)) continue;
    c.has_point = true;
    c.P = backProject(f.pixel, z, frame.intrinsics);
    const auto h = history_.find(f.id);
    if (h != history_.end() && !h->second.empty() && h->second.back().frame + 1 == w.now)
      c.previous = &h->second.back();
    if (!c.region && c.previous) {
      w.bgPrev.push_back(c.previous->P);
      w.bgCur.push_back(c.P);
      w.boxed.push_back(params_.background_outside_boxes && inAnyBox(frame, f.pixel));
    }
  }
}

void DynamicClassifier::estimateCameraMotion(const core::Frame& frame, FrameWork& w) {
  if (prevT_) {
    const auto gyro =
        gyroCameraRotation(frame.imu, *prevT_, frame.t, frame.T_body_imu, frame.T_body_camera);
    // Only the pairs outside every box (background_outside_boxes; else none is boxed). Too few
    // of them and CameraMotionEstimator's constant velocity stands in, not the pairs inside
    // boxes but outside masks: those are the walkers' unmasked parts when people fill the view.
    size_t k = 0;
    for (size_t i = 0; i < w.boxed.size(); ++i)
      if (!w.boxed[i]) {
        w.bgPrev[k] = w.bgPrev[i];
        w.bgCur[k++] = w.bgCur[i];
      }
    w.bgPrev.resize(k);
    w.bgCur.resize(k);
    camera_ = cameraEstimator_.estimate(w.bgPrev, w.bgCur, gyro, prevPose_, frame.T_world_camera);
    ++counts_.camera_sources[camera_.source];
    odometry_.emplace_back(w.now, odometry_.back().second * camera_.motion.isometry().inverse());
    cameraVar_.emplace_back(w.now, camera_.translation_sigma * camera_.translation_sigma);
  } else {
    camera_ = {};
    odometry_.emplace_back(w.now, Eigen::Isometry3d::Identity());
  }
  while (!odometry_.empty() && odometry_.front().first + w.window < w.now) odometry_.pop_front();
  while (!cameraVar_.empty() && cameraVar_.front().first + w.window < w.now) cameraVar_.pop_front();
}

void DynamicClassifier::measureObjectSpeeds(const core::Frame& frame, FrameWork& w) {
  for (size_t i = 0; i < frame.features.size(); ++i) {
    auto& c = w.features[i];
    if (!c.region) continue;
    ++counts_.object_features;
    w.seen[c.region->object_id] = c.region;
    if (!c.has_point) continue;
    const auto h = history_.find(frame.features[i].id);
    if (h == history_.end()) continue;
    for (const auto& o : h->second) {  // oldest first: the longest span within the window
      if (o.frame + w.window < w.now || o.frame >= w.now || !(frame.t > o.t)) continue;
      const Eigen::Vector3d F = sceneFlow(o.P, c.P, cameraFromPast(o.frame));
      const double dt = frame.t - o.t;
      const double speed = F.norm() / dt;
      // Variance of that velocity from the depth noise of both points (the window median
      // divides a reading's sigma by about sqrt(0.64 w^2)).
      const double reduce = 0.8 * std::max(1, params_.depth_window);
      const double sp = params_.depth_sigma_z2 * o.P.z() * o.P.z() / reduce;
      const double sq = params_.depth_sigma_z2 * c.P.z() * c.P.z() / reduce;
      const double var = (sp * sp + sq * sq) / (dt * dt);
      const double sigma = std::sqrt(var);
      // Faster than a person moves, beyond its noise: a depth jump (max_nonrigid_flow_speed).
      if (params_.max_nonrigid_flow_speed > 0 && c.region->model == core::MotionModel::NonRigid &&
          speed > params_.max_nonrigid_flow_speed + params_.speed_noise_sigmas * sigma)
        break;
      w.velocities[c.region->object_id].push_back(F / dt);
      c.speed = speed;
      c.speed_sigma = sigma;
      w.velocityVar[c.region->object_id] += var;
      w.cameraVarSum[c.region->object_id] += cameraVarianceSince(o.frame) / (dt * dt);
      break;
    }
  }
}

void DynamicClassifier::decideObjects(core::Frame& frame, FrameWork& w) {
  // objects_ holds the previous decisions and start_moving_frames' runs until all are made.
  std::map<int, int> movingRuns;
  for (const auto& [id, region] : w.seen) {
    core::ObjectMotionState s;
    s.object_id = id;
    const auto v = w.velocities.find(id);
    s.features = v == w.velocities.end() ? 0 : int(v->second.size());
    if (s.features >= std::max(1, params_.min_flow_features)) {
      s.speed = objectSpeed(v->second, params_.speed_statistic);
      // The median of n velocities has about 1.25 sigma / sqrt(n) of depth noise (sigma: their
      // rms); the camera's error is common to all of them and does not average out.
      const double n = double(s.features);
      const double noise = std::sqrt(1.5625 * w.velocityVar[id] / n / n + w.cameraVarSum[id] / n);
      const bool over = s.speed > params_.speed_threshold + params_.speed_noise_sigmas * noise;
      const auto before = objects_.find(id);
      const int run = over ? (before != objects_.end() ? before->second.moving_run : 0) + 1 : 0;
      movingRuns[id] = run;
      const bool wasStill = before != objects_.end() && !before->second.dynamic;
      s.dynamic = over && !(wasStill && run < params_.start_moving_frames);
    } else if (const std::optional<bool> last = lastDecision(id)) {
      s.dynamic = *last;
    } else {
      s.dynamic = newTrackDecision(frame, id, w);
    }
    w.dynamic[id] = s.dynamic;
    counts_.dynamic_objects += s.dynamic;
    frame.object_motions.push_back(s);
  }
  for (const auto& [id, d] : w.dynamic) remember(id, d, frame.t);
  for (const auto& [id, run] : movingRuns) objects_[id].moving_run = run;
}

bool DynamicClassifier::newTrackDecision(const core::Frame& frame, int id,
                                         const FrameWork& w) const {
  // The tracker may give an object a new id: its features' objects of the last frame vote;
  // without votes it is not dynamic (no scene flow says it moves).
  int votes = 0, dynamicVotes = 0;
  for (size_t i = 0; i < frame.features.size(); ++i) {
    if (!w.features[i].region || w.features[i].region->object_id != id) continue;
    const auto before = objectOf_.find(frame.features[i].id);
    if (before == objectOf_.end()) continue;
    const std::optional<bool> decision = lastDecision(before->second);
    if (!decision) continue;
    ++votes;
    dynamicVotes += *decision;
  }
  return votes > 0 && 2 * dynamicVotes >= votes;
}

void DynamicClassifier::updateRigidSets(core::Frame& frame, FrameWork& w) {
  // From the frame-to-frame pairs of the dynamic objects.
  std::map<int, std::vector<PointPair>> pairs;
  for (size_t i = 0; i < frame.features.size(); ++i) {
    const auto& c = w.features[i];
    if (c.region && c.previous && w.isDynamic(c.region->object_id))
      pairs[c.region->object_id].push_back({frame.features[i].id, c.previous->P, c.P});
  }
  for (auto it = sets_.begin(); it != sets_.end();)
    it = (w.seen.count(it->first) && w.isDynamic(it->first)) ? std::next(it) : sets_.erase(it);
  for (const auto& [id, objectPairs] : pairs) {
    auto set =
        sets_.try_emplace(id, params_.rigid, std::uint32_t(params_.seed) + std::uint32_t(id)).first;
    if (!set->second.update(objectPairs, camera_.motion.R,
                            0.5 * (frame.intrinsics.fx + frame.intrinsics.fy)))
      continue;
    frame.rigid_sets.push_back(set->second.toRigidSet(id));
    ++counts_.rigid_sets;
    w.members[id].insert(set->second.members().begin(), set->second.members().end());
    for (const auto& p : objectPairs) w.tested[id].insert(p.id);
  }
}

DynamicClassifier::Verdict DynamicClassifier::verdictOf(const core::Frame& frame, size_t i,
                                                        const FrameWork& w) const {
  const auto& f = frame.features[i];
  const auto& c = w.features[i];
  const auto decisionOf = [this](int id) { return lastDecision(id); };
  const auto* region = c.region;
  const bool still = c.speed >= 0 && c.speed < params_.still_feature_speed;
  const bool stillAndWasStatic =
      still && (wasStatic_.count(f.id) > 0 ||
                (params_.still_feature_in_still_box && region &&
                 inStillObjectsBox(w.regions, decisionOf, region->object_id, f.pixel)));
  const bool movingInStillObject =
      region && !w.isDynamic(region->object_id) && params_.moving_feature_speed > 0 &&
      c.speed - params_.speed_noise_sigmas * c.speed_sigma > params_.moving_feature_speed &&
      c.speed < params_.moving_feature_max_speed;
  const bool movingFar =
      c.far && w.isDynamic(c.far->object_id) && w.farSpeed[i] > params_.speed_threshold;
  if (movingInStillObject || movingFar) return Verdict::MovingOnItsOwn;
  // unmeasured_feature_by_depth: no flow yet (a new corner), so the depth says whose it is.
  const bool unmeasuredOfStill =
      params_.unmeasured_feature_by_depth && region && c.has_point && c.speed < 0 &&
      inStillObjectsBox(w.regions, decisionOf, region->object_id, f.pixel, c.P.z(), region->depth);
  // still_above_feet_fraction: a walker's only still parts are its planted feet.
  const bool stillAboveFeet =
      params_.still_above_feet_fraction > 0 && still && region && !region->mask.empty() &&
      region->model == core::MotionModel::NonRigid &&
      f.pixel.y < region->roi.y + (1 - params_.still_above_feet_fraction) * region->roi.height;
  // still_carried_outside_box: nothing but last frame's membership puts it on the object.
  if (params_.still_carried_outside_box && still && c.carried_outside_box)
    return Verdict::StillOffObject;
  if (!region || !w.isDynamic(region->object_id) || stillAndWasStatic || unmeasuredOfStill ||
      stillAboveFeet)
    return Verdict::Static;
  return Verdict::ByRigidSet;
}

void DynamicClassifier::classifyFeatures(core::Frame& frame, FrameWork& w) {
  std::unordered_set<std::int64_t> nextStatic;
  for (size_t i = 0; i < frame.features.size(); ++i) {
    auto& f = frame.features[i];
    const auto* region = w.features[i].region;
    switch (verdictOf(frame, i, w)) {
      case Verdict::MovingOnItsOwn:
        f.feature_class = core::FeatureClass::NonRigid;
        break;
      case Verdict::StillOffObject:
        f.object_id = -1;
        w.nextObjectOf.erase(f.id);
        nextStatic.insert(f.id);
        break;
      case Verdict::Static:
        nextStatic.insert(f.id);
        break;
      case Verdict::ByRigidSet: {
        const bool member = w.members[region->object_id].count(f.id) > 0;
        const bool rejected = w.tested[region->object_id].count(f.id) > 0 && !member;
        if (region->model == core::MotionModel::Rigid)
          f.feature_class = rejected ? core::FeatureClass::NonRigid : core::FeatureClass::Rigid;
        else
          f.feature_class = member ? core::FeatureClass::Rigid : core::FeatureClass::NonRigid;
        break;
      }
    }
  }
  wasStatic_ = std::move(nextStatic);
}

void DynamicClassifier::rememberFrame(const core::Frame& frame, FrameWork& w) {
  // This frame's points; features no longer tracked are forgotten.
  std::unordered_map<std::int64_t, std::deque<Observation>> next;
  next.reserve(frame.features.size());
  for (size_t i = 0; i < frame.features.size(); ++i) {
    const std::int64_t id = frame.features[i].id;
    if (w.features[i].has_point)
      next.emplace(id, withLatest(history_, id, w.window, w.now,
                                  Observation{w.now, frame.t, w.features[i].P}));
  }
  history_ = std::move(next);
  if (params_.far_object_min_depth > 0) {
    std::unordered_map<std::int64_t, std::deque<PixelObservation>> pixels;
    pixels.reserve(frame.features.size());
    for (const auto& f : frame.features)
      if (!(f.depth > 0))  // only depthless features are measured by their pixels
        pixels.emplace(f.id, withLatest(pixelHistory_, f.id, w.window, w.now,
                                        PixelObservation{w.now, frame.t, f.pixel}));
    pixelHistory_ = std::move(pixels);
  }
  objectOf_ = std::move(w.nextObjectOf);
  forgetObjectsUnseenSince(frame.t - kObjectMemoryS);
  prevT_ = frame.t;
  prevPose_ = frame.T_world_camera;
  ++frame_;
}

}  // namespace dynslam::frontend
