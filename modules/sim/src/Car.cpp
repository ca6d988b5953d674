#include "dynslam/sim/Car.h"

namespace dynslam::sim {
namespace {

constexpr double kClearance = 0.25;   // m from the ground to the underside of the body
constexpr double kBeltHeight = 0.85;  // m; the cabin sits on the lower body above it
constexpr double kWheelRadius = 0.32;

Eigen::Isometry3d at(double x, double y, double z) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.translation() = Eigen::Vector3d(x, y, z);
  return T;
}

}  // namespace

Eigen::Isometry3d carBodyPose(const Eigen::Isometry3d& T_world_car, const CarAppearance& look) {
  return T_world_car * at(0, 0, look.height / 2);
}

void addCarMesh(Mesh& mesh, const Eigen::Isometry3d& T, const CarAppearance& look,
                uint16_t instance) {
  const double L = look.length, W = look.width, H = look.height;
  // Lower body: the full footprint between the clearance and the belt line.
  addBox(mesh, T * at(0, 0, (kClearance + kBeltHeight) / 2),
         {L / 2, W / 2, (kBeltHeight - kClearance) / 2}, look.paint_texture, instance, 1.2);
  // Cabin: shorter and narrower, set back from the bonnet, with a roof panel on top.
  const double cabinLength = 0.52 * L, cabinX = -0.06 * L, roof = 0.04;
  addBox(mesh, T * at(cabinX, 0, (kBeltHeight + H - roof) / 2),
         {cabinLength / 2, 0.44 * W, (H - roof - kBeltHeight) / 2}, look.paint_texture, instance,
         0.8);
  addBox(mesh, T * at(cabinX, 0, H - roof / 2), {cabinLength / 2 - 0.05, 0.42 * W, roof / 2},
         look.paint_texture, instance, 0.8);
  // Wheels stand slightly proud of the body sides; bumpers slightly proud of its ends.
  for (const double x : {0.33 * L, -0.33 * L})
    for (const double y : {W / 2 - 0.08, -(W / 2 - 0.08)})
      addBox(mesh, T * at(x, y, kWheelRadius), {kWheelRadius, 0.11, kWheelRadius},
             look.tyre_texture, instance, 0.5);
  for (const double x : {L / 2 + 0.04, -(L / 2 + 0.04)})
    addBox(mesh, T * at(x, 0, kClearance + 0.12), {0.05, W / 2 - 0.02, 0.1}, look.tyre_texture,
           instance, 0.5);
}

}  // namespace dynslam::sim
