#include "dynslam/io/FrameReader.h"

#include "dynslam/io/RawlogSource.h"

#include <algorithm>

namespace dynslam::io {

FrameReader::FrameReader(const std::string& rawlog, const SensorSyncOptions& options,
                         size_t capacity)
    : source_(std::make_unique<RawlogSource>(rawlog)),
      sync_(options),
      capacity_(std::max<size_t>(1, capacity)) {
  thread_ = std::thread([this] { read(); });
}

FrameReader::~FrameReader() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
  }
  changed_.notify_all();
  thread_.join();
}

void FrameReader::read() {
  std::vector<core::Frame> ready;
  try {
    for (bool more = true; more;) {
      {
        std::lock_guard<std::mutex> lock(mutex_);
        if (stopping_) break;
      }
      const auto obs = source_->next();
      if (obs) {
        sync_.push(obs, ready);
      } else {
        sync_.flush(ready);
        more = false;
      }
      progress_ = source_->progress();
      publish(ready);
    }
  } catch (...) {
    std::lock_guard<std::mutex> lock(mutex_);
    error_ = std::current_exception();
  }
  {
    std::lock_guard<std::mutex> lock(mutex_);
    final_ = {sync_.counts(), sync_.gnssOrigin()};
    ended_ = true;
  }
  changed_.notify_all();
}

void FrameReader::publish(std::vector<core::Frame>& ready) {
  if (ready.empty()) return;
  const ReadSoFar read{sync_.counts(), sync_.gnssOrigin()};
  std::unique_lock<std::mutex> lock(mutex_);
  for (auto& frame : ready) {
    changed_.wait(lock, [&] { return queue_.size() < capacity_ || stopping_; });
    if (stopping_) break;
    queue_.push_back({std::move(frame), read});
    changed_.notify_all();
  }
  ready.clear();
}

std::optional<core::Frame> FrameReader::next() {
  std::unique_lock<std::mutex> lock(mutex_);
  changed_.wait(lock, [&] { return !queue_.empty() || ended_; });
  if (!queue_.empty()) {
    core::Frame frame = std::move(queue_.front().frame);
    handed_out_ = std::move(queue_.front().read);
    queue_.pop_front();
    changed_.notify_all();
    return frame;
  }
  handed_out_ = final_;
  if (error_) std::rethrow_exception(error_);
  return std::nullopt;
}

SyncCounts FrameReader::counts() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return handed_out_.counts;
}

std::optional<Eigen::Vector3d> FrameReader::gnssOrigin() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return handed_out_.origin;
}

}  // namespace dynslam::io
