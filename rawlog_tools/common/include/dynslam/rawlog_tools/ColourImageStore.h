#pragma once
// Decides how a colour image travels with a rawlog. External (the default, MRPT's convention):
// the image file is copied (or a decoded image PNG-encoded) into <stem>_Images/ and the
// observation refers to it by a path relative to that folder, keeping the rawlog small.
// Embedded: the decoded pixels go into the observation itself.
#include <opencv2/core/mat.hpp>

#include <string>

namespace dynslam::rawlog_tools {

enum class ImageStorage { External, Embedded };

/// A colour image ready to be put into an observation.
struct StoredColourImage {
  int width = 0;
  int height = 0;
  std::string externalName;  ///< relative to the images folder; empty when embedded
  cv::Mat pixels;            ///< BGR 8-bit; empty when stored externally
};

class ColourImageStore {
 public:
  /// imagesDir is created on first use (only in External mode).
  ColourImageStore(ImageStorage storage, std::string imagesDir);

  ImageStorage storage() const { return storage_; }
  const std::string& imagesDir() const { return imagesDir_; }

  /// Takes an image file as it is. External: copies it byte for byte as `storedName` plus the
  /// source's extension (a JPEG stays a JPEG, no re-encoding loss). The file is decoded either
  /// way, to check it and to know its size. Throws ConversionError naming the file.
  StoredColourImage storeFile(const std::string& imageFile, const std::string& storedName);

  /// Takes decoded BGR pixels (e.g. from a simulator). External: writes `storedName`.png.
  StoredColourImage storePixels(const cv::Mat& bgr, const std::string& storedName);

 private:
  void ensureImagesDir();

  ImageStorage storage_;
  std::string imagesDir_;
  bool imagesDirReady_ = false;
};

}  // namespace dynslam::rawlog_tools
