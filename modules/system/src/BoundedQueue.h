#pragma once
// The hand-over between System's threads: onNewObservation() (any thread) -> the synchronizing
// thread -> the pipeline thread. push blocks while the queue is full; close() lets the consumer
// drain it, stop() drops what waits; a failure of either thread ends both queues and is thrown
// by the next push (or, when no push came after it, by flush() or stop()).
#include <condition_variable>
#include <cstddef>
#include <deque>
#include <exception>
#include <mutex>
#include <optional>

namespace dynslam::system {

template <class T>
class BoundedQueue {
 public:
  explicit BoundedQueue(std::size_t capacity) : capacity_(capacity ? capacity : 1) {}

  /// Waits for room; throws the processing's error instead once it failed. Dropped after
  /// close() or stop().
  void push(T item) {
    std::unique_lock<std::mutex> lock(mutex_);
    changed_.wait(lock, [&] { return items_.size() < capacity_ || error_ || stopped_; });
    if (error_) {
      reported_ = true;
      std::rethrow_exception(error_);
    }
    if (stopped_ || closed_) return;
    items_.push_back(std::move(item));
    changed_.notify_all();
  }

  /// The next item; nothing once the queue is closed and drained, stopped, or failed.
  std::optional<T> pop() {
    std::unique_lock<std::mutex> lock(mutex_);
    changed_.wait(lock, [&] { return !items_.empty() || closed_ || stopped_ || error_; });
    if (stopped_ || error_ || items_.empty()) return std::nullopt;
    T item = std::move(items_.front());
    items_.pop_front();
    changed_.notify_all();
    return item;
  }

  void close() {
    set([&] { closed_ = true; });
  }
  void stop() {
    set([&] {
      stopped_ = true;
      items_.clear();
    });
  }
  void fail(std::exception_ptr error) {
    set([&] {
      if (!error_) error_ = error;
    });
  }

  /// The error unless a push threw it already (then it is told once).
  std::exception_ptr unreportedError() {
    std::lock_guard<std::mutex> lock(mutex_);
    if (reported_) return nullptr;
    reported_ = true;
    return error_;
  }
  bool failed() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return error_ != nullptr;
  }
  bool stopped() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return stopped_;
  }

 private:
  template <class F>
  void set(F&& change) {
    std::lock_guard<std::mutex> lock(mutex_);
    change();
    changed_.notify_all();
  }

  const std::size_t capacity_;
  mutable std::mutex mutex_;
  std::condition_variable changed_;
  std::deque<T> items_;
  bool closed_ = false, stopped_ = false, reported_ = false;
  std::exception_ptr error_;
};

}  // namespace dynslam::system
