// KalmanBoxTracker: the depth-IoU association rounds (method.md section 2) and what they compare.
#include "dynslam/tracking/KalmanBoxTracker.h"

#include "AssignmentRound.h"
#include "DepthSurfaces.h"
#include "dynslam/tracking/DepthIoU.h"

#include <Eigen/Cholesky>

namespace dynslam::tracking {

/// The observations with d_alt kept only where a track may take it (withOwnedAlternatives):
/// alternative_depth, with the recent tracks' surfaces for alternative_depth_tracks.
std::vector<BoxObservation> KalmanBoxTracker::withUsableAlternatives(
    const std::vector<BoxObservation>& input, const cv::Size& image) const {
  if (!params_.alternative_depth) return input;
  std::vector<TrackSurface> recent;
  if (params_.alternative_depth_tracks)
    for (const Tracked& tr : tracked_)
      if (tr.track.misses <= kRecentMisses && tr.filter.state()(kD) > 0)
        recent.push_back({clippedToImage(tr.filter.box(), image), tr.filter.state()(kD)});
  return withOwnedAlternatives(input, recent, params_.rho_min);
}

/// The method's round at rho_min, then, when rho_min_coasting < rho_min, a second one for the
/// tracks that were already coasting against the observations left over.
void KalmanBoxTracker::associateByDepthIoU(const std::vector<BoxObservation>& observations,
                                           const cv::Size& image, Association& a) {
  associate(observations, image, params_.rho_min, false, a);
  noteRound(a.observationOf, TrackMatch::Overlap);
  if (params_.rho_min_coasting < params_.rho_min)
    associate(observations, image, params_.rho_min_coasting, true, a);
  noteRound(a.observationOf, TrackMatch::CoastingOverlap);
}

/// The depth of `o` that `tr` is compared with and updated by: o.depth, or with
/// alternative_depth the one of o.depth and o.depth_alt nearer (in ratio) the track's depth.
double KalmanBoxTracker::depthFor(const Tracked& tr, const BoxObservation& o) const {
  const double d = tr.filter.state()(kD);
  if (!params_.alternative_depth || !(o.depth_alt > 0) || !(o.depth > 0) || !(d > 0))
    return o.depth;
  return core::depthRatio(o.depth_alt, d) > core::depthRatio(o.depth, d) ? o.depth_alt : o.depth;
}

/// innovation_gate: the squared Mahalanobis distance of `box`'s centre from `predicted`'s (the
/// track's predicted box, clipped as the detection is) under the filter's position covariance
/// plus meas_center_px^2.
double KalmanBoxTracker::centreInnovation2(const Tracked& tr, const cv::Rect2f& predicted,
                                           const cv::Rect2f& box) const {
  // The centres (u, v) as the filter measures them.
  const Eigen::Vector2d y =
      boxMeasurement(box, 0).head<2>() - boxMeasurement(predicted, 0).head<2>();
  const double r = params_.noise.meas_center_px;
  const Eigen::Matrix2d S =
      tr.filter.covariance().block<2, 2>(kU, kU) + r * r * Eigen::Matrix2d::Identity();
  return y.dot(S.llt().solve(y));
}

/// One round: the tracks without an observation yet (only those already coasting when
/// `coastingOnly`) against the observations not used yet, on the depth IoU, pairs accepted when
/// rho > threshold (and, with innovation_gate, the centre within the gate).
void KalmanBoxTracker::associate(const std::vector<BoxObservation>& observations,
                                 const cv::Size& image, double threshold, bool coastingOnly,
                                 Association& a) const {
  assignRound(
      tracked_, observations,
      [&](const Tracked& tr) { return !coastingOnly || tr.track.misses > 0; },
      [](const BoxObservation&) { return true; },
      [&](const Tracked& tr, const BoxObservation& o) {
        // Detectors clip their boxes to the image: compare like with like.
        const cv::Rect2f predicted = clippedToImage(tr.filter.box(), image);
        const double value = depthIoU(predicted, tr.filter.state()(kD), o.box, depthFor(tr, o));
        if (!(value > threshold)) return 0.0;
        return params_.innovation_gate > 0 &&
                       centreInnovation2(tr, predicted, o.box) > params_.innovation_gate
                   ? 0.0
                   : value;
      },
      a.observationOf, a.observationUsed);
}

}  // namespace dynslam::tracking
