#include "dynslam/segmentation/DepthThresholdSegmenter.h"

#include <opencv2/core.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace dynslam::segmentation {

void resolveByClosestDepth(std::vector<core::ObjectMask>& masks, const cv::Mat& depth) {
  for (size_t a = 0; a < masks.size(); ++a)
    for (size_t b = a + 1; b < masks.size(); ++b) {
      core::ObjectMask &A = masks[a], &B = masks[b];
      if (!A.valid || !B.valid || A.mask.empty() || B.mask.empty()) continue;
      const cv::Rect overlap = A.roi & B.roi;
      for (int y = overlap.y; y < overlap.y + overlap.height; ++y) {
        uint8_t* rowA = A.mask.ptr<uint8_t>(y - A.roi.y) - A.roi.x;
        uint8_t* rowB = B.mask.ptr<uint8_t>(y - B.roi.y) - B.roi.x;
        const float* z = depth.ptr<float>(y);
        for (int x = overlap.x; x < overlap.x + overlap.width; ++x) {
          if (!rowA[x] || !rowB[x]) continue;
          const double da = std::abs(z[x] - A.d_t), db = std::abs(z[x] - B.d_t);
          const bool toA = da < db || (da == db && A.d_t <= B.d_t);
          (toA ? rowB : rowA)[x] = 0;
        }
      }
    }
}

void resolveMutualOcclusion(std::vector<core::ObjectMask>& masks) {
  std::vector<size_t> order;
  for (size_t i = 0; i < masks.size(); ++i)
    if (masks[i].valid && !masks[i].mask.empty()) order.push_back(i);
  std::stable_sort(order.begin(), order.end(),
                   [&](size_t a, size_t b) { return masks[a].d_t < masks[b].d_t; });
  // Nearest first: each mask gives up the pixels that a nearer mask already holds. A pixel in
  // the range of several objects thus ends in the nearest one; a pixel in one range only
  // stays where it is.
  for (size_t k = 1; k < order.size(); ++k) {
    auto& far = masks[order[k]];
    for (size_t j = 0; j < k; ++j) {
      const auto& near = masks[order[j]];
      const cv::Rect overlap = far.roi & near.roi;
      if (overlap.empty()) continue;
      far.mask(overlap - far.roi.tl()).setTo(0, near.mask(overlap - near.roi.tl()));
    }
  }
}

}  // namespace dynslam::segmentation
