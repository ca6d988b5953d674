#pragma once
// A walking person as the method sees one: a rigid core (torso and head, which the adaptive
// rigid point sets should find) with swinging arms and legs (non-rigid overall). Built from
// boxes in the person frame (x forward, y left, z up, origin on the ground between the feet).
#include <dynslam/sim/FloorPath.h>
#include <dynslam/sim/Mesh.h>

#include <Eigen/Geometry>

namespace dynslam::sim {

struct PersonAppearance {
  int shirt_texture = 0, trousers_texture = 0, skin_texture = 0;
  double scale = 1.0;  ///< 1.0 is a 1.75 m person
};

struct PersonPose {
  Eigen::Isometry3d T_world_person = Eigen::Isometry3d::Identity();  ///< ground frame
  double gait_phase = 0;                                             ///< rad; 0 = feet together
  bool moving = false;
};

PersonPose personPoseAt(const FloorPath& path, double t, double stride);

/// The rigid core's pose (torso centre, person axes): the object pose written as ground truth.
Eigen::Isometry3d torsoPose(const PersonPose& pose, const PersonAppearance& look);

/// Appends the body's boxes (about 120 triangles) for `pose`.
void addPersonMesh(Mesh& mesh, const PersonPose& pose, const PersonAppearance& look,
                   uint16_t instance);

}  // namespace dynslam::sim
