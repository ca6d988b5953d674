#pragma once
// New Shi-Tomasi corners spread evenly over the image, kept away from the corners already
// tracked (method.md section 3: "minimum pixel spacing, grid-uniform"). A textured poster
// would otherwise take every corner; spread corners constrain the camera's rotation and
// translation better and leave some for every object in view.
//
// Cost: the image is split into grid cells and a cell's corners are computed only when the
// filling reaches it (the emptiest cells first), so a frame that lost a few tracks computes
// the Shi-Tomasi response over a few cells, not the whole image.
#include <opencv2/core/mat.hpp>
#include <opencv2/core/types.hpp>

#include <functional>
#include <vector>

namespace dynslam::frontend {

/// [FeatureTracking]'s corner settings. Keys, ranges, meanings: FeatureTrackingOptions::describe()
/// (FeatureTrackingStage.cpp); docs/parameters.md.
struct GridCornerParams {
  double min_distance_px = 20;
  double quality_level = 0.01;
  /// Absolute, on the scored image (OpenCV's cornerMinEigenVal units: gradients of the 8-bit
  /// image scaled to [0, 1]), so a bare wall does not fill its cell with noise; image noise
  /// scores higher at full resolution than on level 1.
  double min_eigenvalue = 2e-4;
  int block_size = 3;
  int grid_cols = 8;
  int grid_rows = 6;
  int border_px = 8;  ///< the KLT window needs the pixels around a corner
  /// A level of the KLT pyramid, already built: level 1 scores 4x fewer pixels, the costliest
  /// part of the detection, and finds corners of 2-pixel-and-up structure, which track at least
  /// as well as the finest.
  int level = 1;
};

/// The mask new corners may take: 255 farther than min_distance_px from every point of
/// `occupied`, 0 near them. CV_8UC1, `size`.
cv::Mat freeSpaceMask(cv::Size size, const std::vector<cv::Point2f>& occupied,
                      const GridCornerParams& params);

/// When `p`'s pixel is still free in `free`, marks the disc of radius min_distance_px around
/// it as taken and returns true; false (and nothing changes) otherwise. Claiming tracked points
/// longest track first keeps the old tracks where two drifted together (as VINS-Fusion does).
bool claimIfFree(cv::Mat& free, const cv::Point2f& p, const GridCornerParams& params);

/// Up to `wanted` new corners, scored on `scored` (CV_8UC1: the image itself when level = 0,
/// else its pyramid level `level`), in full-resolution pixels, inside `free` (freeSpaceMask at
/// full resolution, updated with the corners taken) and at least border_px from the image
/// edge, at least min_distance_px
/// from each other and from `occupied`, chosen round by round: every cell that holds the
/// fewest corners (counting `occupied`) takes its strongest remaining candidate, stronger
/// candidates first, until `wanted` are taken or the candidates run out. Also returns how many
/// cells had their corners computed (`cellsComputed`, optional). A candidate for which
/// `rejected` (optional) is true is passed over for the next one of its cell.
std::vector<cv::Point2f> detectGridCorners(
    const cv::Mat& scored, cv::Mat& free, const std::vector<cv::Point2f>& occupied, int wanted,
    const GridCornerParams& params, int* cellsComputed = nullptr,
    const std::function<bool(const cv::Point2f&)>& rejected = {});

}  // namespace dynslam::frontend
