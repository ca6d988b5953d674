#include "classification_scoring.h"

#include <dynslam/frontend/ObjectMembership.h>
#include <dynslam/frontend/RigidRegistration.h>
#include <dynslam/frontend/SceneFlow.h>

#include <algorithm>

namespace dynslam::bench {
namespace {

int labelAt(const cv::Mat& labels, const cv::Point2f& p) {
  const int x = cvRound(p.x), y = cvRound(p.y);
  if (x < 0 || y < 0 || x >= labels.cols || y >= labels.rows) return 0;
  return labels.at<uint16_t>(y, x);
}

const core::ObjectGroundTruthRow* rowOf(const std::vector<core::ObjectGroundTruthRow>& rows,
                                        int id) {
  for (const auto& r : rows)
    if (r.id == id) return &r;
  return nullptr;
}

/// Whether `pixel` lies in the box of a mask that is `valid` (has depth) or not.
bool inMaskBox(const core::Frame& frame, const cv::Point2f& pixel, bool valid) {
  const cv::Point px(cvRound(pixel.x), cvRound(pixel.y));
  for (const auto& m : frame.object_masks)
    if (m.valid == valid && m.roi.contains(px)) return true;
  return false;
}

/// ClassificationScore::depthlessMisses' and depthMisses' key for the missed feature `f` on
/// object `row`.
std::string missCause(const core::Frame& frame, const Truth& truth,
                      const core::ObjectGroundTruthRow& row, const core::Feature& f) {
  const double z = (truth.T_world_camera.inverse() * row.T_world_object).translation().z();
  const char* band = z < 5 ? "0-5 m" : z < 10 ? "5-10 m" : z < 20 ? "10-20 m" : "20+ m";
  const auto inTrackBox = [&] {
    for (const auto& t : frame.tracks)
      if (t.box.contains(f.pixel)) return true;
    return false;
  };
  const auto motion = std::find_if(frame.object_motions.begin(), frame.object_motions.end(),
                                   [&f](const auto& m) { return m.object_id == f.object_id; });
  const bool unmeasured = motion == frame.object_motions.end() || motion->features == 0;
  const bool judgedDynamic = motion != frame.object_motions.end() && motion->dynamic;
  const char* where = f.object_id >= 0 && judgedDynamic  ? "static in an object judged dynamic"
                      : f.object_id >= 0 && unmeasured   ? "given to an object without scene flow"
                      : f.object_id >= 0                 ? "given to an object judged static"
                      : inMaskBox(frame, f.pixel, false) ? "in a depthless box"
                      : inMaskBox(frame, f.pixel, true)  ? "in a masked box, outside its mask"
                      : inTrackBox()                     ? "in a track's box only"
                                                         : "in no box";
  return row.category + ", " + band + ": " + where;
}

/// ClassificationScore::falsePositives' key for the feature `f` wrongly not Static; `row`: the
/// non-moving object its pixel shows (nullptr: background), `inMask`: its object's mask holds
/// it, `ownObject`: its object is the one its pixel shows.
std::string falsePositiveCause(const core::Frame& frame, const core::ObjectGroundTruthRow* row,
                               const core::Feature& f, bool inMask, bool ownObject) {
  const char* whose = f.object_id < 0                    ? "no object's"
                      : inMask && ownObject              ? "its own mask's"
                      : inMask                           ? "a mask's"
                      : inMaskBox(frame, f.pixel, false) ? "a depthless box's"
                                                         : "carried";
  return (row ? "non-moving " + row->category : std::string("background")) + ": " + whose +
         (f.depth > 0 ? ", with depth" : ", no depth");
}

/// ClassificationScore::trackingErrorPx of feature `f` (with depth; its object `row`, nullptr:
/// background) seen at `lastPixel` in the previous frame; -1 when it cannot be told. Where the
/// true motions put it in the previous frame goes to `truePrevious` when given.
double trackingError(const core::Frame& frame, const Truth& truth, const Truth& previous,
                     const core::ObjectGroundTruthRow* row, const core::Feature& f,
                     const cv::Point2f& lastPixel, cv::Point2f* truePrevious = nullptr) {
  const auto& k = frame.intrinsics;
  if (!(f.depth > 0) || !(k.fx > 0)) return -1;
  Eigen::Vector3d world = truth.T_world_camera * frontend::backProject(f.pixel, f.depth, k);
  if (const auto* before = row ? rowOf(previous.objects, row->id) : nullptr)
    world = before->T_world_object * (row->T_world_object.inverse() * world);
  const Eigen::Vector3d then = previous.T_world_camera.inverse() * world;
  if (!(then.z() > 0)) return -1;
  const Eigen::Vector2d uv = frontend::project(then, k);
  const cv::Point2f predicted(float(uv.x()), float(uv.y()));
  if (truePrevious) *truePrevious = predicted;
  return cv::norm(predicted - lastPixel);
}

/// What one frame's features leave for the per-object tallies and the rigid sets.
struct FrameCounts {
  std::map<int, std::pair<size_t, size_t>> perObject;       // label -> features, Static ones
  std::map<int, std::map<std::string, size_t>> missCauses;  // label -> cause -> features
  std::map<std::int64_t, int> labelOfFeature;
  std::map<std::int64_t, cv::Point2f> pixels;
};

/// Whether a track's mask holds a pixel this frame (else its features are carried over).
bool inMaskOf(const std::vector<frontend::ObjectRegion>& regions, int trackId,
              const cv::Point2f& pixel) {
  const cv::Point px(cvRound(pixel.x), cvRound(pixel.y));
  for (const auto& r : regions)
    if (r.object_id == trackId && r.roi.contains(px) &&
        r.mask.at<uint8_t>(px.y - r.roi.y, px.x - r.roi.x) != 0)
      return true;
  return false;
}

/// trackingErrorPx and backgroundFlowRatio of feature `f` (object `row`, nullptr: background).
void addTrackingError(ClassificationScore& score, const core::Frame& frame, const Truth& truth,
                      const Truth& previous, const core::ObjectGroundTruthRow* row,
                      const core::Feature& f) {
  const auto last = score.lastPixel.find(f.id);
  if (last == score.lastPixel.end()) return;
  cv::Point2f truePrevious;
  const double e = trackingError(frame, truth, previous, row, f, last->second, &truePrevious);
  if (e < 0) return;
  score
      .trackingErrorPx[!row          ? "background"
                       : row->moving ? "moving " + row->category
                                     : "non-moving " + row->category]
      .push_back(e);
  const cv::Point2f tracked = f.pixel - last->second, truly = f.pixel - truePrevious;
  if (!row && !f.depth_at_edge && truly.dot(truly) >= 1.0f)
    score.backgroundFlowRatio[f.depth < ClassificationScore::kNearFlowDepth ? 0 : 1].push_back(
        double(tracked.dot(truly)) / double(truly.dot(truly)));
}

/// The confusion counts of feature `f` and where its errors come from.
void addFeatureClass(ClassificationScore& score, const core::Frame& frame, const Truth& truth,
                     const std::vector<frontend::ObjectRegion>& regions,
                     const std::map<int, bool>& matchedNow, const core::Feature& f, int label,
                     FrameCounts& counts) {
  const auto* row = label ? rowOf(truth.objects, label) : nullptr;
  const bool truthDynamic = row && row->moving;
  const bool predicted = f.feature_class != core::FeatureClass::Static;
  // Whether the feature's object is the track whose detection shows this pixel's object.
  const auto owner = score.trackTruth.find(f.object_id);
  const bool ownTrack = row && owner != score.trackTruth.end() && owner->second == label;
  score.tp += truthDynamic && predicted;
  score.fp += !truthDynamic && predicted;
  score.fn += truthDynamic && !predicted;
  score.tn += !truthDynamic && !predicted;
  if (!truthDynamic && predicted) {
    ++(row ? score.fpNonMovingObject : score.fpBackground);
    ++score.falsePositives[falsePositiveCause(frame, row, f,
                                              inMaskOf(regions, f.object_id, f.pixel), ownTrack)];
  }
  if (f.depth > 0) {
    score.tpDepth += truthDynamic && predicted;
    score.fpDepth += !truthDynamic && predicted;
    score.fnDepth += truthDynamic && !predicted;
    score.tnDepth += !truthDynamic && !predicted;
  }
  if (truthDynamic && !predicted) ++(f.object_id < 0 ? score.fnNoObject : score.fnJudgedStatic);
  if (truthDynamic && !predicted)
    ++(f.depth > 0 ? score.depthMisses : score.depthlessMisses)[missCause(frame, truth, *row, f)];
  if (row && !row->moving && predicted) {
    const auto matched = matchedNow.find(f.object_id);
    const char* cause =
        f.object_id < 0                                              ? "no track"
        : ownTrack && matched != matchedNow.end() && matched->second ? "own track (matched)"
        : ownTrack                                                   ? "own track (coasting)"
        : inMaskOf(regions, f.object_id, f.pixel)                    ? "another object's mask"
                                                  : "another object's carried membership";
    ++counts.missCauses[label][cause];
  }
  if (row) {
    ++counts.perObject[label].first;
    counts.perObject[label].second += !predicted;
  }
}

/// Each object seen with >= 3 features: static or dynamic by most of its features.
void tallyObjects(ClassificationScore& score, const Truth& truth, const FrameCounts& counts) {
  for (const auto& [label, n] : counts.perObject) {
    if (n.first < 3) continue;
    const auto* row = rowOf(truth.objects, label);
    const bool isStatic = 2 * n.second >= n.first;
    auto& tally = row->moving ? score.moving[row->category] : score.nonMoving[row->category];
    ++tally.first;
    tally.second += row->moving ? !isStatic : isStatic;
    if (!row->moving && !isStatic) {
      const auto& causes = counts.missCauses.at(label);
      const auto top = std::max_element(causes.begin(), causes.end(),
                                        [](auto& a, auto& b) { return a.second < b.second; });
      ++score.nonMovingMisses[row->category][top->first];
    }
  }
}

/// The rigid sets' motions against their objects' true ones.
void addRigidSets(ClassificationScore& score, const core::Frame& frame, const Truth& truth,
                  const Truth& previous, const std::map<std::int64_t, int>& labelOfFeature) {
  for (const auto& s : frame.rigid_sets) {
    std::map<int, int> votes;
    for (auto id : s.members) {
      const auto l = labelOfFeature.find(id);
      ++votes[l != labelOfFeature.end() ? l->second : 0];
    }
    const auto best = std::max_element(votes.begin(), votes.end(),
                                       [](auto& a, auto& b) { return a.second < b.second; });
    const auto* now = best->first ? rowOf(truth.objects, best->first) : nullptr;
    const auto* before = best->first ? rowOf(previous.objects, best->first) : nullptr;
    if (!now || !before || !now->moving) {
      ++score.rigidSetsUnmatched;
      continue;
    }
    frontend::RigidMotion M{s.R, s.t};
    const Eigen::Isometry3d A =
        truth.T_world_camera * M.isometry() * previous.T_world_camera.inverse();
    const Eigen::Isometry3d Agt = now->T_world_object * before->T_world_object.inverse();
    const Eigen::Vector3d c =
        previous.T_world_camera * (s.R.transpose() * (s.virtual_centroid - s.t));
    score.rotErrDeg[now->category].push_back(
        frontend::rotationAngleDeg(A.linear().transpose() * Agt.linear()));
    score.transErrM[now->category].push_back((A * c - Agt * c).norm());
  }
}

}  // namespace

void ClassificationScore::add(const core::Frame& frame, const Truth& truth, const Truth* previous) {
  std::map<int, bool> matchedNow;  // track id -> matched a detection this frame
  for (const auto& t : frame.tracks) {
    matchedNow[t.id] = t.detection >= 0;
    if (t.detection >= 0 && size_t(t.detection) < frame.detections.size() &&
        frame.detections[size_t(t.detection)].truth_id >= 0)
      trackTruth[t.id] = frame.detections[size_t(t.detection)].truth_id;
  }
  const auto regions = frontend::objectRegions(frame);
  FrameCounts counts;
  for (const auto& f : frame.features) {
    const int label = labelAt(truth.labels, f.pixel);
    counts.labelOfFeature[f.id] = label;
    counts.pixels[f.id] = f.pixel;
    if (previous)
      addTrackingError(*this, frame, truth, *previous,
                       label ? rowOf(truth.objects, label) : nullptr, f);
    addFeatureClass(*this, frame, truth, regions, matchedNow, f, label, counts);
  }
  tallyObjects(*this, truth, counts);
  lastPixel = std::move(counts.pixels);
  if (previous) addRigidSets(*this, frame, truth, *previous, counts.labelOfFeature);
}

}  // namespace dynslam::bench
