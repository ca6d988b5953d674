#include "nav_demo/StaticFootprint.h"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <limits>

namespace dynslam::navdemo {

StaticFootprint::StaticFootprint(const sim::Mesh& mesh, double low, double high, double cell)
    : cell_(cell) {
  Eigen::Vector2d lo(std::numeric_limits<double>::max(), std::numeric_limits<double>::max());
  Eigen::Vector2d hi = -lo;
  for (const auto& tri : mesh)
    for (const auto& p : tri.p) {
      lo = lo.cwiseMin(p.head<2>());
      hi = hi.cwiseMax(p.head<2>());
    }
  if (mesh.empty()) lo = hi = Eigen::Vector2d::Zero();
  origin_ = lo - Eigen::Vector2d(0.5, 0.5);  // a margin: the outside of the walls is free
  const Eigen::Vector2d size = hi - lo + Eigen::Vector2d(1.0, 1.0);
  occupied_ = cv::Mat::zeros(static_cast<int>(std::ceil(size.y() / cell)) + 1,
                             static_cast<int>(std::ceil(size.x() / cell)) + 1, CV_8U);
  const auto toCell = [&](const Eigen::Vector3d& p) {
    return cv::Point(static_cast<int>(std::floor((p.x() - origin_.x()) / cell)),
                     static_cast<int>(std::floor((p.y() - origin_.y()) / cell)));
  };
  for (const auto& tri : mesh) {
    double zmin = tri.p[0].z(), zmax = zmin;
    for (const auto& p : tri.p) zmin = std::min(zmin, p.z()), zmax = std::max(zmax, p.z());
    if (zmax < low || zmin > high) continue;  // the floor, the ceiling
    const std::vector<cv::Point> corners{toCell(tri.p[0]), toCell(tri.p[1]), toCell(tri.p[2])};
    cv::fillConvexPoly(occupied_, corners, 255);
    cv::polylines(occupied_, corners, true, 255);  // a wall seen edge-on is a line
  }
  cv::Mat free = occupied_ == 0;
  cv::distanceTransform(free, distance_, cv::DIST_L2, cv::DIST_MASK_PRECISE);
}

double StaticFootprint::distance(const Eigen::Vector2d& p) const {
  const int col = static_cast<int>(std::floor((p.x() - origin_.x()) / cell_));
  const int row = static_cast<int>(std::floor((p.y() - origin_.y()) / cell_));
  if (row < 0 || col < 0 || row >= distance_.rows || col >= distance_.cols) return 1e9;
  return distance_.at<float>(row, col) * cell_;
}

std::vector<Eigen::Vector2d> StaticFootprint::occupiedCells(int stride) const {
  std::vector<Eigen::Vector2d> out;
  for (int r = 0; r < occupied_.rows; r += stride)
    for (int c = 0; c < occupied_.cols; c += stride)
      if (occupied(r, c))
        out.emplace_back(origin_.x() + (c + 0.5) * cell_, origin_.y() + (r + 0.5) * cell_);
  return out;
}

}  // namespace dynslam::navdemo
