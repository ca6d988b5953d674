#include "dynslam/detection/RealtimeDetector.h"

#include <chrono>

namespace dynslam::detection {

RealtimeDetector::RealtimeDetector(std::unique_ptr<Detector> detector)
    : detector_(std::move(detector)), thread_([this] { run(); }) {}

RealtimeDetector::~RealtimeDetector() {
  {
    std::lock_guard lock(mutex_);
    stop_ = true;
  }
  wake_.notify_all();
  thread_.join();
}

bool RealtimeDetector::submit(const core::Frame& frame) {
  // Only what detectors read: the image (copied: later stages may draw on it), the stamp, the
  // index and the intrinsics. Depth, IMU and perception results stay behind. Copied before
  // locking, so the detector thread is never held up by the copy.
  core::Frame copy;
  copy.index = frame.index;
  copy.t = frame.t;
  copy.sensor_label = frame.sensor_label;
  copy.rgb = frame.rgb.clone();
  copy.intrinsics = frame.intrinsics;
  std::lock_guard lock(mutex_);
  const bool idle = !busy_ && !waiting_;
  waiting_ = std::move(copy);
  wake_.notify_all();
  return idle;
}

std::optional<RealtimeDetector::Result> RealtimeDetector::poll() {
  std::lock_guard lock(mutex_);
  if (error_) {
    std::exception_ptr e = error_;
    error_ = nullptr;
    std::rethrow_exception(e);
  }
  std::optional<Result> result = std::move(done_);
  done_.reset();
  return result;
}

void RealtimeDetector::waitIdle() {
  std::unique_lock lock(mutex_);
  wake_.wait(lock, [this] { return !busy_ && !waiting_; });
}

std::size_t RealtimeDetector::completed() const {
  std::lock_guard lock(mutex_);
  return completed_;
}

std::size_t RealtimeDetector::dropped() const {
  std::lock_guard lock(mutex_);
  return dropped_;
}

void RealtimeDetector::run() {
  std::unique_lock lock(mutex_);
  for (;;) {
    wake_.wait(lock, [this] { return stop_ || waiting_; });
    if (stop_) return;
    const core::Frame frame = std::move(*waiting_);
    waiting_.reset();
    busy_ = true;
    lock.unlock();
    Result result;
    result.frame_index = frame.index;
    result.t = frame.t;
    std::exception_ptr error;
    const auto start = std::chrono::steady_clock::now();
    try {
      result.detections = detector_->detect(frame);
    } catch (...) {
      error = std::current_exception();
    }
    result.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    lock.lock();
    busy_ = false;
    ++completed_;
    if (error) {
      error_ = error;
    } else {
      if (done_) ++dropped_;
      done_ = std::move(result);
    }
    wake_.notify_all();
  }
}

}  // namespace dynslam::detection
