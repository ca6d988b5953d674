#pragma once
// Bags are ordered by the time a message was recorded, not by its header stamp; images arrive
// tens of milliseconds after an IMU sample with the same stamp. This buffer holds observations
// for a window and writes them to the rawlog in stamp order, so the rawlog is sorted while the
// bag is still read once, streaming.
#include "BagMessages.h"

#include <map>
#include <memory>

namespace mrpt::obs {
class CObservation;
}

namespace dynslam::rawlog_tools {
class RawlogWriter;
}

namespace dynslam::rawlog_tools::bag {

class TimeOrderedWriter {
 public:
  explicit TimeOrderedWriter(RawlogWriter& writer) : writer_(writer) {}

  /// An observation older than one already written cannot be placed any more: it is dropped
  /// and counted (late()); a larger reorder window avoids that.
  void add(Nanoseconds stamp, std::shared_ptr<mrpt::obs::CObservation> observation);
  /// Writes every held observation stamped before `horizon`, oldest first.
  void flushBefore(Nanoseconds horizon);
  void flushAll();

  size_t late() const { return late_; }
  size_t held() const { return held_.size(); }

 private:
  RawlogWriter& writer_;
  std::multimap<Nanoseconds, std::shared_ptr<mrpt::obs::CObservation>> held_;
  Nanoseconds lastWritten_ = 0;
  bool wroteAny_ = false;
  size_t late_ = 0;
};

}  // namespace dynslam::rawlog_tools::bag
