#pragma once
// Halving a sequence that has grown to its limit (a map's trajectory line, the GNSS pairs waiting
// for an alignment) while its extent stays whole.
#include <cstddef>
#include <vector>

namespace dynslam::core {

/// Keeps the elements at even positions and the last one, in order.
template <class T>
void keepEverySecond(std::vector<T>& values) {
  if (values.empty()) return;
  std::size_t kept = 0;
  for (std::size_t i = 0; i + 1 < values.size(); i += 2) values[kept++] = values[i];
  values[kept++] = values.back();
  values.resize(kept);
}

}  // namespace dynslam::core
