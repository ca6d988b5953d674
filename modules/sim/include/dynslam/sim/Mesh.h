#pragma once
// Geometry the simulator renders: textured triangles in world coordinates, each tagged with the
// instance it belongs to (0 = static background) so the renderer can write instance labels.
#include <Eigen/Geometry>

#include <array>
#include <cstdint>
#include <vector>

namespace dynslam::sim {

struct Triangle {
  std::array<Eigen::Vector3d, 3> p;   ///< vertices, world frame, metres
  std::array<Eigen::Vector2f, 3> uv;  ///< texture coordinates; textures repeat outside [0, 1]
  int texture = 0;                    ///< index into the TextureLibrary
  uint16_t instance = 0;              ///< 0 = static scene; >= 1 = an object with ground truth
};

using Mesh = std::vector<Triangle>;

/// Appends an axis-aligned box (in its own frame: centre at the origin, half sizes `half`),
/// posed by T_world_box. Each face's texture repeats every `texture_scale` metres so texel
/// density is the same on large and small faces.
void addBox(Mesh& mesh, const Eigen::Isometry3d& T_world_box, const Eigen::Vector3d& half,
            int texture, uint16_t instance, double texture_scale = 1.0);

/// Appends a rectangle spanned by corner `origin` and edges `u`, `v` (two triangles), with its
/// texture repeating every `texture_scale` metres.
void addQuad(Mesh& mesh, const Eigen::Vector3d& origin, const Eigen::Vector3d& u,
             const Eigen::Vector3d& v, int texture, uint16_t instance, double texture_scale = 1.0);

}  // namespace dynslam::sim
