#pragma once
// The two stream joins bag2rawlog makes while reading a bag once, front to back, holding only
// the messages whose partner may still come:
//   RgbdPairer: each colour image takes the nearest unused depth image within maxDt.
//   ImuCombiner: RealSense publishes accelerometer and gyro as separate topics at different
//     rates; one IMU sample is made per gyro sample, with the accelerometer linearly
//     interpolated at the gyro's stamp (gyro drives the integration and is the faster stream).
#include "BagMessages.h"

#include <deque>
#include <optional>
#include <utility>
#include <vector>

namespace dynslam::rawlog_tools::bag {

class RgbdPairer {
 public:
  explicit RgbdPairer(Nanoseconds maxDt) : maxDt_(maxDt) {}
  void addColour(ColourMessage colour) { colour_.push_back(std::move(colour)); }
  void addDepth(DepthMessage depth);

  /// Pairs decided so far, in colour order. A colour image is decided once a depth image
  /// later than its stamp + maxDt arrived, once `now` (the newest stamp of any stream) is past
  /// its stamp + giveUpAfter (a depth stream that stopped must not hold every image in
  /// memory), or at the end of the input.
  std::vector<std::pair<ColourMessage, DepthMessage>> takeReady(Nanoseconds now,
                                                                Nanoseconds giveUpAfter,
                                                                bool endOfInput);
  /// Stamp of the oldest undecided colour image: nothing older may be written yet.
  std::optional<Nanoseconds> oldestPending() const;

  size_t unmatchedColour() const { return unmatchedColour_; }
  size_t unmatchedDepth() const { return unmatchedDepth_; }

 private:
  Nanoseconds maxDt_;
  std::deque<ColourMessage> colour_;
  std::deque<DepthMessage> depth_;
  std::optional<Nanoseconds> newestDepth_;
  size_t unmatchedColour_ = 0, unmatchedDepth_ = 0;
};

struct ImuSample {
  Nanoseconds stamp = 0;
  std::array<double, 3> gyro{}, acc{};
};

class ImuCombiner {
 public:
  /// A sample whose stamp does not increase within its stream is dropped (counted).
  void addAccel(const Vector3Sample& accel);
  void addGyro(const Vector3Sample& gyro);

  /// Samples whose accelerometer bracket is complete. At the end of the input, gyro samples
  /// after the last accelerometer sample are dropped; so are those before the first.
  std::vector<ImuSample> takeReady(bool endOfInput);
  std::optional<Nanoseconds> oldestPending() const;

  size_t droppedGyro() const { return droppedGyro_; }
  size_t outOfOrder() const { return outOfOrder_; }

 private:
  std::deque<Vector3Sample> accel_, gyro_;
  std::optional<Nanoseconds> lastAccel_, lastGyro_;
  size_t droppedGyro_ = 0, outOfOrder_ = 0;
};

}  // namespace dynslam::rawlog_tools::bag
