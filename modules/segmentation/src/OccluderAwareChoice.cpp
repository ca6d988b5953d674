#include "ClusterChoice.h"
#include "dynslam/segmentation/DepthSampling.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace dynslam::segmentation {
namespace {

// Is `p` inside any of `boxes`?
bool insideAny(const std::vector<cv::Rect>& boxes, cv::Point p) {
  return std::any_of(boxes.begin(), boxes.end(), [&](const cv::Rect& b) { return b.contains(p); });
}

// A detector's box edges are a few pixels off (GroundTruthDetector's 3 px jitter; a box cut at
// the image's edge may end a few rows short of it): edges within this many pixels of each other
// or of the image's edge say nothing. Seen: docs/notes/perception.md, 2026-11-28.
int edgeTolerance(int rows) { return std::max(2, rows / 50); }

// What the boxes' bottoms say of whether the detection boxed `front` stands in front of the one
// boxed `back`: on a flat floor the box reaching lower in the image is the nearer one, and a box
// cut off by the image's bottom edge is nearer than one whose bottom shows. When both are cut
// off, or their bottoms lie within a detector's few pixels of each other, nothing (nullopt).
std::optional<bool> bottomsSayInFront(const cv::Rect& front, const cv::Rect& back, int rows) {
  const int tolerance = edgeTolerance(rows);
  const int frontBottom = front.y + front.height, backBottom = back.y + back.height;
  const bool frontCut = frontBottom >= rows - tolerance;
  const bool backCut = backBottom >= rows - tolerance;
  if (frontCut != backCut) return frontCut;
  if (!frontCut && std::abs(frontBottom - backBottom) > tolerance) return frontBottom > backBottom;
  return std::nullopt;
}

// Is the near surface of the detection boxed `back`, whose candidate samples split into 2-means
// clusters `c`, that of the detections boxed `fronts` (one, or several hiding it together)?
// Yes when (a) `back`'s near samples lie inside the fronts' boxes, and so does that surface
// wherever it shows in `back`'s whole box (an occluder's pixels are inside its box; a person
// beside `back` at the same depth shows also outside it), and (b) the surface also shows in the
// fronts' candidate boxes outside `back`'s box (an occluder is larger than the part of it in
// front of `back`; a person behind `back` shows there at its own, farther, depth). When the
// fronts' candidate boxes lie wholly inside `back`'s box, (b) cannot tell, and of two people
// the one whose box reaches higher in the image is the nearer (heads of similar heights; the
// bottoms said nothing). Why: docs/notes/perception.md, 2026-11-28 (surfaceInFront).
bool surfaceInFront(const cv::Mat& depth, const std::vector<cv::Rect>& fronts, const cv::Rect& back,
                    const TwoMeansResult& c, double margin, int samples) {
  int nearSamples = 0, nearInside = 0;
  forEachGridPoint(depth, candidateBox(back), samples, [&](cv::Point p, float z) {
    if (std::abs(z - c.near_mean) >= std::abs(z - c.far_mean)) return;
    ++nearSamples;
    nearInside += insideAny(fronts, p);
  });
  if (nearSamples == 0 || nearInside < 0.9 * nearSamples) return false;
  // The same over the whole of `back`'s box, where a person beside `back` whose box covers the
  // candidate box still shows (95 %: the floor at the occluder's feet may reach its depth).
  int nearInBox = 0, nearInFront = 0;
  forEachGridPoint(depth, cv::Rect2d(back), samples, [&](cv::Point p, float z) {
    if (std::abs(z - c.near_mean) >= margin) return;
    ++nearInBox;
    nearInFront += insideAny(fronts, p);
  });
  if (nearInBox == 0 || nearInFront < 0.95 * nearInBox) return false;
  int outside = 0, onSurface = 0;
  for (const cv::Rect& front : fronts)
    forEachGridPoint(depth, candidateBox(front), samples, [&](cv::Point p, float z) {
      if (back.contains(p)) return;
      ++outside;
      onSurface += std::abs(z - c.near_mean) < margin;
    });
  const int tolerance = edgeTolerance(depth.rows);
  if (outside == 0)
    return std::any_of(fronts.begin(), fronts.end(),
                       [&](const cv::Rect& f) { return f.y < back.y - tolerance; });
  return onSurface >= 0.3 * outside;
}

// Below this share of a candidate box's samples, the far cluster behind an occluder is stray
// background between the occluder's limbs rather than the object: the occluder hides the whole
// centre of the box, and the object shows only beside it (behindOccluder).
constexpr double kFewBehind = 0.25;

// The object's clusters in a box whose near cluster `c.near_mean` is the surface of occluders
// boxed `occluders`. When the far cluster holds enough of the candidate samples, they are what lies
// behind the occluder, and may themselves be the object in front of the background, which the
// far cluster's mean would blur into one depth: of two clusters more than `e` apart, the
// nearer, as without an occluder. When the occluder hides nearly all of the candidate box, the
// object is sought where it can show: m grid points over the whole box `roi` outside the
// occluders' boxes and more than `margin` behind it, split by the same rule. (What else was
// tried: docs/notes/perception.md, 2026-11-28, behindOccluder.)
TwoMeansResult behindOccluder(const cv::Mat& depth, const cv::Rect& roi,
                              const std::vector<cv::Rect>& occluders,
                              const std::vector<float>& sorted, const TwoMeansResult& c,
                              double margin, double e, int m, double maxDepth) {
  std::vector<float> behind;
  if (c.far_count < kFewBehind * (c.near_count + c.far_count)) {
    forEachGridPoint(depth, cv::Rect2d(roi), m, [&](cv::Point p, float z) {
      if (!insideAny(occluders, p) && z > c.near_mean + margin && z <= maxDepth)
        behind.push_back(z);
    });
  }
  const bool beside = behind.size() >= 4;  // else too little to tell the object from background
  if (!beside) behind.assign(sorted.end() - c.far_count, sorted.end());
  const TwoMeansResult rest = twoMeans(behind);
  TwoMeansResult out = c;
  if (twoSurfaces(rest, e)) {
    out.far_mean = rest.near_mean;
    out.far_count = rest.near_count;
  } else if (beside) {
    out.far_mean = meanOfAll(rest);
    out.far_count = int(behind.size());
  }
  return out;
}

// The detections seen standing in front of a box, hiding its near surface, and the margin its
// object is sought behind them by (half the occluders' smallest e); none: no boxes.
struct Occluders {
  std::vector<cv::Rect> boxes;
  double margin = 0;
};

// Is one of `front`'s clusters within its e of `depth` (the near surface of another box)?
bool atDepth(const BoxClusters& front, double depth) {
  const TwoMeansResult& c = front.clusters;
  const double nearest = c.two_clusters ? c.near_mean : c.far_mean;
  return std::abs(nearest - depth) < front.e || std::abs(c.far_mean - depth) < front.e;
}

// What hides box i's near surface: the first detection at that surface's depth, overlapping
// its candidate box, that stands in front of it (the bottoms when they tell, else where the
// surface shows); else, with joint_occluders, those at that depth whose bottoms do not put them
// behind it, together (a person between two nearer people, each covering part of its box,
// otherwise takes their surface as its own).
Occluders occludersOf(const cv::Mat& depth, const std::vector<BoxClusters>& boxes, size_t i,
                      const DepthThresholdParams& p) {
  const BoxClusters& back = boxes[i];
  const TwoMeansResult& c = back.clusters;
  const cv::Rect2d candidate = candidateBox(back.roi);
  std::vector<cv::Rect> together;
  double togetherMargin = back.e;
  for (size_t j = 0; j < boxes.size(); ++j) {
    const BoxClusters& front = boxes[j];
    if (j == i || !front.ok || (cv::Rect2d(front.roi) & candidate).empty()) continue;
    if (!atDepth(front, c.near_mean)) continue;
    const std::optional<bool> bottoms = bottomsSayInFront(front.roi, back.roi, depth.rows);
    if (p.joint_occluders && bottoms.value_or(true)) {
      together.push_back(front.roi);
      togetherMargin = std::min(togetherMargin, front.e);
    }
    const bool inFront =
        bottoms ? *bottoms : surfaceInFront(depth, {front.roi}, back.roi, c, front.e / 2, p.m);
    if (inFront) return {{front.roi}, front.e / 2};
  }
  // Two people may hide it together, each covering too little of its box alone (between them:
  // the near samples split between their boxes).
  if (together.size() >= 2 && surfaceInFront(depth, together, back.roi, c, togetherMargin / 2, p.m))
    return {together, togetherMargin / 2};
  return {};
}

}  // namespace

ClusterChoice chooseWithOthersInView(const cv::Mat& depth, const std::vector<BoxClusters>& boxes,
                                     size_t i, double expected, const DepthThresholdParams& p) {
  const BoxClusters& box = boxes[i];
  ClusterChoice out{box.clusters, twoSurfaces(box.clusters, box.e)};
  const Occluders front = out.nearIsObject ? occludersOf(depth, boxes, i, p) : Occluders{};
  if (!front.boxes.empty()) {
    out.nearIsObject = false;
    out.clusters = behindOccluder(depth, box.roi, front.boxes, box.samples, out.clusters,
                                  front.margin, box.e, p.m, box.maxDepth);
  } else {
    // A detection seen standing in front outweighs the track's depth: a track that followed
    // the occluder's surface would otherwise keep choosing it.
    out.nearIsObject = nearIsExpected(out.clusters, expected, out.nearIsObject);
  }
  objectAtExpected(depth, box.roi, p.m, expected, p.expected_depth_band, out.clusters,
                   out.nearIsObject);
  return out;
}

}  // namespace dynslam::segmentation
