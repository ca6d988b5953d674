#include "dynslam/evaluation/Statistics.h"

#include "dynslam/evaluation/EvaluationError.h"

#include <algorithm>
#include <cmath>

namespace dynslam::evaluation {

double pairwiseSum(const double* values, std::size_t count) {
  constexpr std::size_t kBlock = 128;  // numpy's PW_BLOCKSIZE
  if (count < 8) {
    double sum = 0.0;
    for (std::size_t i = 0; i < count; ++i) sum += values[i];
    return sum;
  }
  if (count <= kBlock) {
    double r[8];
    for (std::size_t j = 0; j < 8; ++j) r[j] = values[j];
    std::size_t i = 8;
    for (; i < count - (count % 8); i += 8)
      for (std::size_t j = 0; j < 8; ++j) r[j] += values[i + j];
    double sum = ((r[0] + r[1]) + (r[2] + r[3])) + ((r[4] + r[5]) + (r[6] + r[7]));
    for (; i < count; ++i) sum += values[i];
    return sum;
  }
  std::size_t half = count / 2;
  half -= half % 8;
  return pairwiseSum(values, half) + pairwiseSum(values + half, count - half);
}

namespace {
double meanOf(const std::vector<double>& v) {
  return pairwiseSum(v.data(), v.size()) / static_cast<double>(v.size());
}

double medianOf(std::vector<double> v) {
  const std::size_t n = v.size();
  const std::size_t upper = n / 2;
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(upper), v.end());
  const double upper_value = v[upper];
  if (n % 2 == 1) return upper_value;
  const double lower_value =
      *std::max_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(upper));
  return (lower_value + upper_value) / 2.0;
}
}  // namespace

ErrorStatistics computeStatistics(const std::vector<double>& errors) {
  if (errors.empty()) throw EvaluationError("no errors to summarise (empty error array)");
  const double n = static_cast<double>(errors.size());

  std::vector<double> squares(errors.size());
  for (std::size_t i = 0; i < errors.size(); ++i) squares[i] = errors[i] * errors[i];

  ErrorStatistics s;
  s.sse = pairwiseSum(squares.data(), squares.size());
  s.rmse = std::sqrt(s.sse / n);
  s.mean = meanOf(errors);
  s.median = medianOf(errors);

  // numpy's var: mean of the squared deviations from the mean.
  std::vector<double> deviations(errors.size());
  for (std::size_t i = 0; i < errors.size(); ++i) {
    const double d = errors[i] - s.mean;
    deviations[i] = d * d;
  }
  s.std = std::sqrt(meanOf(deviations));

  const auto [lo, hi] = std::minmax_element(errors.begin(), errors.end());
  s.min = *lo;
  s.max = *hi;
  return s;
}

}  // namespace dynslam::evaluation
