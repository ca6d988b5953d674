#include "dynslam/segmentation/SegmentationStage.h"

#include <stdexcept>

namespace dynslam::segmentation {
namespace {

constexpr core::Keyword<ObjectCluster> kClusters[] = {
    {"far", ObjectCluster::Far},
    {"larger", ObjectCluster::Larger},
    {"occluder_aware", ObjectCluster::OccluderAware}};
constexpr core::Keyword<OverlapRule> kOverlapRules[] = {
    {"nearer", OverlapRule::Nearer},
    {"closest_depth", OverlapRule::ClosestDepth},
    {"connected", OverlapRule::Connected}};
constexpr core::Keyword<ObjectDepth> kObjectDepths[] = {{"cluster_mean", ObjectDepth::ClusterMean},
                                                        {"mask_median", ObjectDepth::MaskMedian}};
constexpr core::Keyword<SegmentedBoxes> kBoxes[] = {
    {"detections", SegmentedBoxes::Detections},
    {"predicted_tracks", SegmentedBoxes::PredictedTracks},
    {"tracked_detections", SegmentedBoxes::TrackedDetections}};

// Boxes to segment need the frame's depth image: else an error naming the frame.
void requireDepth(const core::Frame& frame, size_t boxes, const char* what) {
  if (frame.depth.empty() && boxes > 0)
    throw std::runtime_error("Segmentation: frame " + std::to_string(frame.index) + " has " + what +
                             " but no depth image");
}

}  // namespace

void SegmentationOptions::describe(core::OptionVisitor& v) {
  using core::Range;
  auto& p = params;
  const Range metres = Range::above(0);
  v.key("m", p.m, Range::atLeast(2),
        "depth samples on an even grid over the candidate box (central half of the box)");
  v.key("n", p.n, Range::atLeast(1),
        "depth samples on an even grid over the upper half of the box (background)");
  v.key("e_person", p.e_person, metres,
        "m; depth margin e of people (method: 0.5), and of other classes mapped to non_rigid");
  v.key("e_car", p.e_car, metres,
        "m; depth margin e of cars (method: 3.0), and of other classes mapped to rigid");
  v.key("min_valid_fraction", p.min_valid_fraction, Range{0, 1, true, false},
        "of the m samples with depth, else the mask is not valid (empty)");
  v.key("max_height_person", p.max_height_person, Range::atLeast(0),
        "m; 0 = off. Not the method: a person is at most this tall, so a box h px high holds "
        "nothing of it beyond max_height_person * fy / h; farther samples are background");
  v.key("expected_depth_band", p.expected_depth_band, Range::closedOpen(0, 1),
        "0 = off; when neither cluster is within 15 % of the track's depth, the samples within "
        "this fraction of it are the object (not the method)");
  v.key("retry_taken_surface", p.retry_taken_surface,
        "a mask whose surface the overlap step gives to another object is cut again on what its "
        "box shows behind that surface (not the method)");
  v.key("joint_occluders", p.joint_occluders,
        "when no single nearer detection passes as the occluder, those at the near surface's "
        "depth are tested together (a person between two nearer people; not the method)");
  v.key("object_cluster", p.object_cluster, kClusters,
        "far: the far 2-means cluster is the object (method.md); larger: the cluster with more "
        "samples; occluder_aware: the near cluster unless a nearer detection claims it (both "
        "variants, not the method)");
  v.key("overlap_rule", p.overlap_rule, kOverlapRules,
        "pixels several masks hold: nearer = the nearest object (method.md); closest_depth = "
        "the object whose d_t is closest to the pixel's depth; connected = the object whose "
        "depth-continuous surface reaches it (both not the method)");
  v.key("object_depth", p.object_depth, kObjectDepths,
        "the d_t each mask reports: cluster_mean = the object's 2-means cluster (method.md); "
        "mask_median = the median depth of the final mask (not the method)");
  v.key("boxes", boxes, kBoxes,
        "detections: the detector's boxes; predicted_tracks: the predicted boxes of confirmed "
        "tracks no detection took this frame (list the stage again after Tracking); "
        "tracked_detections: the detections again, each object cluster chosen by its track's "
        "depth (after Tracking; not the method)");
  v.key("max_track_misses", max_track_misses, Range::atLeast(0),
        "only tracks coasting at most this many frames get a mask (0: every confirmed track; "
        "not the method): a track coasting long predicts a box where its object no longer is");

  // Settings that act only through another: set alone, they would silently do nothing.
  const bool occluderAware = p.object_cluster == ObjectCluster::OccluderAware;
  v.requires("retry_taken_surface", p.retry_taken_surface, "object_cluster = occluder_aware",
             occluderAware);
  v.requires("joint_occluders", p.joint_occluders, "object_cluster = occluder_aware",
             occluderAware);
  v.requires("expected_depth_band", p.expected_depth_band > 0, "boxes = tracked_detections",
             boxes == SegmentedBoxes::TrackedDetections);
  v.requires("max_track_misses", max_track_misses > 0, "boxes = predicted_tracks",
             boxes == SegmentedBoxes::PredictedTracks);
}

void SegmentationStage::configure(const core::IniConfig& cfg, const std::string& section) {
  core::loadOptionsStrict(options_, cfg, section);
  segmenter_ = DepthThresholdSegmenter(options_.params);
}

void SegmentationStage::segmentPredictedTracks(core::Frame& frame) const {
  // Every confirmed track that no detection of this frame took: all of them on a frame the
  // real-time detector skipped, the coasting ones (the detector missed the object) otherwise.
  std::vector<core::Detection> boxes;
  std::vector<int> trackOf;
  for (size_t i = 0; i < frame.tracks.size(); ++i) {
    const auto& t = frame.tracks[i];
    if (t.state != core::TrackState::Confirmed || t.detection >= 0) continue;
    if (options_.max_track_misses > 0 && t.misses > options_.max_track_misses) continue;
    core::Detection box;
    box.box = t.box;
    box.category = t.category;
    box.model = t.model;
    boxes.push_back(box);
    trackOf.push_back(int(i));
  }
  requireDepth(frame, boxes.size(), "predicted boxes");
  auto masks = segmenter_.segment(frame.depth, boxes, {}, frame.intrinsics.fy);
  for (size_t k = 0; k < masks.size(); ++k) {
    masks[k].detection = -1;
    masks[k].track = trackOf[k];
  }
  if (!frame.detections_fresh) frame.object_masks.clear();
  frame.object_masks.insert(frame.object_masks.end(), masks.begin(), masks.end());
}

void SegmentationStage::segmentTrackedDetections(core::Frame& frame) const {
  if (frame.detections.empty()) return;
  requireDepth(frame, frame.detections.size(), "detections");
  std::vector<double> expected(frame.detections.size(), 0.0);
  std::vector<int> trackOf(frame.detections.size(), -1);
  for (size_t k = 0; k < frame.tracks.size(); ++k) {
    const int d = frame.tracks[k].detection;
    if (d >= 0 && size_t(d) < expected.size()) {
      expected[size_t(d)] = frame.tracks[k].depth;
      trackOf[size_t(d)] = int(k);
    }
  }
  auto masks = segmenter_.segment(frame.depth, frame.detections, expected, frame.intrinsics.fy);
  for (size_t i = 0; i < masks.size(); ++i) masks[i].track = trackOf[i];
  // The detections' masks are replaced; masks of predicted boxes (detection -1) stay.
  for (const auto& m : frame.object_masks)
    if (m.detection < 0) masks.push_back(m);
  frame.object_masks = std::move(masks);
}

void SegmentationStage::process(core::Frame& frame) {
  if (options_.boxes == SegmentedBoxes::PredictedTracks) {
    segmentPredictedTracks(frame);
  } else if (options_.boxes == SegmentedBoxes::TrackedDetections) {
    segmentTrackedDetections(frame);
  } else {
    requireDepth(frame, frame.detections.size(), "detections");
    frame.object_masks = segmenter_.segment(frame.depth, frame.detections, {}, frame.intrinsics.fy);
  }
  ++frames_;
  for (const auto& m : frame.object_masks) {
    ++masks_;
    invalid_ += !m.valid;
  }
}

void SegmentationStage::finish() {
  MRPT_LOG_INFO_STREAM(frames_ << " frames, " << masks_ << " masks, " << invalid_
                               << " without enough depth");
}

}  // namespace dynslam::segmentation
