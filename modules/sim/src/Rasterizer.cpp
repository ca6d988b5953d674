// The rasterizer's two pixel passes over horizontal bands: coverage (edge functions, 1/z test,
// winning triangle per pixel) then deferred shading (depth, label, texture) exactly once per
// pixel, so overdraw costs only the cheap coverage loop. Bands are independent, so any number
// of threads gives the same images.
#include "dynslam/sim/Rasterizer.h"

#include "RasterSetup.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <system_error>
#include <thread>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace dynslam::sim {
namespace {

using detail::RasterScene;
using detail::RasterTriangle;
using detail::ShadingPlane;

// Per-pixel winner of the depth test: the ShadingPlane index, or -1 for background.
struct Buffers {
  std::vector<int32_t> winner;
  RasterScene scene;
};

// Keeps the nearest surface per pixel of rows [row_begin, row_end). 1/z ("w") is kept in the
// depth image until the shading pass overwrites it with z: larger w is nearer.
void coverBand(const RasterScene& scene, int row_begin, int row_end, int width, cv::Mat& w_image,
               int32_t* winner) {
  for (int y = row_begin; y < row_end; ++y) {
    std::fill_n(w_image.ptr<float>(y), width, 0.0f);
    std::fill_n(winner + static_cast<size_t>(y) * width, width, -1);
  }
  for (const RasterTriangle& t : scene.triangles) {
    const int y_first = std::max(t.min_y, row_begin), y_last = std::min(t.max_y, row_end - 1);
    for (int y = y_first; y <= y_last; ++y) {
      // The covered pixels of a row are one interval: intersect the three edges' half-lines.
      int64_t lo = t.min_x, hi = t.max_x;
      for (int e = 0; e < 3; ++e) {
        const int64_t a = t.step_x[e], b = t.step_y[e] * y + t.origin[e];  // E = a x + b
        if (a > 0)
          lo = std::max(lo, detail::ceilDiv(-b, a));
        else if (a < 0)
          hi = std::min(hi, detail::floorDiv(b, -a));
        else if (b < 0)
          hi = -1;
      }
      if (lo > hi) continue;
      const auto w_row = static_cast<float>(t.w_y * y + t.w_0);
      const auto w_x = static_cast<float>(t.w_x);
      float* w_out = w_image.ptr<float>(y);
      int32_t* id_out = winner + static_cast<size_t>(y) * width;
      const int32_t id = t.shading;
      // Branch-free select so the compiler can vectorise the loop.
      for (int x = static_cast<int>(lo); x <= static_cast<int>(hi); ++x) {
        const float w = w_row + w_x * static_cast<float>(x);
        const bool nearer = w > w_out[x];
        w_out[x] = nearer ? w : w_out[x];
        id_out[x] = nearer ? id : id_out[x];
      }
    }
  }
}

// Bilinear blend of packed texels (top row a b, bottom row c d) with 8-bit weights wx, wy
// (of b/d and of c/d), per channel: vertical lerps, then the horizontal one, each rounded:
//   lerp(p, q, f) = (p (256 - f) + q f + 128) >> 8.
// The SSE2 path and the portable one compute the same integers.
#if defined(__SSE2__)
inline uint32_t bilinear(uint32_t a, uint32_t b, uint32_t c, uint32_t d, uint32_t wx, uint32_t wy) {
  const __m128i zero = _mm_setzero_si128(), round = _mm_set1_epi16(128);
  const __m128i top =
      _mm_unpacklo_epi8(_mm_set_epi32(0, 0, static_cast<int>(b), static_cast<int>(a)), zero);
  const __m128i bottom =
      _mm_unpacklo_epi8(_mm_set_epi32(0, 0, static_cast<int>(d), static_cast<int>(c)), zero);
  // 16-bit lanes: 255 * 256 + 128 still fits unsigned, and mullo's low half is exact.
  const __m128i columns = _mm_srli_epi16(
      _mm_add_epi16(
          _mm_add_epi16(_mm_mullo_epi16(top, _mm_set1_epi16(static_cast<short>(256 - wy))),
                        _mm_mullo_epi16(bottom, _mm_set1_epi16(static_cast<short>(wy)))),
          round),
      8);
  const __m128i right = _mm_srli_si128(columns, 8);
  const __m128i blend = _mm_srli_epi16(
      _mm_add_epi16(
          _mm_add_epi16(_mm_mullo_epi16(columns, _mm_set1_epi16(static_cast<short>(256 - wx))),
                        _mm_mullo_epi16(right, _mm_set1_epi16(static_cast<short>(wx)))),
          round),
      8);
  return static_cast<uint32_t>(_mm_cvtsi128_si32(_mm_packus_epi16(blend, blend)));
}
#else
// Two channels per multiply (B and R in 16-bit lanes, G alone).
inline uint32_t lerpTexel(uint32_t p, uint32_t q, uint32_t f) {
  const uint32_t g = 256 - f;
  const uint32_t rb = (((p & 0xFF00FFu) * g + (q & 0xFF00FFu) * f + 0x800080u) >> 8) & 0xFF00FFu;
  const uint32_t gr = (((p & 0xFF00u) * g + (q & 0xFF00u) * f + 0x8000u) >> 8) & 0xFF00u;
  return rb | gr;
}
inline uint32_t bilinear(uint32_t a, uint32_t b, uint32_t c, uint32_t d, uint32_t wx, uint32_t wy) {
  return lerpTexel(lerpTexel(a, c, wy), lerpTexel(b, d, wy), wx);
}
#endif

// Texture coordinates go to fixed point with 8 fractional bits at level 0. Adding 2^40 (a
// multiple of every texture period in these units) makes them positive, so truncation is
// floor and wrapping is unchanged; level L is then a right shift by L.
constexpr double kFixedOne = 256.0;
constexpr double kFixedOffset = 1099511627776.0;  // 2^40

inline int64_t toFixed(double texels) {
  return static_cast<int64_t>(texels * kFixedOne + kFixedOffset);
}

// `s`, `t`: level-0 fixed-point coordinates; `level`: the mip level to read.
template <bool kBilinear>
inline uint32_t sample(const detail::SamplerLevel& mip, int64_t s, int64_t t, int level) {
  if (!kBilinear)
    return mip.texels[(((t >> (8 + level)) & mip.mask_y) << mip.width_bits) +
                      ((s >> (8 + level)) & mip.mask_x)];
  // Texel centres are at +0.5: shift by half a texel, then split into texel and weight.
  const int64_t fs = (s >> level) - 128, ft = (t >> level) - 128;
  const int64_t x0 = (fs >> 8) & mip.mask_x, x1 = (x0 + 1) & mip.mask_x;
  const uint32_t* row0 = mip.texels + (((ft >> 8) & mip.mask_y) << mip.width_bits);
  const uint32_t* row1 = mip.texels + ((((ft >> 8) + 1) & mip.mask_y) << mip.width_bits);
  const auto wx = static_cast<uint32_t>(fs & 255), wy = static_cast<uint32_t>(ft & 255);
  return bilinear(row0[x0], row0[x1], row1[x0], row1[x1], wx, wy);
}

// The plane's constants as locals: the byte stores of the colour may alias anything, and
// members read through a reference would be reloaded for every pixel.
struct RunConstants {
  double w_x, u_x, v_x;
  float lod_w_x, lod_w_y, lod_u_x, lod_u_y, lod_v_x, lod_v_y;
  float lod_scale;  // 4^mip_bias, applied to the squared footprint
  int max_level;
};

// The mip level whose texels match the pixel footprint: round(log2(footprint)), where the
// footprint is the longer of the texture-space steps of one pixel in x and in y.
inline int mipLevel(const RunConstants& c, double u, double v, double z) {
  const auto zf = static_cast<float>(z), uf = static_cast<float>(u), vf = static_cast<float>(v);
  // d(u)/dx = (d(u/z)/dx - u d(1/z)/dx) z, and likewise for v and for y.
  const float du_dx = (c.lod_u_x - uf * c.lod_w_x) * zf, dv_dx = (c.lod_v_x - vf * c.lod_w_x) * zf;
  const float du_dy = (c.lod_u_y - uf * c.lod_w_y) * zf, dv_dy = (c.lod_v_y - vf * c.lod_w_y) * zf;
  const float footprint2 =
      std::max(du_dx * du_dx + dv_dx * dv_dx, du_dy * du_dy + dv_dy * dv_dy) * c.lod_scale;
  // round(log2(footprint)) = floor((floor(log2(footprint^2)) + 1) / 2), and floor(log2) of a
  // float is its exponent field.
  uint32_t bits;
  std::memcpy(&bits, &footprint2, sizeof bits);
  const int exponent = static_cast<int>(bits >> 23) - 127;
  return std::clamp((exponent + 1) >> 1, 0, c.max_level);
}

// Pixels [x_begin, x_end) of row y, all won by `plane`.
template <bool kBilinear, bool kMipmaps>
void shadeRun(const ShadingPlane& plane, int y, int x_begin, int x_end, float lod_scale,
              float* depth, uint16_t* label, uint8_t* bgr) {
  const RunConstants c{plane.w_x,
                       plane.u_x,
                       plane.v_x,
                       static_cast<float>(plane.w_x),
                       static_cast<float>(plane.w_y),
                       static_cast<float>(plane.u_x),
                       static_cast<float>(plane.u_y),
                       static_cast<float>(plane.v_x),
                       static_cast<float>(plane.v_y),
                       lod_scale,
                       plane.level_count - 1};
  const double w_row = plane.w_y * y + plane.w_0;
  const double u_row = plane.u_y * y + plane.u_0, v_row = plane.v_y * y + plane.v_0;
  const detail::SamplerLevel* levels = plane.levels;
  const uint16_t instance = plane.instance;
  double x_at = x_begin;
  int level = 0;
  for (int x = x_begin; x < x_end; ++x, x_at += 1.0) {
    const double z = 1.0 / (w_row + c.w_x * x_at);
    const double u = (u_row + c.u_x * x_at) * z, v = (v_row + c.v_x * x_at) * z;
    depth[x] = static_cast<float>(z);
    label[x] = instance;
    // The footprint changes slowly along a row: the level is chosen at the run's first pixel
    // and at every eighth column, which depends on the pixels only (not on bands or threads).
    if (kMipmaps && (x == x_begin || (x & 7) == 0)) level = mipLevel(c, u, v, z);
    const uint32_t texel = sample<kBilinear>(levels[level], toFixed(u), toFixed(v), level);
    bgr[3 * x] = static_cast<uint8_t>(texel);
    bgr[3 * x + 1] = static_cast<uint8_t>(texel >> 8);
    bgr[3 * x + 2] = static_cast<uint8_t>(texel >> 16);
  }
}

template <bool kBilinear, bool kMipmaps>
void shadeBand(const RasterScene& scene, const int32_t* winner, int row_begin, int row_end,
               const RasterizerOptions& options, RenderOutput& out) {
  const int width = out.rgb.cols;
  const auto lod_scale = static_cast<float>(std::pow(4.0, options.mip_bias));
  for (int y = row_begin; y < row_end; ++y) {
    const int32_t* ids = winner + static_cast<size_t>(y) * width;
    auto* depth = out.depth.ptr<float>(y);
    auto* label = out.label.ptr<uint16_t>(y);
    auto* bgr = out.rgb.ptr<uint8_t>(y);
    for (int x = 0; x < width;) {
      const int32_t id = ids[x];
      int end = x + 1;
      while (end < width && ids[end] == id) ++end;
      if (id >= 0) {
        shadeRun<kBilinear, kMipmaps>(scene.shading[id], y, x, end, lod_scale, depth, label, bgr);
      } else {
        for (int i = x; i < end; ++i) {
          depth[i] = 0.0f;
          label[i] = 0;
          for (int c = 0; c < 3; ++c) bgr[3 * i + c] = options.background[c];
        }
      }
      x = end;
    }
  }
}

void renderBand(const RasterScene& scene, int32_t* winner, int row_begin, int row_end,
                const RasterizerOptions& options, RenderOutput& out) {
  coverBand(scene, row_begin, row_end, out.rgb.cols, out.depth, winner);
  if (options.bilinear && options.mipmaps)
    shadeBand<true, true>(scene, winner, row_begin, row_end, options, out);
  else if (options.bilinear)
    shadeBand<true, false>(scene, winner, row_begin, row_end, options, out);
  else if (options.mipmaps)
    shadeBand<false, true>(scene, winner, row_begin, row_end, options, out);
  else
    shadeBand<false, false>(scene, winner, row_begin, row_end, options, out);
}

}  // namespace

