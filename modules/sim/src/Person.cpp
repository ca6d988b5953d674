#include "dynslam/sim/Person.h"

#include <algorithm>
#include <cmath>

namespace dynslam::sim {
namespace {

constexpr double kHipHeight = 0.90, kShoulderHeight = 1.45, kTorsoCentre = 1.20;

Eigen::Isometry3d translation(double x, double y, double z) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.translation() = Eigen::Vector3d(x, y, z);
  return T;
}

/// Rotation about the person's y axis (left): positive swings a limb's lower end backwards.
Eigen::Isometry3d pitch(double angle) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = Eigen::AngleAxisd(angle, Eigen::Vector3d::UnitY()).toRotationMatrix();
  return T;
}

/// A two-segment limb hanging from `joint` (person frame): upper segment swung by `swing`,
/// lower one bent by a further `bend`.
void addLimb(Mesh& mesh, const Eigen::Isometry3d& T_world_person, const Eigen::Vector3d& joint,
             double swing, double bend, double upper_len, double lower_len, double thickness,
             int texture_upper, int texture_lower, uint16_t instance) {
  const Eigen::Isometry3d upper =
      T_world_person * translation(joint.x(), joint.y(), joint.z()) * pitch(swing);
  addBox(mesh, upper * translation(0, 0, -upper_len / 2),
         Eigen::Vector3d(thickness, thickness, upper_len / 2), texture_upper, instance, 0.5);
  const Eigen::Isometry3d lower = upper * translation(0, 0, -upper_len) * pitch(bend);
  addBox(mesh, lower * translation(0, 0, -lower_len / 2),
         Eigen::Vector3d(thickness * 0.85, thickness * 0.85, lower_len / 2), texture_lower,
         instance, 0.5);
}

}  // namespace

PersonPose personPoseAt(const FloorPath& path, double t, double stride) {
  PersonPose pose;
  Eigen::Vector2d xy;
  double heading = 0;
  path.at(t, xy, heading);
  pose.moving = !path.standing();
  pose.gait_phase = pose.moving ? 2 * M_PI * path.distance(t) / stride : 0.0;
  // The body rises slightly twice per gait cycle (at each mid-stance).
  const double bob = pose.moving ? 0.025 * std::abs(std::sin(pose.gait_phase)) : 0.0;
  pose.T_world_person = translation(xy.x(), xy.y(), bob);
  pose.T_world_person.linear() =
      Eigen::AngleAxisd(heading, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  return pose;
}

Eigen::Isometry3d torsoPose(const PersonPose& pose, const PersonAppearance& look) {
  return pose.T_world_person * translation(0, 0, kTorsoCentre * look.scale);
}

void addPersonMesh(Mesh& mesh, const PersonPose& pose, const PersonAppearance& look,
                   uint16_t instance) {
  const double k = look.scale;
  Eigen::Isometry3d T = pose.T_world_person;
  T.linear() *= k;  // scale the whole body about its ground point
  const double phi = pose.gait_phase;
  // Torso and head: the rigid core.
  addBox(mesh, T * translation(0, 0, kTorsoCentre), Eigen::Vector3d(0.12, 0.20, 0.27),
         look.shirt_texture, instance, 0.5);
  addBox(mesh, T * translation(0.01, 0, 1.64), Eigen::Vector3d(0.10, 0.085, 0.115),
         look.skin_texture, instance, 0.3);
  // Legs swing in opposition, knees bend in the swing phase; arms swing against the legs.
  const double legSwing = 0.42 * std::sin(phi);
  const auto knee = [&](double s) { return 0.7 * std::max(0.0, std::sin(s - 0.6)); };
  addLimb(mesh, T, {0, 0.10, kHipHeight}, -legSwing, knee(phi), 0.44, 0.44, 0.07,
          look.trousers_texture, look.trousers_texture, instance);
  addLimb(mesh, T, {0, -0.10, kHipHeight}, legSwing, knee(phi + M_PI), 0.44, 0.44, 0.07,
          look.trousers_texture, look.trousers_texture, instance);
  const double armSwing = 0.35 * std::sin(phi);
  addLimb(mesh, T, {0, 0.26, kShoulderHeight}, armSwing, -0.25, 0.30, 0.27, 0.05,
          look.shirt_texture, look.skin_texture, instance);
  addLimb(mesh, T, {0, -0.26, kShoulderHeight}, -armSwing, -0.25, 0.30, 0.27, 0.05,
          look.shirt_texture, look.skin_texture, instance);
}

}  // namespace dynslam::sim
