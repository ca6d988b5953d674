#pragma once
// The floor of a real RGB-D sequence, found in its back-projected depth: the plane the Augmenter
// stands its people on, and the gravity-aligned frame (z up) its output is expressed in.
#include <dynslam/core/Frame.h>

#include <Eigen/Geometry>
#include <opencv2/core/mat.hpp>

#include <cstddef>
#include <random>
#include <vector>

namespace dynslam::sim {

/// Points p with normal . p = offset; the unit normal points up (to the side of the cameras).
struct Plane {
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
  double offset = 0;
  double height(const Eigen::Vector3d& p) const { return normal.dot(p) - offset; }
};

struct FloorFitOptions {
  double inlier_distance = 0.02;  ///< m
  int iterations = 500;
  double max_tilt_deg = 30;  ///< candidate normals within this of the up hint
  /// The floor is the lowest large plane: a candidate with more than this fraction of the
  /// points further than below_margin beneath it is a table or a shelf, not the floor.
  double max_below_fraction = 0.02;
  double below_margin = 0.06;  ///< m
  /// RANSAC triples are drawn from one frame's pixels at most this many grid steps apart, so
  /// the three points lie on one surface far more often than three points drawn at random.
  int neighbourhood = 6;
};

struct FloorFit {
  Plane plane;
  std::size_t inliers = 0, points = 0;
  double rms = 0;  ///< m, of the inliers' distances to the refined plane
};

/// The depth points of one frame on a pixel grid (every `step`-th pixel in x and y), in the
/// world frame; rows x cols of the grid, invalid where the depth was 0 or beyond max_depth.
struct PointGrid {
  int rows = 0, cols = 0;
  std::vector<Eigen::Vector3d> points;  ///< row-major
  std::vector<bool> valid;
};
PointGrid backProject(const cv::Mat& depth, const core::CameraIntrinsics& camera,
                      const Eigen::Isometry3d& T_world_camera, int step, double max_depth);

/// RANSAC plane over the grids' valid points with the rules of FloorFitOptions, refined by
/// least squares over its inliers (twice, re-selecting them). `up_hint`: roughly up in the
/// world (e.g. minus the mean image-down axis of hand-held cameras). Throws std::runtime_error
/// when no candidate passes, with the counts that ruled them out.
FloorFit fitFloorPlane(const std::vector<PointGrid>& grids, const Eigen::Vector3d& up_hint,
                       const FloorFitOptions& options, std::mt19937_64& rng);

/// A frame on the plane: z = the plane's normal, origin = `origin` projected onto the plane,
/// x = `forward` projected onto the plane (e.g. where the cameras look). Returns T_world_floor.
Eigen::Isometry3d floorFrame(const Plane& plane, const Eigen::Vector3d& origin,
                             const Eigen::Vector3d& forward);

}  // namespace dynslam::sim
