#pragma once
// Frames from a rawlog, read, decoded and synchronized (RawlogSource + SensorSync) on a thread
// of their own, a few frames ahead of the consumer: as a camera driver hands frames over while
// the pipeline works on the last one. On the pipeline's thread, un-gzipping the rawlog and
// decoding its PNG images took about 30 % of a run of the whole system (perf, 250 frames of
// indoor_people_high), and in --realtime they made frames late that the stages kept up with.
// The frames and their order are exactly those of RawlogSource + SensorSync on one thread.
#include <dynslam/core/Frame.h>
#include <dynslam/io/SensorSync.h>

#include <atomic>
#include <condition_variable>
#include <deque>
#include <exception>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

namespace dynslam::io {

class RawlogSource;

class FrameReader {
 public:
  /// Opens the rawlog (a missing or unreadable file throws here) and starts reading; at most
  /// `capacity` frames wait for next().
  FrameReader(const std::string& rawlog, const SensorSyncOptions& options, size_t capacity = 8);
  /// Stops the reading thread (it finishes the observation it is reading) and waits for it.
  ~FrameReader();
  FrameReader(const FrameReader&) = delete;
  FrameReader& operator=(const FrameReader&) = delete;

  /// The next frame, waiting for it to be read; std::nullopt at the end of the rawlog. An error
  /// of the reading (truncated or corrupt rawlog, a frame without depth, out-of-order stamps) is
  /// thrown here, once every frame read before it has been handed out.
  std::optional<core::Frame> next();

  /// Fraction of the rawlog read so far, in [0, 1] (ahead of the frames handed out).
  double progress() const { return progress_.load(); }
  /// The synchronizer's counts and GNSS origin as they were when the last frame handed out was
  /// made (after the end: over the whole rawlog), as a single-threaded loop that stopped there
  /// would report them; the reading ahead does not show.
  SyncCounts counts() const;
  std::optional<Eigen::Vector3d> gnssOrigin() const;

 private:
  void read();
  void publish(std::vector<core::Frame>& ready);

  std::unique_ptr<RawlogSource> source_;
  SensorSync sync_;  // the reading thread's only
  const size_t capacity_;

  struct ReadSoFar {
    SyncCounts counts;
    std::optional<Eigen::Vector3d> origin;
  };
  struct Queued {
    core::Frame frame;
    ReadSoFar read;  ///< when the frame was made
  };

  mutable std::mutex mutex_;
  std::condition_variable changed_;
  std::deque<Queued> queue_;
  ReadSoFar handed_out_;  ///< as of the last frame next() returned
  ReadSoFar final_;       ///< over the whole rawlog, once ended_
  std::exception_ptr error_;
  bool ended_ = false;
  bool stopping_ = false;
  std::atomic<double> progress_{0.0};
  std::thread thread_;
};

}  // namespace dynslam::io
