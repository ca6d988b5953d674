#pragma once
// A walking person as the method sees one: a rigid core (torso and head, which the adaptive
// rigid point sets should find) with swinging arms and legs (non-rigid overall). Built from
// boxes in the person frame (x forward, y left, z up, origin on the ground between the feet).
#include <dynslam/sim/Mesh.h>

#include <Eigen/Geometry>

#include <vector>

namespace dynslam::sim {

struct PersonAppearance {
  int shirt_texture = 0, trousers_texture = 0, skin_texture = 0;
  double scale = 1.0;  ///< 1.0 is a 1.75 m person
};

/// A path on the floor walked back and forth at constant speed (a single point: standing).
class WalkPath {
 public:
  WalkPath(std::vector<Eigen::Vector2d> waypoints, double speed, double start_offset_m = 0.0);

  /// Position on the floor and heading (rad, about z) at time t; the heading follows a point a
  /// little ahead on the path so turns are smooth rather than instantaneous.
  void at(double t, Eigen::Vector2d& xy, double& heading) const;
  /// Distance walked by time t (drives the gait phase).
  double distance(double t) const { return speed_ * t; }
  bool standing() const { return waypoints_.size() < 2 || speed_ <= 0; }

 private:
  Eigen::Vector2d pointAt(double s) const;  // s: arc length along the back-and-forth loop
  std::vector<Eigen::Vector2d> waypoints_;
  std::vector<double> cumulative_;  // arc length at each waypoint
  double speed_, offset_;
};

struct PersonPose {
  Eigen::Isometry3d T_world_person = Eigen::Isometry3d::Identity();  ///< ground frame
  double gait_phase = 0;                                             ///< rad; 0 = feet together
  bool moving = false;
};

PersonPose personPoseAt(const WalkPath& path, double t, double stride);

/// The rigid core's pose (torso centre, person axes): the object pose written as ground truth.
Eigen::Isometry3d torsoPose(const PersonPose& pose, const PersonAppearance& look);

/// Appends the body's boxes (about 120 triangles) for `pose`.
void addPersonMesh(Mesh& mesh, const PersonPose& pose, const PersonAppearance& look,
                   uint16_t instance);

}  // namespace dynslam::sim
