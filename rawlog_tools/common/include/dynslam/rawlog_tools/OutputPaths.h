#pragma once
// Where the files that accompany a rawlog go, following MRPT's convention:
//   <dir>/<stem>.rawlog, its external images in <dir>/<stem>_Images/, ground truth in
//   <dir>/<stem>.gt.tum.
// (CRawlog::detectImagesDirectory drops the '/' between dir and stem; these do not.)
#include <string>

namespace dynslam::rawlog_tools {

struct RawlogOutputPaths {
  std::string rawlog;       ///< as given
  std::string directory;    ///< folder of the rawlog ("." when none)
  std::string stem;         ///< file name without extension
  std::string imagesDir;    ///< <directory>/<stem>_Images
  std::string groundTruth;  ///< <directory>/<stem>.gt.tum
};

/// Creates the rawlog's folder when missing; throws ConversionError when the name has no stem.
RawlogOutputPaths rawlogOutputPaths(const std::string& rawlogPath);

}  // namespace dynslam::rawlog_tools
