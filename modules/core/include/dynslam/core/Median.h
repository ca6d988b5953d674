#pragma once
// The median the stages, benches and tests report: the element at position n/2 of the sorted
// values (for an even count the upper of the two middle ones), found by a partial sort. One
// definition, so a figure in summary.json, a bench and a test mean the same thing.
// (evaluation::computeStatistics keeps evo's averaged median for APE/RPE.)
#include <Eigen/Core>

#include <algorithm>
#include <vector>

namespace dynslam::core {

/// The same on `values` itself, which it reorders: for a buffer reused in a hot loop (doubles,
/// or the floats of a depth image). 0 for no values.
template <class T>
double upperMedianInPlace(std::vector<T>& values) {
  if (values.empty()) return 0.0;
  const auto mid = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
  std::nth_element(values.begin(), mid, values.end());
  return *mid;
}

/// 0 for no values.
inline double upperMedian(std::vector<double> values) { return upperMedianInPlace(values); }

/// The element at position floor(q n) (clamped to the last) of the sorted values: the upper
/// median for q = 0.5, a bench's p90 for q = 0.9. 0 for no values.
inline double upperPercentile(std::vector<double> values, double q) {
  if (values.empty()) return 0.0;
  const auto k = std::min(values.size() - 1, static_cast<size_t>(q * double(values.size())));
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(k), values.end());
  return values[k];
}

/// The upper median of each coordinate of `vectors` (any container of Eigen::Vector3d): robust
/// where one vector in a few is far off. Zero for none.
template <class Vectors>
Eigen::Vector3d componentwiseUpperMedian(const Vectors& vectors) {
  Eigen::Vector3d m;
  std::vector<double> c(vectors.size());
  for (int axis = 0; axis < 3; ++axis) {
    size_t i = 0;
    for (const auto& v : vectors) c[i++] = v(axis);
    m(axis) = upperMedianInPlace(c);
  }
  return m;
}

}  // namespace dynslam::core
