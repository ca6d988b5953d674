#include "dynslam/rawlog_tools/ColourImageStore.h"

#include "dynslam/rawlog_tools/ConversionError.h"

#include <opencv2/imgcodecs.hpp>

#include <filesystem>
#include <system_error>

namespace fs = std::filesystem;

namespace dynslam::rawlog_tools {

ColourImageStore::ColourImageStore(ImageStorage storage, std::string imagesDir)
    : storage_(storage), imagesDir_(std::move(imagesDir)) {}

void ColourImageStore::ensureImagesDir() {
  if (imagesDirReady_) return;
  std::error_code ec;
  fs::create_directories(imagesDir_, ec);
  if (ec) throw ConversionError("cannot create images folder " + imagesDir_ + ": " + ec.message());
  imagesDirReady_ = true;
}

StoredColourImage ColourImageStore::storeFile(const std::string& imageFile,
                                              const std::string& storedName) {
  if (!fs::is_regular_file(imageFile))
    throw ConversionError("colour image " + imageFile + " does not exist");
  // Decoded even when only copied: a broken file should fail the conversion, not the reader.
  cv::Mat bgr = cv::imread(imageFile, cv::IMREAD_COLOR);
  if (bgr.empty()) throw ConversionError("cannot decode colour image " + imageFile);

  StoredColourImage stored;
  stored.width = bgr.cols;
  stored.height = bgr.rows;
  if (storage_ == ImageStorage::Embedded) {
    stored.pixels = std::move(bgr);
    return stored;
  }
  ensureImagesDir();
  stored.externalName = storedName + fs::path(imageFile).extension().string();
  std::error_code ec;
  fs::copy_file(imageFile, fs::path(imagesDir_) / stored.externalName,
                fs::copy_options::overwrite_existing, ec);
  if (ec)
    throw ConversionError("cannot copy " + imageFile + " into " + imagesDir_ + ": " + ec.message());
  return stored;
}

StoredColourImage ColourImageStore::storePixels(const cv::Mat& bgr, const std::string& storedName) {
  if (bgr.empty() || bgr.type() != CV_8UC3)
    throw ConversionError("colour image " + storedName + " is not 8-bit BGR");
  StoredColourImage stored;
  stored.width = bgr.cols;
  stored.height = bgr.rows;
  if (storage_ == ImageStorage::Embedded) {
    stored.pixels = bgr.clone();
    return stored;
  }
  ensureImagesDir();
  stored.externalName = storedName + ".png";
  const std::string target = (fs::path(imagesDir_) / stored.externalName).string();
  if (!cv::imwrite(target, bgr)) throw ConversionError("cannot write " + target);
  return stored;
}

}  // namespace dynslam::rawlog_tools
