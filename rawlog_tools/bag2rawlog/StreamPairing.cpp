#include "StreamPairing.h"

#include <cstdlib>

namespace dynslam::rawlog_tools::bag {

void RgbdPairer::addDepth(DepthMessage depth) {
  if (!newestDepth_ || depth.stamp > *newestDepth_) newestDepth_ = depth.stamp;
  depth_.push_back(std::move(depth));
}

std::vector<std::pair<ColourMessage, DepthMessage>> RgbdPairer::takeReady(Nanoseconds now,
                                                                          Nanoseconds giveUpAfter,
                                                                          bool endOfInput) {
  std::vector<std::pair<ColourMessage, DepthMessage>> ready;
  while (!colour_.empty()) {
    const Nanoseconds t = colour_.front().stamp;
    const bool depthPassed = newestDepth_ && *newestDepth_ > t + maxDt_;
    if (!endOfInput && !depthPassed && now <= t + giveUpAfter) break;
    // Depth images too old for this colour image are too old for every later one.
    while (!depth_.empty() && depth_.front().stamp < t - maxDt_) {
      depth_.pop_front();
      ++unmatchedDepth_;
    }
    auto best = depth_.end();
    for (auto it = depth_.begin(); it != depth_.end(); ++it)
      if (std::llabs(it->stamp - t) <= maxDt_ &&
          (best == depth_.end() || std::llabs(it->stamp - t) < std::llabs(best->stamp - t)))
        best = it;
    if (best == depth_.end()) {
      ++unmatchedColour_;
    } else {
      ready.emplace_back(std::move(colour_.front()), std::move(*best));
      depth_.erase(best);
    }
    colour_.pop_front();
  }
  if (endOfInput) {
    unmatchedDepth_ += depth_.size();
    depth_.clear();
  }
  return ready;
}

std::optional<Nanoseconds> RgbdPairer::oldestPending() const {
  if (colour_.empty()) return std::nullopt;
  return colour_.front().stamp;
}

void ImuCombiner::addAccel(const Vector3Sample& accel) {
  if (lastAccel_ && accel.stamp <= *lastAccel_) {
    ++outOfOrder_;
    return;
  }
  lastAccel_ = accel.stamp;
  accel_.push_back(accel);
}

void ImuCombiner::addGyro(const Vector3Sample& gyro) {
  if (lastGyro_ && gyro.stamp <= *lastGyro_) {
    ++outOfOrder_;
    return;
  }
  lastGyro_ = gyro.stamp;
  gyro_.push_back(gyro);
}

std::vector<ImuSample> ImuCombiner::takeReady(bool endOfInput) {
  std::vector<ImuSample> ready;
  while (!gyro_.empty()) {
    const Vector3Sample& g = gyro_.front();
    // Keep exactly one accelerometer sample at or before the gyro stamp at the front.
    while (accel_.size() >= 2 && accel_[1].stamp <= g.stamp) accel_.pop_front();
    if (accel_.empty() || (accel_.size() == 1 && accel_[0].stamp < g.stamp)) {
      if (!endOfInput) break;  // the next accelerometer sample may still come
      ++droppedGyro_;
      gyro_.pop_front();
      continue;
    }
    if (accel_[0].stamp > g.stamp) {  // before the first accelerometer sample
      ++droppedGyro_;
      gyro_.pop_front();
      continue;
    }
    ImuSample s;
    s.stamp = g.stamp;
    s.gyro = g.v;
    if (accel_[0].stamp == g.stamp) {
      s.acc = accel_[0].v;
    } else {
      const Vector3Sample &a0 = accel_[0], &a1 = accel_[1];
      const double w =
          static_cast<double>(g.stamp - a0.stamp) / static_cast<double>(a1.stamp - a0.stamp);
      for (size_t i = 0; i < 3; ++i) s.acc[i] = (1.0 - w) * a0.v[i] + w * a1.v[i];
    }
    ready.push_back(s);
    gyro_.pop_front();
  }
  return ready;
}

std::optional<Nanoseconds> ImuCombiner::oldestPending() const {
  if (gyro_.empty()) return std::nullopt;
  return gyro_.front().stamp;
}

}  // namespace dynslam::rawlog_tools::bag
