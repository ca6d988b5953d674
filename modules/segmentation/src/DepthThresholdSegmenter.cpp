#include "dynslam/segmentation/DepthThresholdSegmenter.h"

#include "ClusterChoice.h"
#include "dynslam/segmentation/DepthSampling.h"
#include "dynslam/segmentation/TwoMeans.h"

#include <dynslam/core/Median.h>

#include <opencv2/core.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace dynslam::segmentation {
namespace {

void requireMetres(const cv::Mat& depth) {
  if (depth.type() != CV_32FC1)
    throw std::invalid_argument("DepthThresholdSegmenter: the depth image must be CV_32FC1 (m)");
}

// expected_depth_band: how far (in ratio) both clusters must be from the expected depth before
// its own samples are sought, and how many of them it takes.
constexpr double kExpectedMiss = 0.15;
constexpr int kExpectedMinSamples = 3;

}  // namespace

DepthThresholdParams methodParams() {
  DepthThresholdParams p;
  p.object_cluster = ObjectCluster::Far;
  p.overlap_rule = OverlapRule::Nearer;
  p.object_depth = ObjectDepth::ClusterMean;
  p.max_height_person = 0;
  p.joint_occluders = false;
  p.retry_taken_surface = false;
  p.expected_depth_band = 0;
  return p;
}

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

bool nearIsExpected(const TwoMeansResult& c, double expected, bool rule) {
  if (!(expected > 0) || !c.two_clusters || !(c.near_mean > 0)) return rule;
  return core::depthRatio(c.near_mean, expected) > core::depthRatio(c.far_mean, expected);
}

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
  requireMetres(depth);
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

std::vector<BoxClusters> DepthThresholdSegmenter::clusterBoxes(
    const cv::Mat& depth, const std::vector<core::Detection>& detections, double fy) const {
  std::vector<BoxClusters> boxes(detections.size());
  for (size_t i = 0; i < boxes.size(); ++i) {
    BoxClusters& b = boxes[i];
    b.roi = pixelRoi(detections[i].box, depth.size());
    b.e = marginFor(detections[i]);
    b.maxDepth = maxDepthFor(detections[i], fy);
    b.ok = candidateClusters(depth, b.roi, b.maxDepth, b.clusters, b.samples);
  }
  return boxes;
}

std::vector<core::ObjectMask> DepthThresholdSegmenter::segment(
    const cv::Mat& depth, const std::vector<core::Detection>& detections,
    const std::vector<double>& expectedDepth, double fy) const {
  const auto expected = [&](size_t i) { return i < expectedDepth.size() ? expectedDepth[i] : 0.0; };
  if (!detections.empty()) requireMetres(depth);
  std::vector<core::ObjectMask> masks;
  masks.reserve(detections.size());
  if (params_.object_cluster != ObjectCluster::OccluderAware) {
    for (size_t i = 0; i < detections.size(); ++i)
      masks.push_back(segmentOne(depth, detections[i], static_cast<int>(i), expected(i), fy));
    resolveOverlaps(masks, depth);
    return masks;
  }
  // Every box's clusters first: each object's are then chosen with the others in view.
  const std::vector<BoxClusters> boxes = clusterBoxes(depth, detections, fy);
  std::vector<ClusterChoice> chosen(boxes.size());  // the clusters each mask was cut on
  for (size_t i = 0; i < boxes.size(); ++i) {
    if (!boxes[i].ok) {
      core::ObjectMask empty;
      empty.detection = int(i);
      empty.roi = boxes[i].roi;
      masks.push_back(empty);
      continue;
    }
    chosen[i] = chooseWithOthersInView(depth, boxes, i, expected(i), params_);
    masks.push_back(segmentWith(depth, detections[i], int(i), chosen[i].clusters,
                                chosen[i].nearIsObject, boxes[i].maxDepth));
  }
  if (params_.retry_taken_surface)
    retryTakenSurfaces(depth, detections, boxes, chosen, masks);
  else
    resolveOverlaps(masks, depth);
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

}  // namespace dynslam::segmentation
