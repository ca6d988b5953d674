#include "dynslam/segmentation/DepthThresholdSegmenter.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace dynslam::segmentation {
namespace {

/// Depth step, m, across which two neighbouring pixels are one surface: a body's surface changes
/// by millimetres between pixels, two people walking less than e apart by decimetres (3 and 10
/// cm measured alike: docs/notes/perception.md, 2026-11-28, overlap_rule).
constexpr float kSurfaceStep = 0.05f;

/// The pixels of `area` as the search sees them, for `n` masks held one bit each in a `Bits`
/// per pixel: 8 bits cover the usual few people at an eighth of the memory traffic of 64 (the
/// time it saves: docs/notes/perception.md, 2026-11-28, overlap_rule). The grid has one more
/// pixel on every side that no mask holds, so that the search needs no bounds checks: pixel
/// (x, y) of `area` is index (y - area.y + 1) * W + x - area.x + 1.
template <typename Bits>
struct OverlapGrid {
  cv::Rect area;
  int W = 0;
  size_t N = 0;
  std::vector<Bits> holders;  // bit k: masks[k] holds the pixel
  std::vector<float> z;       // its depth

  OverlapGrid(const std::vector<core::ObjectMask>& masks, size_t n, const cv::Mat& depth,
              cv::Rect a)
      : area(a), W(a.width + 2), N(size_t(W) * (a.height + 2)), holders(N, 0), z(N, 0.f) {
    for (int y = area.y; y < area.br().y; ++y) {
      const float* row = depth.ptr<float>(y);
      std::copy(row + area.x, row + area.br().x, z.begin() + index(area.x, y));
    }
    for (size_t k = 0; k < n; ++k) {
      if (!masks[k].valid || masks[k].mask.empty()) continue;
      const cv::Rect r = masks[k].roi & area;
      for (int y = r.y; y < r.br().y; ++y) {
        const uint8_t* row = masks[k].mask.ptr<uint8_t>(y - masks[k].roi.y) - masks[k].roi.x;
        Bits* h = holders.data() + index(area.x, y) - area.x;  // h[x]: pixel (x, y)
        for (int x = r.x; x < r.br().x; ++x)
          if (row[x]) h[x] |= Bits(Bits(1) << k);
      }
    }
  }
  size_t index(int x, int y) const { return size_t(y - area.y + 1) * W + (x - area.x + 1); }
};

/// For each pixel of the grid, the mask whose surface reached it (its only holder for pixels
/// one mask holds); -1: shared and reached by no surface; -2: no mask holds it. Breadth-first
/// from every mask's own pixels beside shared ones into the shared ones, across neighbours one
/// surface step apart: a shared pixel goes to the object whose surface reaches it first.
template <typename Bits>
std::vector<int8_t> surfaceOwners(const OverlapGrid<Bits>& g) {
  const size_t W = size_t(g.W), N = g.N;
  std::vector<int8_t> owner(N, -2);
  for (size_t p = 0; p < N; ++p) {
    const Bits h = g.holders[p];
    if (h) owner[p] = (h & (h - 1)) == 0 ? int8_t(__builtin_ctzll(h)) : int8_t(-1);
  }
  const std::ptrdiff_t step[4] = {-1, 1, -std::ptrdiff_t(W), std::ptrdiff_t(W)};
  std::vector<std::uint32_t> queue;  // grid indices (the grid is at most an image)
  queue.reserve(N);
  for (size_t p = W; p + W < N; ++p)
    if (owner[p] >= 0 &&
        (owner[p - 1] == -1 || owner[p + 1] == -1 || owner[p - W] == -1 || owner[p + W] == -1))
      queue.push_back(std::uint32_t(p));
  for (size_t head = 0; head < queue.size(); ++head) {
    const std::uint32_t p = queue[head];
    const int k = owner[p];
    for (std::ptrdiff_t d : step) {
      const std::uint32_t q = std::uint32_t(p + d);
      if (owner[q] != -1 || !(g.holders[q] >> k & 1) || !(std::abs(g.z[q] - g.z[p]) < kSurfaceStep))
        continue;
      owner[q] = int8_t(k);
      queue.push_back(q);
    }
  }
  return owner;
}

/// Clears each shared pixel from every mask but its owner; a pixel no surface reached goes to
/// the object whose d_t is closest to its depth (the nearer one on a tie).
template <typename Bits>
void keepOwners(std::vector<core::ObjectMask>& masks, size_t n, const OverlapGrid<Bits>& g,
                const std::vector<int8_t>& owner) {
  for (int y = g.area.y; y < g.area.br().y; ++y)
    for (int x = g.area.x; x < g.area.br().x; ++x) {
      const size_t p = g.index(x, y);
      const Bits h = g.holders[p];
      if ((h & (h - 1)) == 0) continue;  // held by one mask or none
      int keep = owner[p];
      if (keep < 0) {
        double best = 1e300;
        for (size_t k = 0; k < n; ++k) {
          if (!(h >> k & 1)) continue;
          const double d = std::abs(g.z[p] - masks[k].d_t);
          if (d < best || (d == best && masks[k].d_t < masks[keep].d_t)) best = d, keep = int(k);
        }
      }
      for (size_t k = 0; k < n; ++k)
        if ((h >> k & 1) && int(k) != keep)
          masks[k].mask.at<uint8_t>(y - masks[k].roi.y, x - masks[k].roi.x) = 0;
    }
}

/// The search in `area` for the first `n` masks.
template <typename Bits>
void resolveInArea(std::vector<core::ObjectMask>& masks, size_t n, const cv::Mat& depth,
                   cv::Rect area) {
  const OverlapGrid<Bits> grid(masks, n, depth, area);
  keepOwners(masks, n, grid, surfaceOwners(grid));
}

}  // namespace

void resolveByConnectivity(std::vector<core::ObjectMask>& masks, const cv::Mat& depth) {
  // Only the overlaps hold pixels of several masks: work in their bounding rectangle, one pixel
  // wider so that each mask's own pixels along it can start the search.
  const size_t n = std::min<size_t>(masks.size(), 64);  // one bit per mask
  auto usable = [&](size_t k) { return masks[k].valid && !masks[k].mask.empty(); };
  cv::Rect area;
  for (size_t a = 0; a < n; ++a)
    for (size_t b = a + 1; b < n; ++b)
      if (usable(a) && usable(b)) area |= masks[a].roi & masks[b].roi;
  if (area.empty()) return;
  area = cv::Rect(area.x - 1, area.y - 1, area.width + 2, area.height + 2) &
         cv::Rect(0, 0, depth.cols, depth.rows);
  if (n <= 8)
    resolveInArea<std::uint8_t>(masks, n, depth, area);
  else
    resolveInArea<std::uint64_t>(masks, n, depth, area);
}

}  // namespace dynslam::segmentation
