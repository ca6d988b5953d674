#include "TimeOrderedWriter.h"

#include <dynslam/rawlog_tools/RawlogWriter.h>
#include <mrpt/obs/CObservation.h>

namespace dynslam::rawlog_tools::bag {

void TimeOrderedWriter::add(Nanoseconds stamp,
                            std::shared_ptr<mrpt::obs::CObservation> observation) {
  if (wroteAny_ && stamp < lastWritten_) {
    ++late_;
    return;
  }
  held_.emplace(stamp, std::move(observation));  // equal stamps keep their arrival order
}

void TimeOrderedWriter::flushBefore(Nanoseconds horizon) {
  auto it = held_.begin();
  for (; it != held_.end() && it->first < horizon; ++it) {
    writer_.write(*it->second);
    lastWritten_ = it->first;
    wroteAny_ = true;
  }
  held_.erase(held_.begin(), it);
}

void TimeOrderedWriter::flushAll() {
  for (const auto& [stamp, observation] : held_) {
    writer_.write(*observation);
    lastWritten_ = stamp;
    wroteAny_ = true;
  }
  held_.clear();
}

}  // namespace dynslam::rawlog_tools::bag
