#pragma once
// Writes a TUM trajectory pose by pose, flushing each line, so a run that stops part-way
// (bad input, Ctrl-C, a crash in a later stage) leaves every pose it estimated on disk.
#include <dynslam/core/Trajectory.h>

#include <fstream>
#include <string>

namespace dynslam::io {

class TumTrajectoryWriter {
 public:
  /// Creates (truncates) `path`; throws std::runtime_error naming it when that fails.
  explicit TumTrajectoryWriter(const std::string& path);

  void append(const core::StampedPose& pose);
  size_t count() const { return count_; }
  const std::string& path() const { return path_; }

 private:
  std::string path_;
  std::ofstream out_;
  size_t count_ = 0;
};

}  // namespace dynslam::io
