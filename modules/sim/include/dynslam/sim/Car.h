#pragma once
// A car as the method sees one: a rigid textured body (lower body, cabin, wheels, bumpers),
// built from boxes in the car frame (x forward, y left, z up, origin on the ground under the
// body's centre).
#include <dynslam/sim/Mesh.h>

#include <Eigen/Geometry>

namespace dynslam::sim {

struct CarAppearance {
  int paint_texture = 0;  ///< body and cabin (TextureKind::CarPaint: paint, windows, seams)
  int tyre_texture = 0;   ///< wheels and bumpers (dark, speckled)
  double length = 4.4, width = 1.8, height = 1.45;  ///< m
};

/// The rigid core's pose (centre of the body's bounding box, car axes): the object pose written
/// as ground truth.
Eigen::Isometry3d carBodyPose(const Eigen::Isometry3d& T_world_car, const CarAppearance& look);

/// Appends the car's boxes (108 triangles) at ground pose T_world_car.
void addCarMesh(Mesh& mesh, const Eigen::Isometry3d& T_world_car, const CarAppearance& look,
                uint16_t instance);

}  // namespace dynslam::sim
