#pragma once
// The simulated world's static obstacles seen from above: every static triangle that reaches
// into a height band (walls, shelves, stalls; not the floor or the ceiling) filled into a floor
// grid, with each cell's distance to the nearest occupied one. It gives the robot's clearance to
// static obstacles (contacts), the ground-truth static obstacle points, and the top view's
// background.
#include <dynslam/sim/Mesh.h>

#include <Eigen/Core>
#include <opencv2/core/mat.hpp>

#include <vector>

namespace dynslam::navdemo {

class StaticFootprint {
 public:
  /// Triangles of `mesh` with a part between `low` and `high` (m above the floor), on a grid of
  /// `cell` m covering the mesh's extent.
  StaticFootprint(const sim::Mesh& mesh, double low, double high, double cell = 0.02);

  /// m from (x, y) to the nearest occupied cell (0 inside one); large outside the grid.
  double distance(const Eigen::Vector2d& p) const;
  /// The occupied cells' centres (x, y), every `stride`-th cell in each direction.
  std::vector<Eigen::Vector2d> occupiedCells(int stride = 1) const;
  bool occupied(int row, int col) const { return occupied_.at<uchar>(row, col) != 0; }

  Eigen::Vector2d origin() const { return origin_; }  ///< world x, y of cell (0, 0)'s corner
  double cell() const { return cell_; }
  int rows() const { return occupied_.rows; }
  int cols() const { return occupied_.cols; }

 private:
  Eigen::Vector2d origin_;
  double cell_;
  cv::Mat occupied_;  // CV_8U, row = y, col = x
  cv::Mat distance_;  // CV_32F, cells to the nearest occupied cell
};

}  // namespace dynslam::navdemo
