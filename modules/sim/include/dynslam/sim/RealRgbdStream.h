#pragma once
// The RGB-D frames of a real rawlog, one at a time: what the Augmenter composites its rendered
// movers into. Streams the file (a 600-frame sequence is over 1 GB as float depth, so frames
// are never all held); asking for a frame before the current one re-opens the file and reads
// forward again, so any order works and increasing order costs one pass.
#include <dynslam/core/Frame.h>

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

namespace dynslam::sim {

class RealRgbdStream {
 public:
  /// Throws io::RawlogError naming the path when the file is missing or not a rawlog.
  explicit RealRgbdStream(std::string rawlog_path);
  ~RealRgbdStream();
  RealRgbdStream(const RealRgbdStream&) = delete;
  RealRgbdStream& operator=(const RealRgbdStream&) = delete;

  /// The `number`-th RGB-D observation of the file (0-based, file order; other observation
  /// types are skipped) as a Frame: rgb, depth in metres registered to rgb, intrinsics, t.
  /// The reference stays valid until the next call. Throws std::out_of_range naming the file
  /// when it holds fewer RGB-D observations.
  const core::Frame& frame(std::size_t number);

  /// Stamps (s) of every RGB-D observation, in file order: one pass that decodes no images.
  static std::vector<double> rgbdStamps(const std::string& rawlog_path);

  const std::string& path() const { return path_; }

 private:
  void reopen();

  struct Reader;
  std::string path_;
  std::unique_ptr<Reader> reader_;
  core::Frame current_;
  std::size_t next_number_ = 0;  // RGB-D observations consumed from the open file
  bool have_current_ = false;
};

}  // namespace dynslam::sim
