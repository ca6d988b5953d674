#pragma once
// Points just behind an occluding edge (not the method; FeatureTracker's
// occlusion_edge_radius_px). A corner there has the nearer surface's silhouette in its KLT
// window (and in the wider windows of the coarser pyramid levels), so its image motion can
// follow that edge while its depth is the far surface's: on a standing person uncovered by a
// walker its scene flow reads the walker's speed, on the background it is a "static" point that
// moves with the walker. Measured: docs/notes/frontend.md, 2026-11-28 (front-end settings'
// history).
#include <opencv2/core/mat.hpp>
#include <opencv2/core/types.hpp>

namespace dynslam::frontend {

struct OcclusionEdgeParams {
  int radius_px = 0;        ///< square window half-side; 0: off
  double min_gap_m = 0.15;  ///< a nearer surface is one nearer by more than this ...
  /// ... and than this times the point's depth: the depth noise grows with the depth, and the
  /// window's nearest reading is its noisiest (a smaller ratio took noise for edges).
  double gap_ratio = 0.1;
};

/// Whether a valid reading of `depth` (CV_32FC1 metres, 0 or non-finite = none) within the
/// window round `pixel` is nearer than the pixel's own reading by more than the gap, counting
/// only the readings where `nearer` (CV_8UC1, optional: empty = everywhere) is non-zero. False
/// where the pixel has no reading or the check is off.
bool behindOcclusionEdge(const cv::Mat& depth, const cv::Point2f& pixel,
                         const OcclusionEdgeParams& params, const cv::Mat& nearer = {});

/// Whether the window round `pixel` holds a depth edge: a reading nearer or farther than the
/// pixel's own by more than the gap, or none (an edge's shadow or the range's end). False where
/// the pixel has no reading or radius_px <= 0. A reading there may belong to either surface as
/// the tracked pixel moves by a fraction of a pixel.
bool nearDepthEdge(const cv::Mat& depth, const cv::Point2f& pixel,
                   const OcclusionEdgeParams& params);

}  // namespace dynslam::frontend
