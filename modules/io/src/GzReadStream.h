#pragma once
// A read-only mrpt::io::CStream over zlib's gzFile (plain files read through unchanged) that
// knows two things CFileGZInputStream does not tell: how far into the compressed file we are
// (for progress and ETA) and how many bytes the current object has consumed (to tell a clean
// end of file from a file cut in the middle of an object). Every byte it delivers passes
// through a SerializedSizeGuard, which refuses a size field over the limit before MRPT sees it.
#include "SerializedSizeGuard.h"

#include <mrpt/io/CStream.h>

#include <cstdint>
#include <string>

namespace dynslam::io::detail {

class GzReadStream : public mrpt::io::CStream {
 public:
  /// Throws std::runtime_error naming `path` when it cannot be opened. No field of an object
  /// may claim more than max_field_bytes (SerializedSizeGuard).
  GzReadStream(const std::string& path, uint64_t max_field_bytes);
  ~GzReadStream() override;
  GzReadStream(const GzReadStream&) = delete;
  GzReadStream& operator=(const GzReadStream&) = delete;

  size_t Read(void* buffer, size_t count) override;
  size_t Write(const void*, size_t) override;
  uint64_t Seek(int64_t, mrpt::io::CStream::TSeekOrigin) override;
  uint64_t getTotalBytesCount() const override { return file_size_; }
  uint64_t getPosition() const override { return uncompressed_pos_; }

  /// Bytes of the file (compressed) consumed so far.
  uint64_t compressedPosition() const;
  /// Bytes read since the last markObjectStart().
  uint64_t bytesSinceMark() const { return uncompressed_pos_ - mark_; }
  void markObjectStart() {
    mark_ = uncompressed_pos_;
    guard_.beginObject();
  }
  const SerializedSizeGuard& guard() const { return guard_; }
  /// zlib's description of a read error ("" when none), e.g. for a truncated gzip member.
  std::string zlibError() const;

 private:
  void* gz_ = nullptr;  // gzFile, kept opaque so zlib.h stays out of this header
  uint64_t file_size_ = 0;
  uint64_t uncompressed_pos_ = 0;
  uint64_t mark_ = 0;
  SerializedSizeGuard guard_;
};

}  // namespace dynslam::io::detail
