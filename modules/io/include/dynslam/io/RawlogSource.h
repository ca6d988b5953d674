#pragma once
// Streams the observations of a rawlog one at a time, never holding the file in memory. Reads
// both layouts MRPT writes: plain observation sequences and action / sensory-frame pairs (the
// observations of each CSensoryFrame come out one by one; actions are skipped). Images stored
// outside the file (<dir>/<stem>_Images/) are found automatically.
#include <mrpt/obs/CObservation.h>

#include <cstddef>
#include <cstdint>
#include <deque>
#include <memory>
#include <stdexcept>
#include <string>

namespace dynslam::io {

/// A rawlog that cannot be read: missing, not a rawlog, truncated or corrupt. The message names
/// the file and the entry at which reading failed.
struct RawlogError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

namespace detail {
class GzReadStream;
}

/// The most one field of an observation (an image, a depth matrix, the 3D points, a string)
/// may take once read: a corrupt size field claiming more is refused before it is allocated.
inline constexpr std::size_t kDefaultMaxObservationFieldBytes = std::size_t{512} << 20;

class RawlogSource {
 public:
  /// An entry with a field claiming more than max_field_bytes is a RawlogError (corrupt).
  explicit RawlogSource(const std::string& path,
                        std::size_t max_field_bytes = kDefaultMaxObservationFieldBytes);
  ~RawlogSource();
  RawlogSource(const RawlogSource&) = delete;
  RawlogSource& operator=(const RawlogSource&) = delete;

  /// The next observation, or nullptr at the end of the file. Throws RawlogError when the
  /// file is truncated or corrupt.
  mrpt::obs::CObservation::Ptr next();

  const std::string& path() const { return path_; }
  /// Folder of externally stored images, "" when there is none.
  const std::string& imagesDir() const { return images_dir_; }
  /// Fraction of the file consumed so far, in [0, 1] (for progress bars).
  double progress() const;
  /// Top-level entries (observations, sensory frames, actions) read so far.
  size_t entriesRead() const { return entries_; }

 private:
  std::string path_;
  std::string images_dir_;
  std::unique_ptr<detail::GzReadStream> stream_;
  std::deque<mrpt::obs::CObservation::Ptr> pending_;  // rest of the current sensory frame
  size_t entries_ = 0;
  bool ended_ = false;
};

}  // namespace dynslam::io
