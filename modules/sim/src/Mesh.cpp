#include "dynslam/sim/Mesh.h"

namespace dynslam::sim {

void addQuad(Mesh& mesh, const Eigen::Vector3d& origin, const Eigen::Vector3d& u,
             const Eigen::Vector3d& v, int texture, uint16_t instance, double texture_scale) {
  const float su = static_cast<float>(u.norm() / texture_scale);
  const float sv = static_cast<float>(v.norm() / texture_scale);
  const Eigen::Vector3d c00 = origin, c10 = origin + u, c11 = origin + u + v, c01 = origin + v;
  const Eigen::Vector2f t00(0, 0), t10(su, 0), t11(su, sv), t01(0, sv);
  mesh.push_back({{c00, c10, c11}, {t00, t10, t11}, texture, instance});
  mesh.push_back({{c00, c11, c01}, {t00, t11, t01}, texture, instance});
}

void addBox(Mesh& mesh, const Eigen::Isometry3d& T_world_box, const Eigen::Vector3d& half,
            int texture, uint16_t instance, double texture_scale) {
  const Eigen::Vector3d h = half;
  const auto corner = [&](double sx, double sy, double sz) {
    return T_world_box * Eigen::Vector3d(sx * h.x(), sy * h.y(), sz * h.z());
  };
  // Six faces as (origin, u, v); winding does not matter: the rasterizer draws both sides.
  const Eigen::Vector3d o = corner(-1, -1, -1);
  const Eigen::Vector3d ex = corner(1, -1, -1) - o, ey = corner(-1, 1, -1) - o,
                        ez = corner(-1, -1, 1) - o;
  addQuad(mesh, o, ex, ey, texture, instance, texture_scale);       // bottom
  addQuad(mesh, o + ez, ex, ey, texture, instance, texture_scale);  // top
  addQuad(mesh, o, ex, ez, texture, instance, texture_scale);       // front (-y)
  addQuad(mesh, o + ey, ex, ez, texture, instance, texture_scale);  // back (+y)
  addQuad(mesh, o, ey, ez, texture, instance, texture_scale);       // left (-x)
  addQuad(mesh, o + ex, ey, ez, texture, instance, texture_scale);  // right (+x)
}

}  // namespace dynslam::sim
