#pragma once
// Streams observations into a gzip-compressed, observations-only .rawlog as they are produced:
// nothing of the sequence stays in memory. Readers use
// CRawlog::getActionObservationPairOrObservation.
#include <cstddef>
#include <map>
#include <memory>
#include <string>

namespace mrpt::obs {
class CObservation;
}

namespace dynslam::rawlog_tools {

class RawlogWriter {
 public:
  /// Opens (truncates) the file; compressionLevel 1 is MRPT's default and the fastest.
  /// Throws ConversionError when the file cannot be created.
  explicit RawlogWriter(const std::string& path, int compressionLevel = 1);
  ~RawlogWriter();
  RawlogWriter(const RawlogWriter&) = delete;
  RawlogWriter& operator=(const RawlogWriter&) = delete;

  /// Serializes one observation. Observations should come in timestamp order; the writer
  /// does not reorder them.
  void write(const mrpt::obs::CObservation& observation);

  /// Flushes and closes; further writes throw. Only a closed rawlog counts as complete: a
  /// writer destroyed without close() (a conversion that threw) deletes its file, so a failed
  /// run never leaves a rawlog that looks whole.
  void close();

  size_t written() const { return written_; }
  /// Observations written per sensor label.
  const std::map<std::string, size_t>& writtenPerLabel() const { return perLabel_; }
  const std::string& path() const { return path_; }

 private:
  struct Stream;
  std::unique_ptr<Stream> stream_;
  std::string path_;
  size_t written_ = 0;
  std::map<std::string, size_t> perLabel_;
};

}  // namespace dynslam::rawlog_tools
