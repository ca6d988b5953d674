#include "dynslam/io/RawlogSource.h"

#include "GzReadStream.h"

#include <dynslam/core/CommandLine.h>

#include <mrpt/io/lazy_load_path.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/serialization/CArchive.h>

#include <filesystem>

namespace fs = std::filesystem;

namespace dynslam::io {

RawlogSource::RawlogSource(const std::string& path, std::size_t max_field_bytes) : path_(path) {
  if (!fs::is_regular_file(path)) throw RawlogError("rawlog '" + path + "' does not exist");
  try {
    stream_ = std::make_unique<detail::GzReadStream>(path, max_field_bytes);
  } catch (const std::exception& e) {
    throw RawlogError(e.what());
  }
  // MRPT's convention: <dir>/<stem>_Images beside the file. CRawlog::detectImagesDirectory()
  // drops the separator (mrpt-notes.md pitfall 1), so build the path here.
  const fs::path p(path);
  const fs::path images = p.parent_path() / (p.stem().string() + "_Images");
  if (fs::is_directory(images)) {
    images_dir_ = images.string();
    mrpt::io::setLazyLoadPathBase(images_dir_);
  }
}

RawlogSource::~RawlogSource() = default;

mrpt::obs::CObservation::Ptr RawlogSource::next() {
  while (pending_.empty()) {
    if (ended_) return nullptr;
    auto archive = mrpt::serialization::archiveFrom(*stream_);
    stream_->markObjectStart();
    mrpt::serialization::CSerializable::Ptr obj;
    try {
      archive >> obj;
    } catch (const std::exception& e) {
      // An end of file before the first byte of an entry is the normal end; anywhere else the
      // file was cut short or is not a rawlog.
      const auto& guard = stream_->guard();
      if (!guard.refused() && stream_->bytesSinceMark() == 0 && stream_->zlibError().empty()) {
        ended_ = true;
        return nullptr;
      }
      // MRPT wraps the guard's exception in its own, so take the refusal from the guard.
      const std::string zerr = stream_->zlibError();
      const std::string why =
          guard.refused() ? guard.refusal() : (zerr.empty() ? core::userMessage(e.what()) : zerr);
      throw RawlogError("rawlog '" + path_ + "' is truncated or corrupt at entry #" +
                        std::to_string(entries_) + " (byte " +
                        std::to_string(stream_->compressedPosition()) + " of " +
                        std::to_string(stream_->getTotalBytesCount()) + "): " + why);
    }
    ++entries_;
    if (!obj)  // MRPT writes a null pointer as the class name "nullptr"
      throw RawlogError("rawlog '" + path_ + "': entry #" + std::to_string(entries_ - 1) +
                        " is an empty object (nullptr), not an observation");
    if (auto obs = std::dynamic_pointer_cast<mrpt::obs::CObservation>(obj)) return obs;
    if (auto sf = std::dynamic_pointer_cast<mrpt::obs::CSensoryFrame>(obj)) {
      for (const auto& o : *sf) pending_.push_back(o);
      continue;
    }
    if (std::dynamic_pointer_cast<mrpt::obs::CActionCollection>(obj)) continue;  // odometry
    throw RawlogError("rawlog '" + path_ + "': entry #" + std::to_string(entries_ - 1) + " is a " +
                      obj->GetRuntimeClass()->className +
                      ", not an observation, sensory frame or action");
  }
  auto obs = pending_.front();
  pending_.pop_front();
  return obs;
}

double RawlogSource::progress() const {
  const auto total = stream_->getTotalBytesCount();
  if (ended_ || total == 0) return 1.0;
  return std::min(1.0, static_cast<double>(stream_->compressedPosition()) / total);
}

}  // namespace dynslam::io
