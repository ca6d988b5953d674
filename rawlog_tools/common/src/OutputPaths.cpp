#include "dynslam/rawlog_tools/OutputPaths.h"

#include "dynslam/rawlog_tools/ConversionError.h"

#include <filesystem>
#include <system_error>

namespace fs = std::filesystem;

namespace dynslam::rawlog_tools {

RawlogOutputPaths rawlogOutputPaths(const std::string& rawlogPath) {
  const fs::path path(rawlogPath);
  RawlogOutputPaths out;
  out.rawlog = rawlogPath;
  out.stem = path.stem().string();
  if (out.stem.empty() || out.stem == "." || out.stem == "..")
    throw ConversionError("output '" + rawlogPath + "' has no file name");
  const fs::path dir = path.has_parent_path() ? path.parent_path() : fs::path(".");
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec)
    throw ConversionError("cannot create output folder " + dir.string() + ": " + ec.message());
  out.directory = dir.string();
  out.imagesDir = (dir / (out.stem + "_Images")).string();
  out.groundTruth = (dir / (out.stem + ".gt.tum")).string();
  return out;
}

}  // namespace dynslam::rawlog_tools
