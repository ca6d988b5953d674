#include "dynslam/sim/RealRgbdStream.h"

#include <dynslam/io/ObservationConversion.h>
#include <dynslam/io/RawlogSource.h>

#include <mrpt/core/Clock.h>
#include <mrpt/obs/CObservation3DRangeScan.h>

#include <stdexcept>

namespace dynslam::sim {

struct RealRgbdStream::Reader {
  explicit Reader(const std::string& path) : source(path) {}
  io::RawlogSource source;
};

RealRgbdStream::RealRgbdStream(std::string rawlog_path) : path_(std::move(rawlog_path)) {
  reopen();
}

RealRgbdStream::~RealRgbdStream() = default;

void RealRgbdStream::reopen() {
  reader_.reset();  // one open stream at a time (the external images folder is global in MRPT)
  reader_ = std::make_unique<Reader>(path_);
  next_number_ = 0;
  have_current_ = false;
}

const core::Frame& RealRgbdStream::frame(std::size_t number) {
  if (have_current_ && number + 1 == next_number_) return current_;
  if (number < next_number_) reopen();
  while (true) {
    const auto obs = reader_->source.next();
    if (!obs)
      throw std::out_of_range("rawlog '" + path_ + "' holds " + std::to_string(next_number_) +
                              " RGB-D observations; frame " + std::to_string(number) +
                              " was asked for");
    const auto* rgbd = dynamic_cast<const mrpt::obs::CObservation3DRangeScan*>(obs.get());
    if (rgbd == nullptr) continue;
    if (next_number_++ < number) continue;  // skipped: its images are never decoded
    current_ = core::Frame{};
    current_.index = number;
    io::fillFrameFromRgbd(*rgbd, current_);
    have_current_ = true;
    return current_;
  }
}

std::vector<double> RealRgbdStream::rgbdStamps(const std::string& rawlog_path) {
  io::RawlogSource source(rawlog_path);
  std::vector<double> stamps;
  while (const auto obs = source.next())
    if (dynamic_cast<const mrpt::obs::CObservation3DRangeScan*>(obs.get()) != nullptr)
      stamps.push_back(mrpt::Clock::toDouble(obs->timestamp));
  return stamps;
}

}  // namespace dynslam::sim
