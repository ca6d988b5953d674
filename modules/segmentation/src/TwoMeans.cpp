#include "dynslam/segmentation/TwoMeans.h"

#include <algorithm>

namespace dynslam::segmentation {

TwoMeansResult twoMeans(std::vector<float>& values) {
  TwoMeansResult r;
  const int n = static_cast<int>(values.size());
  if (n == 0) return r;
  std::sort(values.begin(), values.end());
  double total = 0;
  for (float v : values) total += v;
  r.far_mean = total / n;
  r.far_count = n;
  if (n < 2 || values.front() == values.back()) return r;

  // Within-cluster sum of squares = sum v^2 - S_near^2 / k - S_far^2 / (n - k); the first term
  // is fixed, so the best split maximises S_near^2 / k + S_far^2 / (n - k). Splits between two
  // equal values are skipped: they would put one depth in both clusters.
  double prefix = 0, best = -1;
  int bestK = 0;
  double bestNear = 0;
  for (int k = 1; k < n; ++k) {
    prefix += values[k - 1];
    if (values[k - 1] == values[k]) continue;
    const double rest = total - prefix;
    const double score = prefix * prefix / k + rest * rest / (n - k);
    if (score > best) {
      best = score;
      bestK = k;
      bestNear = prefix;
    }
  }
  r.two_clusters = true;
  r.near_count = bestK;
  r.far_count = n - bestK;
  r.near_mean = bestNear / bestK;
  r.far_mean = (total - bestNear) / (n - bestK);
  return r;
}

}  // namespace dynslam::segmentation
