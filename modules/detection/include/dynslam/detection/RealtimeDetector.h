#pragma once
// Runs a detector in a thread of its own at whatever rate it manages, as the paper's detection
// thread does. The pipeline never waits for it: each frame is left in a one-frame mailbox
// (replacing a frame still waiting there), and the detector, whenever it is free, takes the
// newest frame at once, so it runs back to back when it is slower than the camera instead of
// idling until the next frame arrives. Each frame picks up the newest result finished since the
// previous one; results therefore come in frame order, each at most once.
#include <dynslam/detection/Detector.h>

#include <condition_variable>
#include <cstddef>
#include <exception>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>

namespace dynslam::detection {

class RealtimeDetector {
 public:
  /// The detections of one frame and which frame they came from.
  struct Result {
    std::size_t frame_index = 0;
    double t = 0;
    std::vector<core::Detection> detections;
    double seconds = 0;  ///< how long detect() took
  };

  explicit RealtimeDetector(std::unique_ptr<Detector> detector);
  ~RealtimeDetector();  ///< stops the thread (waits for a detection under way)
  RealtimeDetector(const RealtimeDetector&) = delete;
  RealtimeDetector& operator=(const RealtimeDetector&) = delete;

  /// Leaves `frame` for the detector (its colour image copied, so the caller may change the
  /// frame afterwards) and returns at once. True when the detector was idle and takes it now;
  /// false when it is busy and the frame waits for it, replacing an older waiting frame.
  bool submit(const core::Frame& frame);

  /// The newest result finished and not yet taken, if any (an older one not taken by then is
  /// dropped). Rethrows, once, an exception the detector threw.
  std::optional<Result> poll();

  /// Waits until the detector is idle with no frame waiting (a final result; tests).
  void waitIdle();

  std::size_t completed() const;  ///< detections finished so far
  std::size_t dropped() const;    ///< results replaced by a newer one before poll() took them

 private:
  void run();

  std::unique_ptr<Detector> detector_;
  mutable std::mutex mutex_;
  std::condition_variable wake_;
  std::optional<core::Frame> waiting_;  // the mailbox
  bool busy_ = false;
  std::optional<Result> done_;  // the newest finished result not yet taken
  std::exception_ptr error_;
  std::size_t completed_ = 0, dropped_ = 0;
  bool stop_ = false;
  std::thread thread_;  // last: starts after everything it uses exists
};

}  // namespace dynslam::detection
