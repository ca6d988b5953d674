#pragma once
// Per-frame figures of a run of any length (a stage's time, a solve's time) in bounded memory:
// every sample while there are at most `capacity`, then a uniformly drawn subset of that size
// (reservoir sampling, Vitter's algorithm R, with a fixed seed so a rerun reports the same
// figures). The count, the last and the largest sample stay exact; a median from samples() is
// exact up to `capacity` samples and an unbiased estimate after.
#include <algorithm>
#include <cstddef>
#include <random>
#include <vector>

namespace dynslam::core {

class SampleReservoir {
 public:
  /// 100,000 samples (800 KB): 55 minutes of a 30 Hz camera kept whole.
  static constexpr std::size_t kDefaultCapacity = 100000;

  explicit SampleReservoir(std::size_t capacity = kDefaultCapacity)
      : capacity_(std::max<std::size_t>(capacity, 1)) {}

  void add(double value) {
    ++count_;
    last_ = value;
    max_ = count_ == 1 ? value : std::max(max_, value);
    if (samples_.size() < capacity_) {
      samples_.push_back(value);
      return;
    }
    const std::size_t slot = std::uniform_int_distribution<std::size_t>(0, count_ - 1)(random_);
    if (slot < capacity_) samples_[slot] = value;
  }

  std::size_t count() const { return count_; }  ///< samples added
  bool empty() const { return count_ == 0; }
  double last() const { return last_; }  ///< 0 before the first
  double max() const { return max_; }    ///< 0 before the first
  /// Every sample, or a uniform subset of `capacity` of them once more came (in no order then).
  const std::vector<double>& samples() const { return samples_; }

 private:
  std::size_t capacity_;
  std::size_t count_ = 0;
  double last_ = 0.0, max_ = 0.0;
  std::vector<double> samples_;
  std::mt19937_64 random_{20261129};
};

}  // namespace dynslam::core
