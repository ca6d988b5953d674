#include "dynslam/viz/IdColours.h"

#include <cstdint>

namespace dynslam::viz {

cv::Scalar colourForId(int id) {
  if (id == 0) return {0, 0, 0};
  // Knuth's multiplicative hash spreads consecutive ids over the colour cube.
  const uint32_t h = static_cast<uint32_t>(id) * 2654435761u;
  return {static_cast<double>(64 + (h & 0xBF)), static_cast<double>(64 + ((h >> 8) & 0xBF)),
          static_cast<double>(64 + ((h >> 16) & 0xBF))};
}

}  // namespace dynslam::viz
