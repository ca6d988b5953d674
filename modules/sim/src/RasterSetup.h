#pragma once
// Triangle setup for the rasterizer (internal to the sim module): world -> camera, clipping
// against the near plane and a guard band, and the per-triangle constants the pixel loops use.
#include <dynslam/core/Frame.h>
#include <dynslam/sim/Mesh.h>
#include <dynslam/sim/Texture.h>

#include <cstdint>
#include <vector>

namespace dynslam::sim::detail {

/// Screen coordinates are fixed point with this many fractional bits.
constexpr int kSubpixelBits = 8;

/// One mip level as the shading loop reads it.
struct SamplerLevel {
  const uint32_t* texels;
  int64_t mask_x, mask_y;  ///< width - 1, height - 1 (powers of two)
  int width_bits;          ///< log2(width)
};

/// What the shading pass needs of one visible mesh triangle: 1/z, u/z and v/z as affine
/// functions of the pixel coordinates (exact for a planar triangle under perspective), with
/// u, v in texels of the full-size texture.
struct ShadingPlane {
  double w_x, w_y, w_0;        ///< 1/z = w_x x + w_y y + w_0
  double u_x, u_y, u_0;        ///< u/z
  double v_x, v_y, v_0;        ///< v/z
  const SamplerLevel* levels;  ///< into RasterScene::sampler_levels
  int level_count;
  uint16_t instance;
};

/// One triangle of a clipped polygon's fan, ready for coverage: three edge functions
/// E(x, y) = step_x x + step_y y + origin over integer pixels, all >= 0 exactly on the covered
/// pixels (top-left rule folded into `origin`), and 1/z for the depth test.
struct RasterTriangle {
  int64_t step_x[3], step_y[3], origin[3];
  int min_x, max_x, min_y, max_y;  ///< pixel bounds, clamped to the image
  double w_x, w_y, w_0;
  int32_t shading;  ///< index into RasterScene::shading
};

struct RasterScene {
  std::vector<SamplerLevel> sampler_levels;  ///< every texture's levels, texture by texture
  std::vector<ShadingPlane> shading;
  std::vector<RasterTriangle> triangles;
};

/// Fills `scene` (cleared first; its capacity is reused) with the parts of `mesh` in front of
/// the near plane.
void setupTriangles(const Mesh& mesh, const TextureLibrary& textures,
                    const core::CameraIntrinsics& camera, const Eigen::Isometry3d& T_world_camera,
                    double near_plane, RasterScene& scene);

/// floor(n / d) and ceil(n / d) for d > 0 (C++ division truncates toward zero).
inline int64_t floorDiv(int64_t n, int64_t d) { return n >= 0 ? n / d : -((-n + d - 1) / d); }
inline int64_t ceilDiv(int64_t n, int64_t d) { return n >= 0 ? (n + d - 1) / d : -((-n) / d); }

}  // namespace dynslam::sim::detail