void render(const Mesh& mesh, const TextureLibrary& textures, const core::CameraIntrinsics& camera,
            const Eigen::Isometry3d& T_world_camera, RenderOutput& out,
            const RasterizerOptions& options) {
  if (camera.width <= 0 || camera.height <= 0)
    throw std::invalid_argument("render: the camera has an empty image size");
  if (!(options.near_plane > 0)) throw std::invalid_argument("render: near_plane must be > 0");
  const auto prepare = [&](cv::Mat& image, int type) {
    // Images shared with another header (a frame the caller kept) get a buffer of their own
    // instead of being overwritten.
    if (image.u != nullptr && image.u->refcount > 1) image.release();
    image.create(camera.height, camera.width, type);
  };
  prepare(out.rgb, CV_8UC3);
  prepare(out.depth, CV_32FC1);
  prepare(out.label, CV_16UC1);

  // Reused between frames: no allocation once the sizes have settled.
  thread_local Buffers buffers;
  buffers.winner.resize(static_cast<size_t>(camera.width) * camera.height);
  detail::setupTriangles(mesh, textures, camera, T_world_camera, options.near_plane, buffers.scene);

  int bands =
      options.threads > 0 ? options.threads : static_cast<int>(std::thread::hardware_concurrency());
  bands = std::clamp(bands, 1, camera.height);
  std::vector<std::thread> workers;
  int first_unstarted = 1;
  try {
    for (; first_unstarted < bands; ++first_unstarted)
      workers.emplace_back(renderBand, std::cref(buffers.scene), buffers.winner.data(),
                           first_unstarted * camera.height / bands,
                           (first_unstarted + 1) * camera.height / bands, std::cref(options),
                           std::ref(out));
  } catch (const std::system_error&) {
    // No thread to be had: the calling thread renders the bands left (same images).
  }
  renderBand(buffers.scene, buffers.winner.data(), 0, camera.height / bands, options, out);
  for (int band = first_unstarted; band < bands; ++band)
    renderBand(buffers.scene, buffers.winner.data(), band * camera.height / bands,
               (band + 1) * camera.height / bands, options, out);
  for (std::thread& worker : workers) worker.join();
}

}  // namespace dynslam::sim
