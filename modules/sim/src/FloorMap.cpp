#include "dynslam/sim/FloorMap.h"

#include <opencv2/imgproc.hpp>

#include <cmath>
#include <stdexcept>

namespace dynslam::sim {

FloorMap::FloorMap(const Eigen::Vector2d& min_xy, const Eigen::Vector2d& max_xy,
                   const FloorMapOptions& options)
    : options_(options), min_xy_(min_xy) {
  if (!(options.cell > 0)) throw std::invalid_argument("FloorMap: cell size must be > 0");
  const Eigen::Vector2d size = max_xy - min_xy;
  if (!(size.x() > 0 && size.y() > 0) || size.maxCoeff() / options.cell > 4000)
    throw std::invalid_argument("FloorMap: the floor extent is empty or too large for a grid");
  cols_ = static_cast<int>(std::ceil(size.x() / options.cell));
  rows_ = static_cast<int>(std::ceil(size.y() / options.cell));
  floor_hits_ = cv::Mat::zeros(rows_, cols_, CV_32SC1);
  obstacle_hits_ = cv::Mat::zeros(rows_, cols_, CV_32SC1);
  views_ = cv::Mat::zeros(rows_, cols_, CV_32SC1);
  clear_ = cv::Mat::zeros(rows_, cols_, CV_8UC1);
}

Eigen::Vector2d FloorMap::cellCentre(int row, int col) const {
  return min_xy_ + options_.cell * Eigen::Vector2d(col + 0.5, row + 0.5);
}

bool FloorMap::cellOf(const Eigen::Vector2d& xy, int& row, int& col) const {
  const Eigen::Vector2d g = (xy - min_xy_) / options_.cell;
  col = static_cast<int>(std::floor(g.x()));
  row = static_cast<int>(std::floor(g.y()));
  return row >= 0 && row < rows_ && col >= 0 && col < cols_;
}

void FloorMap::addPoints(const PointGrid& points) {
  for (size_t i = 0; i < points.points.size(); ++i) {
    if (!points.valid[i]) continue;
    const Eigen::Vector3d& p = points.points[i];
    int row, col;
    if (!cellOf(p.head<2>(), row, col)) continue;
    if (std::abs(p.z()) <= options_.floor_band)
      ++floor_hits_.at<int>(row, col);
    else if (p.z() >= options_.obstacle_height && p.z() <= options_.max_height)
      ++obstacle_hits_.at<int>(row, col);
  }
}

void FloorMap::addView(const cv::Mat& depth, const core::CameraIntrinsics& k,
                       const Eigen::Isometry3d& T_floor_camera, double min_distance) {
  const Eigen::Isometry3d T_camera_floor = T_floor_camera.inverse();
  for (int row = 0; row < rows_; ++row)
    for (int col = 0; col < cols_; ++col) {
      const Eigen::Vector2d xy = cellCentre(row, col);
      for (const double height : {0.1, 0.6, 1.1, 1.6}) {
        const Eigen::Vector3d q = T_camera_floor * Eigen::Vector3d(xy.x(), xy.y(), height);
        if (q.z() < min_distance) continue;
        const int u = static_cast<int>(std::lround(k.fx * q.x() / q.z() + k.cx));
        const int v = static_cast<int>(std::lround(k.fy * q.y() / q.z() + k.cy));
        if (u < 0 || v < 0 || u >= depth.cols || v >= depth.rows) continue;
        const float real = depth.at<float>(v, u);
        // 0.3 m of slack: a body is that thick around the spot's centre line.
        if (real > 0 && real < q.z() - 0.3) continue;
        ++views_.at<int>(row, col);
      }
    }
}

void FloorMap::finish() {
  cv::Mat bare = (floor_hits_ > 0) & (obstacle_hits_ < options_.min_obstacle_hits);
  // Distance (in cells) from every cell to the nearest cell that is not bare floor; the grid's
  // border counts as not bare (nothing is known beyond it).
  cv::Mat padded;
  cv::copyMakeBorder(bare, padded, 1, 1, 1, 1, cv::BORDER_CONSTANT, 0);
  cv::Mat distance;
  cv::distanceTransform(padded, distance, cv::DIST_L2, cv::DIST_MASK_PRECISE);
  const auto min_cells = static_cast<float>(options_.clearance / options_.cell + 0.5);
  clear_ = distance(cv::Rect(1, 1, cols_, rows_)) > min_cells;
}

bool FloorMap::isClear(const Eigen::Vector2d& xy) const {
  int row, col;
  return cellOf(xy, row, col) && clear_.at<uint8_t>(row, col) != 0;
}

bool FloorMap::segmentClear(const Eigen::Vector2d& a, const Eigen::Vector2d& b) const {
  const double step = options_.cell / 4;
  const int n = static_cast<int>(std::ceil((b - a).norm() / step));
  for (int i = 0; i <= n; ++i)
    if (!isClear(a + (b - a) * (n > 0 ? double(i) / n : 0.0))) return false;
  return true;
}

double FloorMap::clearRun(const Eigen::Vector2d& through, const Eigen::Vector2d& direction,
                          double max_length) const {
  // Samples every quarter cell and at max_length itself, so a clear run reports max_length
  // exactly (callers compare it with lengths they need).
  const double step = options_.cell / 4;
  double run = 0;
  for (int i = 1;; ++i) {
    const double s = std::min(i * step, max_length);
    if (!isClear(through + s * direction)) return run;
    run = s;
    if (s >= max_length) return run;
  }
}

}  // namespace dynslam::sim
