#include "RasterSetup.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

namespace dynslam::sim::detail {
namespace {

// Pixels beyond each image border that vertices may reach before being clipped: keeps the
// fixed-point edge functions far from overflow while clipping only the triangles that reach
// well outside the view.
constexpr double kGuardBandPixels = 1024;
constexpr int kClipPlanes = 5;  // near, left, right, top, bottom
// Sutherland-Hodgman adds at most one vertex per plane.
constexpr int kMaxPolygon = 3 + kClipPlanes;

struct ClipPlane {
  Eigen::Vector3d normal;  // inside: normal . X + offset >= 0 (camera frame)
  double offset;
  double distance(const Eigen::Vector3d& X) const { return normal.dot(X) + offset; }
};

struct Polygon {
  std::array<Eigen::Vector3d, kMaxPolygon + 1> vertex;
  int size = 0;
};

std::array<ClipPlane, kClipPlanes> clipPlanes(const core::CameraIntrinsics& k, double near) {
  const double g = kGuardBandPixels;
  // x = fx X / Z + cx >= -g  <=>  fx X + (cx + g) Z >= 0 for Z > 0, and likewise for the rest.
  return {{{{0, 0, 1}, -near},
           {{k.fx, 0, k.cx + g}, 0},
           {{-k.fx, 0, k.width - 1 + g - k.cx}, 0},
           {{0, k.fy, k.cy + g}, 0},
           {{0, -k.fy, k.height - 1 + g - k.cy}, 0}}};
}

bool lexicographicLess(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  if (a.x() != b.x()) return a.x() < b.x();
  if (a.y() != b.y()) return a.y() < b.y();
  return a.z() < b.z();
}

// Where edge a-b crosses the plane. The endpoints are put in a canonical order first, so the
// two triangles sharing an edge get bit-identical points and their clipped edges still meet
// exactly (no cracks along the near plane).
Eigen::Vector3d crossing(Eigen::Vector3d a, double da, Eigen::Vector3d b, double db) {
  if (lexicographicLess(b, a)) {
    std::swap(a, b);
    std::swap(da, db);
  }
  return a + (da / (da - db)) * (b - a);
}

void clip(const ClipPlane& plane, const Polygon& in, Polygon& out) {
  out.size = 0;
  for (int i = 0; i < in.size; ++i) {
    const Eigen::Vector3d& a = in.vertex[i];
    const Eigen::Vector3d& b = in.vertex[(i + 1) % in.size];
    const double da = plane.distance(a), db = plane.distance(b);
    if (da >= 0) out.vertex[out.size++] = a;
    if ((da >= 0) != (db >= 0)) out.vertex[out.size++] = crossing(a, da, b, db);
  }
}

// 1/z, u/z, v/z over the image for the plane of triangle P (camera frame). With the ray
// r(x, y) = ((x - cx) / fx, (y - cy) / fy, 1) and the plane n . X = d, 1/z = n . r / d; an
// affine texture coordinate u(X) = g . X + h gives u/z = g . r + h / z. Returns false for a
// degenerate triangle or one seen exactly edge-on (it covers no pixel).
bool shadingPlane(const std::array<Eigen::Vector3d, 3>& P, const Triangle& triangle,
                  const std::vector<MipLevel>& levels, const SamplerLevel* sampler_levels,
                  const core::CameraIntrinsics& k, ShadingPlane& out) {
  const Eigen::Vector3d e1 = P[1] - P[0], e2 = P[2] - P[0];
  const Eigen::Vector3d n = e1.cross(e2);
  const double nn = n.squaredNorm();
  const double d = n.dot(P[0]);
  if (nn == 0 || std::abs(d) <= 1e-12 * std::sqrt(nn) * P[0].norm()) return false;
  // Gradients of the barycentric coordinates of P[1] and P[2] within the plane.
  const Eigen::Vector3d g1 = e2.cross(n) / nn, g2 = n.cross(e1) / nn;
  const auto affine = [&](const Eigen::Vector3d& g, double h, double& ax, double& ay,
                          double& a0) {  // g . r + h * (1/z)
    ax = g.x() / k.fx + h * out.w_x;
    ay = g.y() / k.fy + h * out.w_y;
    a0 = g.z() - g.x() * k.cx / k.fx - g.y() * k.cy / k.fy + h * out.w_0;
  };
  out.w_x = n.x() / (k.fx * d);
  out.w_y = n.y() / (k.fy * d);
  out.w_0 = (n.z() - n.x() * k.cx / k.fx - n.y() * k.cy / k.fy) / d;
  const double width = levels[0].width, height = levels[0].height;
  const auto& t = triangle.uv;
  const Eigen::Vector3d gu =
      (t[1].x() - t[0].x()) * width * g1 + (t[2].x() - t[0].x()) * width * g2;
  const Eigen::Vector3d gv =
      (t[1].y() - t[0].y()) * height * g1 + (t[2].y() - t[0].y()) * height * g2;
  affine(gu, t[0].x() * width - gu.dot(P[0]), out.u_x, out.u_y, out.u_0);
  affine(gv, t[0].y() * height - gv.dot(P[0]), out.v_x, out.v_y, out.v_0);
  // Garbage in (NaN or infinite vertices or texture coordinates) draws nothing rather than
  // indexing textures with undefined integers.
  const double all =
      out.w_x + out.w_y + out.w_0 + out.u_x + out.u_y + out.u_0 + out.v_x + out.v_y + out.v_0;
  if (!std::isfinite(all)) return false;
  out.levels = sampler_levels;
  out.level_count = static_cast<int>(levels.size());
  out.instance = triangle.instance;
  return true;
}

struct FixedPoint {
  int64_t x, y;
};

FixedPoint project(const Eigen::Vector3d& X, const core::CameraIntrinsics& k) {
  const double scale = 1 << kSubpixelBits;
  return {std::llround((k.fx * X.x() / X.z() + k.cx) * scale),
          std::llround((k.fy * X.y() / X.z() + k.cy) * scale)};
}

// Appends the coverage form of screen triangle abc, if it has area and touches the image.
void addRasterTriangle(FixedPoint a, FixedPoint b, FixedPoint c, const ShadingPlane& plane,
                       int32_t shading, const core::CameraIntrinsics& k, RasterScene& scene) {
  int64_t area = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
  if (area == 0) return;
  if (area < 0) std::swap(b, c);  // both sides are drawn: orient so the inside is positive
  constexpr int64_t one = int64_t{1} << kSubpixelBits;
  RasterTriangle t;
  t.min_x = static_cast<int>(std::max<int64_t>(0, ceilDiv(std::min({a.x, b.x, c.x}), one)));
  t.max_x =
      static_cast<int>(std::min<int64_t>(k.width - 1, floorDiv(std::max({a.x, b.x, c.x}), one)));
  t.min_y = static_cast<int>(std::max<int64_t>(0, ceilDiv(std::min({a.y, b.y, c.y}), one)));
  t.max_y =
      static_cast<int>(std::min<int64_t>(k.height - 1, floorDiv(std::max({a.y, b.y, c.y}), one)));
  if (t.min_x > t.max_x || t.min_y > t.max_y) return;
  const FixedPoint vertex[3] = {a, b, c};
  for (int e = 0; e < 3; ++e) {
    const FixedPoint& from = vertex[e];
    const FixedPoint& to = vertex[(e + 1) % 3];
    const int64_t dx = to.x - from.x, dy = to.y - from.y;
    // With y down and the inside on the positive side, a left edge goes up (dy < 0) and a top
    // edge goes right (dy == 0, dx > 0). Pixels exactly on other edges belong to the neighbour.
    const bool top_left = dy < 0 || (dy == 0 && dx > 0);
    // E = dx (Py - from.y) - dy (Px - from.x) with P = (x, y) << kSubpixelBits.
    t.step_x[e] = -dy * one;
    t.step_y[e] = dx * one;
    t.origin[e] = dy * from.x - dx * from.y - (top_left ? 0 : 1);
  }
  t.w_x = plane.w_x;
  t.w_y = plane.w_y;
  t.w_0 = plane.w_0;
  t.shading = shading;
  scene.triangles.push_back(t);
}

/// Sampler view of every texture's mip levels in scene.sampler_levels (sized first:
/// ShadingPlanes point into it); returns each texture's first level there.
std::vector<size_t> setupSamplers(const TextureLibrary& textures, RasterScene& scene) {
  std::vector<size_t> first_level(textures.size());
  size_t level_total = 0;
  for (size_t i = 0; i < textures.size(); ++i) {
    first_level[i] = level_total;
    level_total += textures.mipLevels(static_cast<int>(i)).size();
  }
  scene.sampler_levels.resize(level_total);
  for (size_t i = 0; i < textures.size(); ++i) {
    const std::vector<MipLevel>& levels = textures.mipLevels(static_cast<int>(i));
    for (size_t l = 0; l < levels.size(); ++l) {
      SamplerLevel& sampler = scene.sampler_levels[first_level[i] + l];
      sampler.texels = levels[l].texels.data();
      sampler.mask_x = levels[l].width - 1;
      sampler.mask_y = levels[l].height - 1;
      sampler.width_bits = 0;
      while ((1 << sampler.width_bits) < levels[l].width) ++sampler.width_bits;
    }
  }
  return first_level;
}

/// The camera-frame triangle P clipped to the view volume into `polygon`; false when nothing
/// of it is left.
bool clipToView(const std::array<Eigen::Vector3d, 3>& P,
                const std::array<ClipPlane, kClipPlanes>& planes, bool inside_all,
                Polygon& polygon) {
  Polygon scratch;
  for (int i = 0; i < 3; ++i) polygon.vertex[i] = P[i];
  polygon.size = 3;
  if (inside_all) return true;
  for (const ClipPlane& plane : planes) {
    clip(plane, polygon, scratch);
    std::swap(polygon, scratch);
    if (polygon.size < 3) break;
  }
  return polygon.size >= 3;
}

}  // namespace

void setupTriangles(const Mesh& mesh, const TextureLibrary& textures,
                    const core::CameraIntrinsics& camera, const Eigen::Isometry3d& T_world_camera,
                    double near_plane, RasterScene& scene) {
  scene.shading.clear();
  scene.triangles.clear();
  const Eigen::Isometry3d T_camera_world = T_world_camera.inverse();
  const Eigen::Matrix3d R = T_camera_world.linear();
  const Eigen::Vector3d t = T_camera_world.translation();
  const std::array<ClipPlane, kClipPlanes> planes = clipPlanes(camera, near_plane);
  const std::vector<size_t> first_level = setupSamplers(textures, scene);

  for (const Triangle& triangle : mesh) {
    if (triangle.texture < 0 || static_cast<size_t>(triangle.texture) >= textures.size())
      throw std::out_of_range("render: triangle texture " + std::to_string(triangle.texture) +
                              " is not in the library (" + std::to_string(textures.size()) +
                              " textures)");
    const std::array<Eigen::Vector3d, 3> P = {R * triangle.p[0] + t, R * triangle.p[1] + t,
                                              R * triangle.p[2] + t};
    bool outside_one = false, inside_all = true;
    for (const ClipPlane& plane : planes) {
      const double d0 = plane.distance(P[0]), d1 = plane.distance(P[1]), d2 = plane.distance(P[2]);
      outside_one |= d0 < 0 && d1 < 0 && d2 < 0;
      inside_all &= d0 >= 0 && d1 >= 0 && d2 >= 0;
    }
    if (outside_one) continue;
    ShadingPlane shading;
    if (!shadingPlane(P, triangle, textures.mipLevels(triangle.texture),
                      &scene.sampler_levels[first_level[triangle.texture]], camera, shading))
      continue;
    Polygon polygon;
    if (!clipToView(P, planes, inside_all, polygon)) continue;
    const auto index = static_cast<int32_t>(scene.shading.size());
    const size_t first_raster = scene.triangles.size();
    const FixedPoint fan_root = project(polygon.vertex[0], camera);
    FixedPoint previous = project(polygon.vertex[1], camera);
    for (int i = 2; i < polygon.size; ++i) {
      const FixedPoint next = project(polygon.vertex[i], camera);
      addRasterTriangle(fan_root, previous, next, shading, index, camera, scene);
      previous = next;
    }
    if (scene.triangles.size() > first_raster) scene.shading.push_back(shading);
  }
}

}  // namespace dynslam::sim::detail
