#pragma once
// Whose surface a detection's depth is (internal to KalmanBoxTracker): the tests that
// alternative_depth, descriptor_own_surface and the appearance round share.
#include "dynslam/tracking/KalmanBoxTracker.h"

#include <opencv2/core/types.hpp>

#include <vector>

namespace dynslam::tracking {

/// Tracks seen on one of the last this many frames count as a surface on this one
/// (descriptor_own_surface, alternative_depth_tracks). A track coasting longer has a drifting
/// prediction, and the person it lost is the likeliest one standing there. Measured:
/// docs/notes/perception.md, 2026-11-28 (descriptor_own_surface).
constexpr int kRecentMisses = 1;

/// Cluster means of one surface measured in two boxes agree within a few per cent; two people a
/// pace apart differ by 20 % and more (docs/notes/perception.md, 2026-11-28, surfaces).
constexpr double kSameSurfaceRatio = 0.85;

/// True when more than a fifth of `box` lies inside `other`: enough of another object in a box
/// to show in its descriptor.
bool coveredBy(const cv::Rect2f& box, const cv::Rect2f& other);

/// True when more than a fifth of observation j's box is covered by the box of a nearer
/// observation: its descriptor then shows a part of the object only (the occluder's pixels are
/// left out by the depth band, Appearance.h), and a track's descriptor is updated from whole
/// views only.
bool occluded(const std::vector<BoxObservation>& observations, size_t j);

/// A track's predicted box clipped to `image` (when given), as detectors clip theirs.
cv::Rect2f clippedToImage(const cv::Rect2f& box, const cv::Size& image);

/// A recent track's predicted box and depth: a surface a detection may have been given.
struct TrackSurface {
  cv::Rect2f box;
  double depth = 0;
};

/// The observations with d_alt kept only where a track may take it: where the cluster the
/// segmentation chose is another detection's surface (a partly hidden person given its
/// occluder's depth), or, with `tracks` (alternative_depth_tracks), the surface of one of them
/// whose box overlaps the detection's but too little to be its own track (box IoU <= maxOwnIoU:
/// the occluder of a partly hidden person whose own detection was missed), or where d_alt is
/// the nearer cluster and nobody else's (a person given the wall behind it). Otherwise a track
/// whose depth had once gone to the wrong surface kept taking that surface through d_alt and
/// never came back (docs/notes/perception.md, 2026-11-28, alternative_depth).
std::vector<BoxObservation> withOwnedAlternatives(std::vector<BoxObservation> observations,
                                                  const std::vector<TrackSurface>& tracks,
                                                  double maxOwnIoU);

}  // namespace dynslam::tracking
