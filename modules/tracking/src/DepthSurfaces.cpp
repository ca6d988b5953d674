#include "DepthSurfaces.h"

#include "dynslam/tracking/DepthIoU.h"

namespace dynslam::tracking {

bool coveredBy(const cv::Rect2f& box, const cv::Rect2f& other) {
  return (other & box).area() > 0.2f * box.area();
}

bool occluded(const std::vector<BoxObservation>& observations, size_t j) {
  const BoxObservation& o = observations[j];
  for (size_t k = 0; k < observations.size(); ++k) {
    const BoxObservation& n = observations[k];
    if (k == j || !(n.depth > 0 && o.depth > 0 && n.depth < o.depth)) continue;
    if (coveredBy(o.box, n.box)) return true;
  }
  return false;
}

cv::Rect2f clippedToImage(const cv::Rect2f& box, const cv::Size& image) {
  return image.empty() ? box : box & cv::Rect2f(0, 0, float(image.width), float(image.height));
}

namespace {

/// True when `depth` is the surface at `surface` (m): within kSameSurfaceRatio of it and nearer
/// it than `otherDepth`.
bool isSurface(double surface, double depth, double otherDepth) {
  const double same = core::depthRatio(surface, depth);
  return same >= kSameSurfaceRatio && same > core::depthRatio(surface, otherDepth);
}

/// True when `depth` is the surface of another observation whose box overlaps observation j's
/// (isSurface of its d_t).
bool surfaceOfAnother(const std::vector<BoxObservation>& observations, size_t j, double depth,
                      double otherDepth) {
  for (size_t k = 0; k < observations.size(); ++k) {
    const BoxObservation& n = observations[k];
    if (k == j || !(n.depth > 0) || (n.box & observations[j].box).area() <= 0) continue;
    if (isSurface(n.depth, depth, otherDepth)) return true;
  }
  return false;
}

/// alternative_depth_tracks: true when `depth` (of a detection's `box`) is the surface of one of
/// `tracks` (isSurface of its depth) whose box overlaps the detection's, as surfaceOfAnother
/// asks of detections, but too little to be its own track (box IoU <= maxOwnIoU, so its depth
/// IoU cannot pass rho_min). (Asking the track's box to cover a fifth of the detection's, as
/// descriptor_own_surface does, gained less: docs/notes/perception.md, 2026-11-28,
/// alternative_depth_tracks.)
bool surfaceOfTrack(const std::vector<TrackSurface>& tracks, const cv::Rect2f& box, double depth,
                    double otherDepth, double maxOwnIoU) {
  for (const TrackSurface& t : tracks) {
    if ((t.box & box).area() <= 0 || boxIoU(t.box, box) > maxOwnIoU) continue;
    if (isSurface(t.depth, depth, otherDepth)) return true;
  }
  return false;
}

}  // namespace

bool givenAnothersSurface(const std::vector<BoxObservation>& observations, size_t j) {
  return observations[j].depth > 0 && surfaceOfAnother(observations, j, observations[j].depth, 0.0);
}

std::vector<BoxObservation> withOwnedAlternatives(std::vector<BoxObservation> observations,
                                                  const std::vector<TrackSurface>& tracks,
                                                  double maxOwnIoU) {
  // surfaceOfAnother reads the others' d_t only: d_alt can be cleared as the loop goes.
  for (size_t j = 0; j < observations.size(); ++j) {
    BoxObservation& o = observations[j];
    if (!(o.depth > 0 && o.depth_alt > 0)) continue;
    const bool usable =
        surfaceOfAnother(observations, j, o.depth, o.depth_alt) ||
        surfaceOfTrack(tracks, o.box, o.depth, o.depth_alt, maxOwnIoU) ||
        (o.depth_alt < o.depth && !surfaceOfAnother(observations, j, o.depth_alt, o.depth));
    if (!usable) o.depth_alt = 0;
  }
  return observations;
}

}  // namespace dynslam::tracking
