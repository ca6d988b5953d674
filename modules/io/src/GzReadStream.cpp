#include "GzReadStream.h"

#include <zlib.h>

#include <filesystem>
#include <stdexcept>

namespace dynslam::io::detail {

GzReadStream::GzReadStream(const std::string& path, uint64_t max_field_bytes)
    : guard_(max_field_bytes) {
  std::error_code ec;
  file_size_ = std::filesystem::file_size(path, ec);
  if (ec) throw std::runtime_error("cannot open rawlog '" + path + "': " + ec.message());
  gz_ = gzopen(path.c_str(), "rb");
  if (!gz_) throw std::runtime_error("cannot open rawlog '" + path + "'");
  gzbuffer(static_cast<gzFile>(gz_), 1 << 20);
}

GzReadStream::~GzReadStream() {
  if (gz_) gzclose(static_cast<gzFile>(gz_));
}

size_t GzReadStream::Read(void* buffer, size_t count) {
  if (count == 0) return 0;
  guard_.checkRequest(count);
  const int n = gzread(static_cast<gzFile>(gz_), buffer, static_cast<unsigned>(count));
  if (n < 0) throw std::runtime_error("read error: " + zlibError());
  uncompressed_pos_ += static_cast<uint64_t>(n);
  guard_.observe(buffer, static_cast<size_t>(n));
  return static_cast<size_t>(n);
}

size_t GzReadStream::Write(const void*, size_t) {
  throw std::logic_error("GzReadStream is read-only");
}

uint64_t GzReadStream::Seek(int64_t, mrpt::io::CStream::TSeekOrigin) {
  throw std::logic_error("GzReadStream does not seek: rawlogs are streamed front to back");
}

uint64_t GzReadStream::compressedPosition() const {
  const auto off = gzoffset(static_cast<gzFile>(gz_));
  return off < 0 ? 0 : static_cast<uint64_t>(off);
}

std::string GzReadStream::zlibError() const {
  int code = Z_OK;
  const char* msg = gzerror(static_cast<gzFile>(gz_), &code);
  return (code == Z_OK || !msg) ? std::string() : std::string(msg);
}

}  // namespace dynslam::io::detail
