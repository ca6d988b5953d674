#include "dynslam/rawlog_tools/RawlogWriter.h"

#include "dynslam/rawlog_tools/ConversionError.h"

#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/obs/CObservation.h>
#include <mrpt/serialization/CArchive.h>

#include <filesystem>
#include <system_error>

namespace dynslam::rawlog_tools {

struct RawlogWriter::Stream {
  mrpt::io::CFileGZOutputStream file;
  mrpt::serialization::CArchive::UniquePtr archive;
};

RawlogWriter::RawlogWriter(const std::string& path, int compressionLevel)
    : stream_(std::make_unique<Stream>()), path_(path) {
  std::string error;
  if (!stream_->file.open(path, compressionLevel, error))
    throw ConversionError("cannot create rawlog " + path + (error.empty() ? "" : ": " + error));
  stream_->archive = mrpt::serialization::archiveUniquePtrFrom(stream_->file);
}

RawlogWriter::~RawlogWriter() {
  if (!stream_) return;
  try {
    close();
    std::error_code ec;
    std::filesystem::remove(path_, ec);
  } catch (...) {
    // A destructor must not throw.
  }
}

void RawlogWriter::write(const mrpt::obs::CObservation& observation) {
  if (!stream_) throw ConversionError("rawlog " + path_ + " is already closed");
  try {
    *stream_->archive << observation;
  } catch (const std::exception& e) {
    throw ConversionError("writing observation " + std::to_string(written_) + " to " + path_ +
                          " failed: " + e.what());
  }
  ++written_;
  ++perLabel_[observation.sensorLabel];
}

void RawlogWriter::close() {
  if (!stream_) return;
  stream_->archive.reset();
  stream_->file.close();
  stream_.reset();
}

}  // namespace dynslam::rawlog_tools
