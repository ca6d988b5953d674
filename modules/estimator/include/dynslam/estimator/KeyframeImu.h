#pragma once
// Feeds the frames' IMU samples into the preintegration since the last keyframe, and cuts it at
// each new keyframe's time. The camera and the IMU are not synchronised: a keyframe's time falls
// between two samples, so the last sample is held up to it (zero-order hold over at most one
// IMU period), and the next preintegration starts from that same held sample at the keyframe's
// time. Preintegrations therefore cover exactly the interval between keyframe stamps.
// A gap in the samples longer than max_gap (a dropped IMU stream) breaks the current
// preintegration: integrating across it would pretend to know the motion. The keyframe pair it
// spans then gets no IMU factor (cutAt returns null), and predictions fall back to vision.
// A preintegration longer than max_interval (no keyframe for that long) is broken the same way
// and its samples freed, so its memory is bounded by max_interval times the IMU rate.
#include <dynslam/core/Frame.h>
#include <dynslam/estimator/imu/ImuPreintegration.h>

#include <memory>
#include <optional>

namespace dynslam::estimator {

class KeyframeImu {
 public:
  static constexpr double kMaxGapS = 0.05;
  static constexpr double kMaxIntervalS = 10.0;
  explicit KeyframeImu(const ImuNoise& noise, double max_gap = kMaxGapS,
                       double max_interval = kMaxIntervalS)
      : noise_(noise), max_gap_(max_gap), max_interval_(max_interval) {}

  /// Adds one frame's samples (those with gyro and accelerometer). Throws std::runtime_error
  /// naming the frame and the sample for a non-finite value or a time that does not increase.
  void addSamples(const std::vector<core::ImuSample>& samples, std::size_t frame);

  /// True once a sample has been seen.
  bool hasSamples() const { return last_.has_value(); }
  /// Gaps longer than max_gap seen so far.
  std::size_t gaps() const { return gaps_; }
  /// Preintegrations dropped for spanning more than max_interval.
  std::size_t overlong() const { return overlong_; }

  /// Ends the current preintegration at time t (null if none had started, the first keyframe,
  /// if a gap broke it, or if t lies more than max_gap past the last sample) and starts the
  /// next one there, linearised at the biases (ba, bg).
  std::shared_ptr<ImuPreintegration> cutAt(double t, const Eigen::Vector3d& ba,
                                           const Eigen::Vector3d& bg);

  /// The current preintegration extended to time t (a copy; null before the first keyframe,
  /// when a gap broke it, or when t lies more than max_gap past the last sample: samples are
  /// missing, and holding the last one over the gap predicts a wrong motion).
  std::shared_ptr<ImuPreintegration> peekAt(double t) const;

 private:
  /// More than max_gap past the last sample: the samples are missing (a gap shows only once
  /// they resume), and holding the last one over it gave the frames of an IMU gap a prediction
  /// that pulled their poses away.
  bool missingAt(double t) const { return last_ && t - last_->t > max_gap_; }
  /// The current preintegration, extended to t, would span more than max_interval.
  bool overlongAt(double t) const { return current_ && t - current_start_ > max_interval_; }
  struct Sample {
    double t;
    Eigen::Vector3d acc, gyr;
  };
  ImuNoise noise_;
  double max_gap_, max_interval_;
  bool broken_ = false;  // the current preintegration spans a gap in the samples
  std::size_t gaps_ = 0, overlong_ = 0;
  std::optional<Sample> last_;
  std::shared_ptr<ImuPreintegration> current_;
  double current_start_ = 0;  // the keyframe time current_ starts at
  double current_end_ = 0;    // time of the last sample pushed into current_
};

}  // namespace dynslam::estimator
