#include "dynslam/sim/SensorNoise.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <vector>

namespace dynslam::sim {
namespace {

constexpr int kTableBits = 16;
constexpr int kTableSize = 1 << kTableBits;

// Acklam's rational approximation of the standard normal quantile (relative error < 1.2e-9).
double inverseNormalCdf(double p) {
  static const double a[] = {-3.969683028665376e+01, 2.209460984245205e+02,  -2.759285104469687e+02,
                             1.383577518672690e+02,  -3.066479806614716e+01, 2.506628277459239e+00};
  static const double b[] = {-5.447609879822406e+01, 1.615858368580409e+02, -1.556989798598866e+02,
                             6.680131188771972e+01, -1.328068155288572e+01};
  static const double c[] = {-7.784894002430293e-03, -3.223964580411365e-01, -2.400758277161838e+00,
                             -2.549732539343734e+00, 4.374664141464968e+00,  2.938163982698783e+00};
  static const double d[] = {7.784695709041462e-03, 3.224671290700398e-01, 2.445134137142996e+00,
                             3.754408661907416e+00};
  const double p_low = 0.02425;
  if (p < p_low) {
    const double q = std::sqrt(-2 * std::log(p));
    return (((((c[0] * q + c[1]) * q + c[2]) * q + c[3]) * q + c[4]) * q + c[5]) /
           ((((d[0] * q + d[1]) * q + d[2]) * q + d[3]) * q + 1);
  }
  if (p > 1 - p_low) return -inverseNormalCdf(1 - p);
  const double q = p - 0.5, r = q * q;
  return (((((a[0] * r + a[1]) * r + a[2]) * r + a[3]) * r + a[4]) * r + a[5]) * q /
         (((((b[0] * r + b[1]) * r + b[2]) * r + b[3]) * r + b[4]) * r + 1);
}

// Standard normal samples at the midpoints of 65536 equal-probability strata, rescaled to unit
// variance: exactly the right distribution (to +-4.2 sigma) with no random state of its own.
const std::vector<float>& standardNormals() {
  static const std::vector<float> table = [] {
    std::vector<double> quantiles(kTableSize);
    double sum_squares = 0;
    for (int i = 0; i < kTableSize; ++i) {
      quantiles[i] = inverseNormalCdf((i + 0.5) / kTableSize);
      sum_squares += quantiles[i] * quantiles[i];
    }
    const double scale = 1.0 / std::sqrt(sum_squares / kTableSize);
    std::vector<float> normals(kTableSize);
    for (int i = 0; i < kTableSize; ++i) normals[i] = static_cast<float>(quantiles[i] * scale);
    return normals;
  }();
  return table;
}

// SplitMix64: a fast, well-mixed 64-bit stream; each output gives four 16-bit table indices.
class IndexStream {
 public:
  explicit IndexStream(uint64_t seed) : state_(seed) {}
  uint64_t nextFour() {
    uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }

