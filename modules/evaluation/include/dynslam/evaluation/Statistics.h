#pragma once
// Summary statistics of an error array, defined as evo's PE.get_statistic computes them with
// numpy (population std, median averaging the two middle values, numpy's pairwise summation).
#include <cstddef>
#include <vector>

namespace dynslam::evaluation {

struct ErrorStatistics {
  double rmse = 0.0;  ///< sqrt(mean(e^2))
  double mean = 0.0;
  double median = 0.0;
  double std = 0.0;  ///< population standard deviation (numpy's default, ddof = 0)
  double min = 0.0;
  double max = 0.0;
  double sse = 0.0;  ///< sum of e^2
};

/// Throws EvaluationError on an empty array.
ErrorStatistics computeStatistics(const std::vector<double>& errors);

/// Sum in numpy's pairwise order (blocks of 128 summed with 8 accumulators, halves recursively),
/// so that sums of thousands of errors round like evo's.
double pairwiseSum(const double* values, std::size_t count);

}  // namespace dynslam::evaluation
