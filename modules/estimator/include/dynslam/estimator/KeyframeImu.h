#pragma once
// Feeds the frames' IMU samples into the preintegration since the last keyframe, and cuts it at
// each new keyframe's time. The camera and the IMU are not synchronised: a keyframe's time falls
// between two samples, so the last sample is held up to it (zero-order hold over at most one
// IMU period), and the next preintegration starts from that same held sample at the keyframe's
// time. Preintegrations therefore cover exactly the interval between keyframe stamps.
#include <dynslam/core/Frame.h>
#include <dynslam/estimator/imu/ImuPreintegration.h>

#include <memory>
#include <optional>

namespace dynslam::estimator {

class KeyframeImu {
 public:
  explicit KeyframeImu(const ImuNoise& noise) : noise_(noise) {}

  /// Adds one frame's samples (those with gyro and accelerometer). Throws std::runtime_error
  /// naming the frame and the sample for a non-finite value or a time that does not increase.
  void addSamples(const std::vector<core::ImuSample>& samples, std::size_t frame);

  /// True once a sample has been seen.
  bool hasSamples() const { return last_.has_value(); }

  /// Ends the current preintegration at time t (null if none had started: the first keyframe)
  /// and starts the next one there, linearised at the biases (ba, bg).
  std::shared_ptr<ImuPreintegration> cutAt(double t, const Eigen::Vector3d& ba,
                                           const Eigen::Vector3d& bg);

  /// The current preintegration extended to time t (a copy; null before the first keyframe).
  std::shared_ptr<ImuPreintegration> peekAt(double t) const;

 private:
  struct Sample {
    double t;
    Eigen::Vector3d acc, gyr;
  };
  ImuNoise noise_;
  std::optional<Sample> last_;
  std::shared_ptr<ImuPreintegration> current_;
  double current_end_ = 0;  // time of the last sample pushed into current_
};

}  // namespace dynslam::estimator
