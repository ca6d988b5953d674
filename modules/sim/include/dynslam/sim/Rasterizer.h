#pragma once
// CPU z-buffer rasterizer of textured triangles for a pinhole camera: colour, depth along the
// optical axis and the instance id of the surface seen at each pixel. Triangles crossing the
// near plane are clipped, not dropped (people pass close in front of the camera).
//
// Conventions: pixel (x, y) is sampled at its centre, which is the image point (x, y) (as in
// OpenCV and the datasets: a camera point projects to x = fx X / Z + cx). Both sides of every
// triangle are drawn.
//
// Coverage follows the top-left fill rule on 1/256-pixel fixed-point vertices, so triangles
// sharing an edge (the same two vertices, also after clipping) cover every pixel along it
// exactly once. A vertex in the middle of another triangle's edge (a T-junction) is not
// shared and can leave rare one-pixel cracks: meshes should split such edges.
//
// Depth is the exact z of the triangle's plane at the pixel centre. Colour is the texture
// sampled perspective-correctly (u/z, v/z and 1/z are affine in the image), bilinear within
// the mip level whose texel size matches the pixel footprint (chosen every 8 pixels of a row).
#include <dynslam/core/Frame.h>
#include <dynslam/sim/Mesh.h>
#include <dynslam/sim/Texture.h>

#include <opencv2/core/mat.hpp>

namespace dynslam::sim {

struct RenderOutput {
  cv::Mat rgb;    ///< CV_8UC3 BGR; background colour where nothing was hit
  cv::Mat depth;  ///< CV_32FC1 metres along the optical axis; 0 where nothing was hit
  cv::Mat label;  ///< CV_16UC1 instance id of the visible surface; 0 for static scene/nothing
};

struct RasterizerOptions {
  double near_plane = 0.05;  ///< m
  cv::Vec3b background{40, 40, 40};
  /// Bilinear texture filtering (false: nearest texel, blocky when magnified).
  bool bilinear = true;
  /// Pick the mip level matching each pixel's footprint (false: always the full-size image,
  /// which aliases on far or grazing surfaces).
  bool mipmaps = true;
  /// Added to the mip level (log2 of the footprint in texels): > 0 blurrier, < 0 sharper.
  double mip_bias = 0.0;
  /// Horizontal bands rendered in parallel (1: the calling thread only; 0: one per core). The
  /// output does not depend on it.
  int threads = 1;
};

/// Renders `mesh` seen by a camera at T_world_camera (optical frame: x right, y down, z
/// forward) with intrinsics `camera`. Deterministic; may use several threads. The output
/// images are written in place when their size and type fit and nothing else shares them
/// (a cv::Mat copy of a previous frame keeps its pixels). Throws std::invalid_argument
/// for an empty image size or a non-positive near plane and std::out_of_range for a triangle
/// whose texture index is not in `textures`.
void render(const Mesh& mesh, const TextureLibrary& textures, const core::CameraIntrinsics& camera,
            const Eigen::Isometry3d& T_world_camera, RenderOutput& out,
            const RasterizerOptions& options = {});

}  // namespace dynslam::sim
