#include "dynslam/segmentation/DepthThresholdSegmenter.h"

#include "dynslam/segmentation/DepthSampling.h"
#include "dynslam/segmentation/TwoMeans.h"

#include <dynslam/core/Median.h>

#include <opencv2/core.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <optional>
#include <stdexcept>
#include <string>

namespace dynslam::segmentation {

DepthThresholdSegmenter::DepthThresholdSegmenter(DepthThresholdParams params)
    : params_(std::move(params)) {}

double DepthThresholdSegmenter::marginFor(const core::Detection& detection) const {
  if (detection.category == "person") return params_.e_person;
  if (detection.category == "car") return params_.e_car;
  return detection.model == core::MotionModel::Rigid ? params_.e_car : params_.e_person;
}

double DepthThresholdSegmenter::maxDepthFor(const core::Detection& detection, double fy) const {
  const double height = detection.category == "person" ? params_.max_height_person : 0.0;
  if (!(height > 0 && fy > 0 && detection.box.height > 0))
    return std::numeric_limits<double>::infinity();
  return height * fy / detection.box.height;
}

cv::Rect pixelRoi(const cv::Rect2f& box, cv::Size size) {
  const auto edge = [](double v) { return static_cast<int>(std::lround(v)); };
  const int x0 = std::max(0, edge(box.x)), y0 = std::max(0, edge(box.y));
  const int x1 = std::min(size.width, edge(double(box.x) + box.width));
  const int y1 = std::min(size.height, edge(double(box.y) + box.height));
  if (x1 <= x0 || y1 <= y0) return {};
  return {x0, y0, x1 - x0, y1 - y0};
}

namespace {

cv::Rect2d candidateBox(const cv::Rect& roi) {
  const cv::Rect2d box(roi);
  return {box.x + box.width / 4, box.y + box.height / 4, box.width / 2, box.height / 2};
}

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
bool surfaceInFront(const cv::Mat& depth, const std::vector<cv::Rect>& fronts,
                    const cv::Rect& back, const TwoMeansResult& c, double margin, int samples) {
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

// Two 2-means clusters more than e apart are two surfaces (an object and what lies behind or
// before it), not the spread of one.
bool twoSurfaces(const TwoMeansResult& c, double e) {
  return c.two_clusters && c.far_mean - c.near_mean > e;
}

// The mean of all the values a 2-means split.
double meanOfAll(const TwoMeansResult& c) {
  return (c.near_mean * c.near_count + c.far_mean * c.far_count) /
         double(c.near_count + c.far_count);
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

// The cluster choice a depth expected for the object makes: near when its mean is nearer that
// depth in ratio. `expected` <= 0 or one cluster: `rule`, the choice without it.
bool nearIsExpected(const TwoMeansResult& c, double expected, bool rule) {
  if (!(expected > 0) || !c.two_clusters || !(c.near_mean > 0)) return rule;
  return core::depthRatio(c.near_mean, expected) > core::depthRatio(c.far_mean, expected);
}

// expected_depth_band: how far (in ratio) both clusters must be from the expected depth before
// its own samples are sought, and how many of them it takes.
constexpr double kExpectedMiss = 0.15;
constexpr int kExpectedMinSamples = 3;

// The clusters with the object's replaced by the depths within `band` of `expected` among m
// grid samples over the whole box `roi` (the hidden person shows above or beside its occluder,
// not in the candidate box it covers) when neither cluster of `c` is within kExpectedMiss of
// it (expected_depth_band); false, and `c` and `nearIsObject` untouched, otherwise. The
// nearest of `c`'s clusters stays beside the object: as its occluder when in front of it.
bool objectAtExpected(const cv::Mat& depth, const cv::Rect& roi, int m, double expected,
                      double band, TwoMeansResult& c, bool& nearIsObject) {
  if (!(band > 0 && expected > 0)) return false;
  double best = core::depthRatio(c.far_mean, expected);
  if (c.near_count > 0) best = std::max(best, core::depthRatio(c.near_mean, expected));
  if (best >= 1 - kExpectedMiss) return false;
  double sum = 0;
  int count = 0;
  forEachGridPoint(depth, cv::Rect2d(roi), m, [&](cv::Point, float z) {
    if (std::abs(z - expected) > band * expected) return;
    sum += z;
    ++count;
  });
  if (count < kExpectedMinSamples) return false;
  const double object = sum / count;
  const double other = c.near_count > 0 ? c.near_mean : c.far_mean;
  const int otherCount = c.near_count > 0 ? c.near_count : c.far_count;
  nearIsObject = object < other;
  c.two_clusters = true;
  c.near_mean = nearIsObject ? object : other;
  c.near_count = nearIsObject ? count : otherCount;
  c.far_mean = nearIsObject ? other : object;
  c.far_count = nearIsObject ? otherCount : count;
  return true;
}

// retry_taken_surface: a mask keeping less than this share of its pixels after the overlap step,
// with another overlapping mask on the same body (d_t within kSameSurface of its own, or nearer
// by less than e / 2: the flank of the body in front, whose d_t is its front), lost its surface
// to it. The flank: a hidden person's mask often holds the side of the person in front, 0.1-0.2
// m behind its front. Measured: docs/notes/perception.md, 2026-11-28 (retry_taken_surface).
constexpr double kTakenFraction = 0.2;
constexpr double kSameSurface = 0.9;

// Did mask i (`before` pixels before the overlap step) lose its surface to another mask? When
// the step left it empty, or under kTakenFraction of its pixels with another overlapping mask
// on the same body (e: the margin of mask i's class).
bool takenSurface(const std::vector<core::ObjectMask>& masks, size_t i, int before, double e) {
  const int now = cv::countNonZero(masks[i].mask);
  if (now == 0) return true;
  if (now >= kTakenFraction * before) return false;
  for (size_t j = 0; j < masks.size(); ++j) {
    if (j == i || !masks[j].valid || (masks[j].roi & masks[i].roi).area() <= 0) continue;
    const double di = masks[i].d_t, dj = masks[j].d_t;
    if (core::depthRatio(dj, di) >= kSameSurface || (dj < di && di - dj < e / 2)) return true;
  }
  return false;
}

// The clusters of an object hidden behind another's `surface`: m grid points over its whole box
// `roi` more than e / 2 behind the surface and not beyond `maxDepth` (max_height_person), of
// whose 2-means the nearer cluster when more than e apart (the object before the wall), else
// their mean, is the object (far cluster) and the surface its occluder (near cluster). False
// with fewer than 4 such points.
bool clustersBehind(const cv::Mat& depth, const cv::Rect& roi, double surface, double e, int m,
                    double maxDepth, TwoMeansResult& out) {
  std::vector<float> behind;
  forEachGridPoint(depth, cv::Rect2d(roi), m, [&](cv::Point, float z) {
    if (z > surface + e / 2 && z <= maxDepth) behind.push_back(z);
  });
  if (behind.size() < 4) return false;
  const TwoMeansResult rest = twoMeans(behind);
  out.two_clusters = true;
  out.near_mean = surface;
  out.near_count = 0;
  out.far_count = int(behind.size());
  out.far_mean = twoSurfaces(rest, e) ? rest.near_mean : meanOfAll(rest);
  return true;
}

}  // namespace

bool DepthThresholdSegmenter::candidateClusters(const cv::Mat& depth, const cv::Rect& roi,
                                                double maxDepth, TwoMeansResult& out,
                                                std::vector<float>& samples) const {
  if (roi.empty()) return false;
  // Steps 1-3: the candidate box M (same centre, half the size), m grid samples, 2-means.
  samples.clear();
  samples.reserve(params_.m);
  const int gridPoints = sampleGrid(depth, candidateBox(roi), params_.m, samples);
  const int needed =
      std::max(1, static_cast<int>(std::ceil(params_.min_valid_fraction * gridPoints)));
  if (static_cast<int>(samples.size()) < needed) return false;
  // Samples beyond the object's farthest possible depth are background (max_height_person); when
  // fewer than two are left, the box shows nothing of it at a possible depth and all stay.
  const auto beyond =
      std::count_if(samples.begin(), samples.end(), [&](float z) { return z > maxDepth; });
  if (beyond > 0 && samples.size() - size_t(beyond) >= 2)
    samples.erase(
        std::remove_if(samples.begin(), samples.end(), [&](float z) { return z > maxDepth; }),
        samples.end());
  out = twoMeans(samples);
  return true;
}

core::ObjectMask DepthThresholdSegmenter::segmentOne(const cv::Mat& depth,
                                                     const core::Detection& detection,
                                                     int detectionIndex, double expectedDepth,
                                                     double fy) const {
  if (depth.type() != CV_32FC1)
    throw std::invalid_argument("DepthThresholdSegmenter: the depth image must be CV_32FC1 (m)");
  core::ObjectMask out;
  out.detection = detectionIndex;
  out.roi = pixelRoi(detection.box, depth.size());
  TwoMeansResult clusters;
  std::vector<float> samples;
  const double maxDepth = maxDepthFor(detection, fy);
  if (!candidateClusters(depth, out.roi, maxDepth, clusters, samples)) return out;
  bool nearIsObject = false;
  if (params_.object_cluster == ObjectCluster::Larger)
    nearIsObject = clusters.near_count > clusters.far_count;
  else if (params_.object_cluster == ObjectCluster::OccluderAware)  // no other box: no occluder
    nearIsObject = twoSurfaces(clusters, marginFor(detection));
  nearIsObject = nearIsExpected(clusters, expectedDepth, nearIsObject);
  objectAtExpected(depth, out.roi, params_.m, expectedDepth, params_.expected_depth_band, clusters,
                   nearIsObject);
  return segmentWith(depth, detection, detectionIndex, clusters, nearIsObject, maxDepth);
}

core::ObjectMask DepthThresholdSegmenter::segmentWith(const cv::Mat& depth,
                                                      const core::Detection& detection,
                                                      int detectionIndex,
                                                      const TwoMeansResult& clusters,
                                                      bool nearIsObject, double maxDepth) const {
  core::ObjectMask out;
  out.detection = detectionIndex;
  out.roi = pixelRoi(detection.box, depth.size());
  const cv::Rect2d box(out.roi);
  const double e = marginFor(detection);
  out.d_t = nearIsObject ? clusters.near_mean : clusters.far_mean;
  if (clusters.two_clusters) out.d_alt = nearIsObject ? clusters.far_mean : clusters.near_mean;

  // Step 4: a near cluster more than e in front is an occluder; otherwise there is none
  // (d_o = 0, also when every sample had the same depth and 2-means found one cluster).
  const bool occluded = !nearIsObject && clusters.two_clusters && out.d_t - clusters.near_mean > e;
  out.d_o = occluded ? clusters.near_mean : 0.0;
  out.t_min = occluded ? (out.d_t + out.d_o) / 2 : out.d_t - e;

  // Steps 5-6: background from the upper half of B (the lower half shows the floor). With no
  // valid sample there d_b = 0, which takes the "no background behind" branch: d_t + e.
  std::vector<float> background;
  background.reserve(params_.n);
  sampleGrid(depth, cv::Rect2d(box.x, box.y, box.width, box.height / 2), params_.n, background);
  out.d_b = threeSigmaMean(background);
  out.t_max = out.d_b - out.d_t > e ? (out.d_t + out.d_b) / 2 : out.d_t + e;
  out.t_max = std::max(std::min(out.t_max, maxDepth), out.d_t);  // max_height_person

  // Step 8. The lower bound stays above 0 so that missing depth (0) never joins the mask when
  // d_t - e <= 0 (a car nearer than 3 m).
  const double lower = std::max(out.t_min, double(std::numeric_limits<float>::min()));
  cv::inRange(depth(out.roi), lower, out.t_max, out.mask);
  out.valid = true;
  return out;
}

std::vector<core::ObjectMask> DepthThresholdSegmenter::segment(
    const cv::Mat& depth, const std::vector<core::Detection>& detections,
    const std::vector<double>& expectedDepth, double fy) const {
  const auto expected = [&](size_t i) { return i < expectedDepth.size() ? expectedDepth[i] : 0.0; };
  if (depth.type() != CV_32FC1 && !detections.empty())
    throw std::invalid_argument("DepthThresholdSegmenter: the depth image must be CV_32FC1 (m)");
  std::vector<core::ObjectMask> masks;
  masks.reserve(detections.size());
  if (params_.object_cluster != ObjectCluster::OccluderAware) {
    for (size_t i = 0; i < detections.size(); ++i)
      masks.push_back(segmentOne(depth, detections[i], static_cast<int>(i), expected(i), fy));
    resolveOverlaps(masks, depth);
    return masks;
  }
  const size_t n = detections.size();
  std::vector<cv::Rect> rois(n);
  std::vector<TwoMeansResult> clusters(n);
  std::vector<std::vector<float>> samples(n);
  std::vector<char> ok(n);
  std::vector<double> maxDepth(n);
  for (size_t i = 0; i < n; ++i) {
    rois[i] = pixelRoi(detections[i].box, depth.size());
    maxDepth[i] = maxDepthFor(detections[i], fy);
    ok[i] = candidateClusters(depth, rois[i], maxDepth[i], clusters[i], samples[i]);
  }
  std::vector<TwoMeansResult> chosen(n);  // the clusters each mask was cut on
  std::vector<char> chosenNear(n);
  for (size_t i = 0; i < n; ++i) {
    if (!ok[i]) {
      core::ObjectMask empty;
      empty.detection = int(i);
      empty.roi = rois[i];
      masks.push_back(empty);
      continue;
    }
    TwoMeansResult c = clusters[i];
    const double e = marginFor(detections[i]);
    bool nearIsObject = twoSurfaces(c, e);
    bool occluded = false;
    // Is the near surface another detection standing in front?
    const cv::Rect2d candidate = candidateBox(rois[i]);
    // joint_occluders: the detections at the near surface's depth whose bottoms do not put them
    // behind it.
    std::vector<cv::Rect> together;
    double togetherMargin = e;
    for (size_t j = 0; j < n && nearIsObject; ++j) {
      if (j == i || !ok[j] || (cv::Rect2d(rois[j]) & candidate).empty()) continue;
      const double ej = marginFor(detections[j]);
      const double nearest =
          clusters[j].two_clusters ? clusters[j].near_mean : clusters[j].far_mean;
      if (std::abs(nearest - c.near_mean) >= ej &&
          std::abs(clusters[j].far_mean - c.near_mean) >= ej)
        continue;
      // Does j stand in front of i? The bottoms when they tell, else the near surface's place.
      const std::optional<bool> bottoms = bottomsSayInFront(rois[j], rois[i], depth.rows);
      if (params_.joint_occluders && bottoms.value_or(true)) {
        together.push_back(rois[j]);
        togetherMargin = std::min(togetherMargin, ej);
      }
      const bool inFront =
          bottoms ? *bottoms : surfaceInFront(depth, {rois[j]}, rois[i], c, ej / 2, params_.m);
      if (!inFront) continue;
      nearIsObject = false;
      occluded = true;
      c = behindOccluder(depth, rois[i], {rois[j]}, samples[i], c, ej / 2, e, params_.m,
                         maxDepth[i]);
    }
    // Two people may hide it together, each covering too little of its box alone (between
    // them: the near samples split between their boxes).
    if (nearIsObject && together.size() >= 2 &&
        surfaceInFront(depth, together, rois[i], c, togetherMargin / 2, params_.m)) {
      nearIsObject = false;
      occluded = true;
      c = behindOccluder(depth, rois[i], together, samples[i], c, togetherMargin / 2, e,
                         params_.m, maxDepth[i]);
    }
    // A detection seen standing in front outweighs the track's depth: a track that followed
    // the occluder's surface would otherwise keep choosing it.
    if (!occluded) nearIsObject = nearIsExpected(c, expected(i), nearIsObject);
    objectAtExpected(depth, rois[i], params_.m, expected(i), params_.expected_depth_band, c,
                     nearIsObject);
    masks.push_back(segmentWith(depth, detections[i], int(i), c, nearIsObject, maxDepth[i]));
    chosen[i] = c;
    chosenNear[i] = nearIsObject;
  }
  std::vector<int> cut(n, 0);  // each mask's pixels before the overlap step
  if (params_.retry_taken_surface)
    for (size_t i = 0; i < n; ++i)
      if (masks[i].valid && !masks[i].mask.empty()) cut[i] = cv::countNonZero(masks[i].mask);
  resolveOverlaps(masks, depth);
  if (!params_.retry_taken_surface) return masks;
  // A mask whose surface the overlap step gave to another object was cut on that object's
  // surface: two detections are not one surface, so it is cut again on what its box shows
  // behind that surface, and the overlaps are resolved again.
  bool retried = false;
  for (size_t i = 0; i < n; ++i) {
    const double e = marginFor(detections[i]);
    if (!masks[i].valid || !takenSurface(masks, i, cut[i], e)) continue;
    const TwoMeansResult& c = chosen[i];
    const double surface = chosenNear[i] ? c.near_mean : c.far_mean;
    TwoMeansResult behind;
    if (clustersBehind(depth, rois[i], surface, e, params_.m, maxDepth[i], behind)) {
      masks[i] = segmentWith(depth, detections[i], int(i), behind, false, maxDepth[i]);
      retried = true;
    } else if (cv::countNonZero(masks[i].mask) == 0 && twoSurfaces(c, e)) {
      // nothing behind: the other cluster
      masks[i] = segmentWith(depth, detections[i], int(i), c, !chosenNear[i], maxDepth[i]);
      retried = true;
    }
  }
  if (retried) resolveOverlaps(masks, depth);
  return masks;
}

void DepthThresholdSegmenter::resolveOverlaps(std::vector<core::ObjectMask>& masks,
                                              const cv::Mat& depth) const {
  if (params_.overlap_rule == OverlapRule::ClosestDepth)
    resolveByClosestDepth(masks, depth);
  else if (params_.overlap_rule == OverlapRule::Connected)
    resolveByConnectivity(masks, depth);
  else
    resolveMutualOcclusion(masks);
  if (params_.object_depth == ObjectDepth::MaskMedian)
    for (auto& m : masks)
      if (const double z = maskMedianDepth(m, depth, 2); z > 0) m.d_t = z;
}

double maskMedianDepth(const core::ObjectMask& mask, const cv::Mat& depth, int stride) {
  if (!mask.valid || mask.mask.empty()) return 0;
  stride = std::max(1, stride);
  std::vector<float> z;
  z.reserve(size_t(mask.roi.area() / (stride * stride)) + 1);
  for (int y = 0; y < mask.roi.height; y += stride) {
    const uint8_t* in = mask.mask.ptr<uint8_t>(y);
    const float* d = depth.ptr<float>(mask.roi.y + y) + mask.roi.x;
    for (int x = 0; x < mask.roi.width; x += stride)
      if (in[x] && d[x] > 0 && std::isfinite(d[x])) z.push_back(d[x]);
  }
  return core::upperMedianInPlace(z);
}

void resolveByClosestDepth(std::vector<core::ObjectMask>& masks, const cv::Mat& depth) {
  for (size_t a = 0; a < masks.size(); ++a)
    for (size_t b = a + 1; b < masks.size(); ++b) {
      core::ObjectMask &A = masks[a], &B = masks[b];
      if (!A.valid || !B.valid || A.mask.empty() || B.mask.empty()) continue;
      const cv::Rect overlap = A.roi & B.roi;
      for (int y = overlap.y; y < overlap.y + overlap.height; ++y) {
        uint8_t* rowA = A.mask.ptr<uint8_t>(y - A.roi.y) - A.roi.x;
        uint8_t* rowB = B.mask.ptr<uint8_t>(y - B.roi.y) - B.roi.x;
        const float* z = depth.ptr<float>(y);
        for (int x = overlap.x; x < overlap.x + overlap.width; ++x) {
          if (!rowA[x] || !rowB[x]) continue;
          const double da = std::abs(z[x] - A.d_t), db = std::abs(z[x] - B.d_t);
          const bool toA = da < db || (da == db && A.d_t <= B.d_t);
          (toA ? rowB : rowA)[x] = 0;
        }
      }
    }
}

void resolveMutualOcclusion(std::vector<core::ObjectMask>& masks) {
  std::vector<size_t> order;
  for (size_t i = 0; i < masks.size(); ++i)
    if (masks[i].valid && !masks[i].mask.empty()) order.push_back(i);
  std::stable_sort(order.begin(), order.end(),
                   [&](size_t a, size_t b) { return masks[a].d_t < masks[b].d_t; });
  // Nearest first: each mask gives up the pixels that a nearer mask already holds. A pixel in
  // the range of several objects thus ends in the nearest one; a pixel in one range only
  // stays where it is.
  for (size_t k = 1; k < order.size(); ++k) {
    auto& far = masks[order[k]];
    for (size_t j = 0; j < k; ++j) {
      const auto& near = masks[order[j]];
      const cv::Rect overlap = far.roi & near.roi;
      if (overlap.empty()) continue;
      far.mask(overlap - far.roi.tl()).setTo(0, near.mask(overlap - near.roi.tl()));
    }
  }
}

}  // namespace dynslam::segmentation
