#include "dynslam/estimator/KeyframeImu.h"

#include <stdexcept>
#include <string>

namespace dynslam::estimator {

void KeyframeImu::addSamples(const std::vector<core::ImuSample>& samples, std::size_t frame) {
  for (const auto& s : samples) {
    if (!s.has_gyro || !s.has_acc) continue;
    if (!s.gyro.allFinite() || !s.acc.allFinite() || !std::isfinite(s.t))
      throw std::runtime_error("IMU sample at t = " + std::to_string(s.t) + " before frame " +
                               std::to_string(frame) + " is not finite (gyro or acc NaN/inf)");
    if (last_ && !(s.t > last_->t))
      throw std::runtime_error("IMU sample at t = " + std::to_string(s.t) + " before frame " +
                               std::to_string(frame) + " does not come after the previous one (" +
                               std::to_string(last_->t) + ")");
    if (last_ && s.t - last_->t > max_gap_) {
      broken_ = true;
      ++gaps_;
    }
    if (!broken_ && overlongAt(s.t)) {
      broken_ = true;
      ++overlong_;
      current_.reset();  // its samples go with it
    }
    if (current_ && !broken_) current_->push(s.t - current_end_, s.acc, s.gyro);
    current_end_ = s.t;
    last_ = Sample{s.t, s.acc, s.gyro};
  }
}

std::shared_ptr<ImuPreintegration> KeyframeImu::cutAt(double t, const Eigen::Vector3d& ba,
                                                      const Eigen::Vector3d& bg) {
  if (!last_) return nullptr;
  // Samples up to the limit, the keyframe past it: dropped and counted as in addSamples.
  if (!broken_ && overlongAt(t)) ++overlong_;
  // Samples missing at t: nothing to close the interval with.
  std::shared_ptr<ImuPreintegration> done =
      broken_ || missingAt(t) || overlongAt(t) ? nullptr : current_;
  if (done && t > current_end_) done->push(t - current_end_, last_->acc, last_->gyr);
  broken_ = false;
  current_ = std::make_shared<ImuPreintegration>(last_->acc, last_->gyr, ba, bg, noise_);
  current_start_ = current_end_ = t;
  return done;
}

std::shared_ptr<ImuPreintegration> KeyframeImu::peekAt(double t) const {
  if (!current_ || broken_ || missingAt(t)) return nullptr;
  auto copy = std::make_shared<ImuPreintegration>(*current_);
  if (t > current_end_) copy->push(t - current_end_, last_->acc, last_->gyr);
  return copy;
}

}  // namespace dynslam::estimator
