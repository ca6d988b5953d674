#include "dynslam/io/TrajectoryWriter.h"

#include <dynslam/core/TrajectoryFile.h>

#include <stdexcept>

namespace dynslam::io {

TumTrajectoryWriter::TumTrajectoryWriter(const std::string& path) : path_(path), out_(path) {
  if (!out_) throw std::runtime_error("cannot write trajectory '" + path + "'");
}

void TumTrajectoryWriter::append(const core::StampedPose& pose) {
  core::appendTumLine(out_, pose);
  out_.flush();
  if (!out_) throw std::runtime_error("write to trajectory '" + path_ + "' failed");
  ++count_;
}

}  // namespace dynslam::io
