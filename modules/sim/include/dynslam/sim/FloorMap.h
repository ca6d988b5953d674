#pragma once
// Which parts of a real floor inserted people may walk on: a grid over the floor plane (floor
// frame: z up, the floor at z = 0) of what the real depth showed there (bare floor, or
// something standing on it, like a table or a chair), and of how often the camera saw each
// cell. The Augmenter plans its agents' paths inside the clear cells it sees most.
#include <dynslam/core/Frame.h>
#include <dynslam/sim/FloorPlane.h>

#include <Eigen/Geometry>
#include <opencv2/core/mat.hpp>

namespace dynslam::sim {

struct FloorMapOptions {
  double cell = 0.1;             ///< m
  double floor_band = 0.05;      ///< m; points within it of z = 0 are bare floor
  double obstacle_height = 0.1;  ///< m; points from here ...
  double max_height = 2.0;       ///< m; ... to here stand in the way (higher: a lamp, a hood)
  int min_obstacle_hits = 3;     ///< fewer obstacle points in a cell are depth noise
  double clearance = 0.3;        ///< m kept between a clear cell and any other cell
};

class FloorMap {
 public:
  /// Cells covering [min_xy, max_xy] of the floor frame.
  FloorMap(const Eigen::Vector2d& min_xy, const Eigen::Vector2d& max_xy,
           const FloorMapOptions& options);

  /// Counts the grid's points (already in the floor frame) as floor or obstacle hits.
  void addPoints(const PointGrid& points_in_floor);
  /// One view of the real sequence: every cell gains one for each of four points of a body
  /// standing on it (0.1, 0.6, 1.1 and 1.6 m above the floor) that projects into the image at
  /// least min_distance in front of the camera and is not hidden behind the real depth there.
  /// So cells where a whole person would be seen score highest, cells right under the camera or
  /// behind a wall nothing.
  void addView(const cv::Mat& depth, const core::CameraIntrinsics& camera,
               const Eigen::Isometry3d& T_floor_camera, double min_distance);
  /// Recomputes clear(): cells with floor hits, fewer than min_obstacle_hits obstacle hits, and
  /// no other cell within `clearance`. Call after the last addPoints.
  void finish();

  int rows() const { return rows_; }
  int cols() const { return cols_; }
  double cellSize() const { return options_.cell; }
  Eigen::Vector2d cellCentre(int row, int col) const;
  /// False when xy lies outside the grid.
  bool cellOf(const Eigen::Vector2d& xy, int& row, int& col) const;
  bool isClear(const Eigen::Vector2d& xy) const;
  /// Every point of the segment (sampled at a quarter cell) is clear.
  bool segmentClear(const Eigen::Vector2d& a, const Eigen::Vector2d& b) const;
  /// From a clear `through`, how far (m) one can go along the unit `direction` while staying on
  /// clear cells, at most max_length.
  double clearRun(const Eigen::Vector2d& through, const Eigen::Vector2d& direction,
                  double max_length) const;

  const cv::Mat& floorHits() const { return floor_hits_; }        ///< CV_32SC1
  const cv::Mat& obstacleHits() const { return obstacle_hits_; }  ///< CV_32SC1
  const cv::Mat& views() const { return views_; }                 ///< CV_32SC1
  const cv::Mat& clear() const { return clear_; }                 ///< CV_8UC1, 255 = clear

 private:
  FloorMapOptions options_;
  Eigen::Vector2d min_xy_;
  int rows_ = 0, cols_ = 0;
  cv::Mat floor_hits_, obstacle_hits_, views_, clear_;
};

}  // namespace dynslam::sim
