#include "dynslam/frontend/ObjectMembership.h"

#include <algorithm>
#include <cmath>

namespace dynslam::frontend {
namespace {

/// The track of mask `m`: ObjectMask::track, else the track matched to its detection; nullptr.
const core::Track* trackOf(const core::Frame& frame, const core::ObjectMask& m) {
  int track = m.track;
  if (track < 0 && m.detection >= 0)
    for (size_t i = 0; i < frame.tracks.size(); ++i)
      if (frame.tracks[i].detection == m.detection) track = int(i);
  if (track < 0 || size_t(track) >= frame.tracks.size()) return nullptr;
  return &frame.tracks[size_t(track)];
}

}  // namespace

std::vector<ObjectRegion> objectRegions(const core::Frame& frame) {
  std::vector<ObjectRegion> regions;
  for (const auto& m : frame.object_masks) {
    if (!m.valid || m.mask.empty()) continue;
    if (const core::Track* tr = trackOf(frame, m))
      regions.push_back({tr->id, tr->model, m.roi, m.mask, m.d_t});
  }
  std::stable_sort(regions.begin(), regions.end(),
                   [](const ObjectRegion& a, const ObjectRegion& b) { return a.depth < b.depth; });
  return regions;
}

std::vector<ObjectRegion> depthlessObjectBoxes(const core::Frame& frame) {
  std::vector<ObjectRegion> boxes;
  for (const auto& m : frame.object_masks) {
    if (m.valid || m.roi.area() <= 0) continue;
    if (const core::Track* tr = trackOf(frame, m))
      boxes.push_back({tr->id, tr->model, m.roi, cv::Mat(), 0.0});
  }
  return boxes;
}

const ObjectRegion* regionAt(const std::vector<ObjectRegion>& regions, const cv::Point2f& pixel) {
  const int x = int(std::lround(pixel.x)), y = int(std::lround(pixel.y));
  for (const auto& r : regions) {
    if (!r.roi.contains({x, y})) continue;
    if (r.mask.at<uint8_t>(y - r.roi.y, x - r.roi.x) != 0) return &r;
  }
  return nullptr;
}

}  // namespace dynslam::frontend
