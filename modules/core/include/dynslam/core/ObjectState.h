#pragma once
// What a planner reads of a tracked object (ObjectStates stage, ini [ObjectStates]): its body
// centre and velocity in the world, filtered over time, its size, and how sure the filter is.
// MRPT-free, like Frame.h.
#include <Eigen/Core>

#include <string>

namespace dynslam::core {

struct ObjectState {
  /// Stable while the object is followed and never reused in a run: the id of the first track
  /// it followed (a track that starts where a coasting state is predicted continues that state).
  int id = -1;
  int track_id = -1;  ///< the tracker's id it follows now (Track::id)
  std::string category;
  /// World, m: the body's centre, behind the seen surface, at the middle of its seen height.
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();  ///< world, m/s
  /// m: across the line of sight, along it (assumed from the width), and along up.
  Eigen::Vector3d extent = Eigen::Vector3d::Zero();
  /// Of (centre, velocity), world axes, m and m/s.
  Eigen::Matrix<double, 6, 6> covariance = Eigen::Matrix<double, 6, 6>::Identity();
  /// The world's up (unit): the mean of the accelerometer's (else the image's) up seen so far;
  /// the ground plane is perpendicular to it.
  Eigen::Vector3d up = Eigen::Vector3d::UnitZ();
  double last_measured = 0;  ///< s, stamp of the last frame that measured it
  bool measured = false;     ///< measured in this frame (else predicted: occluded, coasting)
  bool moving = false;       ///< its horizontal speed is above the stage's moving_speed
};

}  // namespace dynslam::core