 private:
  uint64_t state_;
};

// Calls visit(i, table_index) for i in [0, count), four indices per generator output.
template <typename Visit>
inline void forEachIndex(int count, IndexStream& indices, Visit visit) {
  int i = 0;
  for (; i + 4 <= count; i += 4) {
    const uint64_t bits = indices.nextFour();
    visit(i, bits & (kTableSize - 1));
    visit(i + 1, (bits >> 16) & (kTableSize - 1));
    visit(i + 2, (bits >> 32) & (kTableSize - 1));
    visit(i + 3, bits >> 48);
  }
  for (uint64_t bits = i < count ? indices.nextFour() : 0; i < count; ++i, bits >>= 16)
    visit(i, bits & (kTableSize - 1));
}

// Colour noise is rounded to whole grey levels, so 4096 quantiles (an 8 KB table that stays
// in L1) describe it as well as 65536 would.
constexpr int kColourTableSize = 4096;

void addColourNoise(cv::Mat& rgb, double sigma, IndexStream& indices) {
  // Integer offsets: adding a rounded offset to an integer pixel rounds the noisy value.
  thread_local double table_sigma = -1;
  thread_local std::vector<int16_t> offsets(kColourTableSize);
  if (sigma != table_sigma) {
    const int stride = kTableSize / kColourTableSize;
    const std::vector<float>& normals = standardNormals();
    for (int i = 0; i < kColourTableSize; ++i) {
      // Mean of each stratum's 16 quantiles: the variance stays within 0.1 % of one.
      double sum = 0;
      for (int j = 0; j < stride; ++j) sum += normals[i * stride + j];
      offsets[i] = static_cast<int16_t>(std::clamp(std::lround(sum / stride * sigma), -255L, 255L));
    }
    table_sigma = sigma;
  }
  const int16_t* offset = offsets.data();
  for (int y = 0; y < rgb.rows; ++y) {
    uint8_t* row = rgb.ptr<uint8_t>(y);
    forEachIndex(rgb.cols * 3, indices, [&](int i, uint64_t index) {
      row[i] =
          static_cast<uint8_t>(std::clamp(row[i] + offset[index & (kColourTableSize - 1)], 0, 255));
    });
  }
}

// Marks `width` pixels on the far side of every 4-neighbour pair whose depths differ by more
// than `jump` (pairs with an invalid pixel have no far side to remove: it is already a hole).
void markEdgeHoles(const cv::Mat& depth, double jump, int width, std::vector<uint8_t>& hole) {
  const int cols = depth.cols, rows = depth.rows;
  hole.assign(static_cast<size_t>(cols) * rows, 0);
  const auto mark = [&](int x, int y, int step_x, int step_y) {
    for (int i = 0; i < width; ++i, x += step_x, y += step_y) {
      if (x < 0 || x >= cols || y < 0 || y >= rows) return;
      hole[static_cast<size_t>(y) * cols + x] = 1;
    }
  };
  const auto threshold = static_cast<float>(jump);
  for (int y = 0; y < rows; ++y) {
    const float* row = depth.ptr<float>(y);
    const float* below = y + 1 < rows ? depth.ptr<float>(y + 1) : nullptr;
    for (int x = 0; x + 1 < cols; ++x) {
      const float a = row[x], b = row[x + 1];
      if (std::abs(a - b) > threshold && a > 0 && b > 0) {
        if (b > a)
          mark(x + 1, y, 1, 0);
        else
          mark(x, y, -1, 0);
      }
    }
    if (below == nullptr) continue;
    for (int x = 0; x < cols; ++x) {
      const float a = row[x], b = below[x];
      if (std::abs(a - b) > threshold && a > 0 && b > 0) {
        if (b > a)
          mark(x, y + 1, 0, 1);
        else
          mark(x, y, 0, -1);
      }
    }
  }
}

// Stereo: the background left of a near object's left edge, which the right imager (baseline b
// to the right) cannot see: f b (1/z_near - 1/z_far) px of it.
void markStereoOcclusions(const cv::Mat& depth, double focal_baseline, double jump,
                          std::vector<uint8_t>& hole) {
  const int cols = depth.cols;
  for (int y = 0; y < depth.rows; ++y) {
    const float* row = depth.ptr<float>(y);
    for (int x = 0; x + 1 < cols; ++x) {
      const float far = row[x], near = row[x + 1];
      if (!(far > 0 && near > 0 && far - near > jump)) continue;
      const int band = int(std::ceil(focal_baseline * (1.0 / near - 1.0 / far)));
      for (int i = 0; i < band && x - i >= 0; ++i) hole[static_cast<size_t>(y) * cols + x - i] = 1;
    }
  }
}

void addDepthNoise(cv::Mat& depth, const RgbdNoiseOptions& options, IndexStream& indices) {
  thread_local std::vector<uint8_t> hole;
  if (options.edge_hole_width > 0)
    markEdgeHoles(depth, options.edge_jump, options.edge_hole_width, hole);
  else
    hole.assign(static_cast<size_t>(depth.cols) * depth.rows, 0);
  const bool stereo = options.depth_model == DepthModel::Stereo;
  const double focal_baseline = options.focal_px * options.stereo_baseline;
  if (stereo) markStereoOcclusions(depth, focal_baseline, options.edge_jump, hole);
  const float* normal = standardNormals().data();
  const auto sigma_min = static_cast<float>(options.depth_sigma_min);
  const auto sigma_z2 = static_cast<float>(stereo ? options.disparity_sigma / focal_baseline
                                                  : options.depth_sigma_z2);
  const auto min_range = static_cast<float>(options.min_range);
  const auto max_range = static_cast<float>(options.max_range);
  for (int y = 0; y < depth.rows; ++y) {
    float* row = depth.ptr<float>(y);
    const uint8_t* hole_row = hole.data() + static_cast<size_t>(y) * depth.cols;
    // An index for every pixel, valid or not, so one pixel's noise does not depend on others.
    forEachIndex(depth.cols, indices, [&](int x, uint64_t index) {
      const float z = row[x];
      const bool valid = z > 0 && !hole_row[x] && z <= max_range && z >= min_range;
      const float noisy = z + (sigma_min + sigma_z2 * z * z) * normal[index];
      row[x] = valid && noisy > 0 ? noisy : 0.0f;
    });
  }
}

}  // namespace

void applyRgbdNoise(RenderOutput& frame, const RgbdNoiseOptions& options, std::mt19937_64& rng) {
  if (!frame.rgb.empty() && frame.rgb.type() != CV_8UC3)
    throw std::invalid_argument("applyRgbdNoise: rgb must be CV_8UC3");
  if (!frame.depth.empty() && frame.depth.type() != CV_32FC1)
    throw std::invalid_argument("applyRgbdNoise: depth must be CV_32FC1");
  // Both seeds are drawn whatever is present, so the rng advances the same way every call.
  IndexStream colour_indices(rng()), depth_indices(rng());
  if (!frame.rgb.empty() && options.colour_sigma > 0)
    addColourNoise(frame.rgb, options.colour_sigma, colour_indices);
  if (!frame.depth.empty()) addDepthNoise(frame.depth, options, depth_indices);
}

}  // namespace dynslam::sim
