#include "TumSequence.h"

#include <dynslam/rawlog_tools/TextTables.h>

#include <filesystem>

namespace fs = std::filesystem;

namespace dynslam::rawlog_tools::tum {

std::vector<ImageEntry> readImageList(const std::string& sequenceDir, const std::string& listName) {
  const std::string file = (fs::path(sequenceDir) / listName).string();
  std::vector<ImageEntry> entries;
  forEachTableRow(file, ' ', [&](const TableSource& source, const TableRow& row) {
    requireFieldCount(source, row, 2);
    entries.push_back(
        {parseFiniteDouble(source, row, 0), (fs::path(sequenceDir) / row.fields[1]).string()});
  });
  return entries;
}

std::vector<AccelerometerSample> readAccelerometer(const std::string& file) {
  std::vector<AccelerometerSample> samples;
  if (!fs::exists(file)) return samples;
  forEachTableRow(file, ' ', [&](const TableSource& source, const TableRow& row) {
    requireFieldCount(source, row, 4);
    AccelerometerSample s;
    s.t = parseFiniteDouble(source, row, 0);
    for (size_t i = 0; i < 3; ++i) s.acc[i] = parseFiniteDouble(source, row, i + 1);
    samples.push_back(s);
  });
  return samples;
}

NamedIntrinsics intrinsicsForSequenceName(const std::string& folderName) {
  // Values from the TUM RGB-D "File Formats" page (colour camera; depth is registered to it).
  if (folderName.find("freiburg1") != std::string::npos)
    return {"freiburg1", {517.3, 516.5, 318.6, 255.3}};
  if (folderName.find("freiburg2") != std::string::npos)
    return {"freiburg2", {520.9, 521.0, 325.1, 249.7}};
  if (folderName.find("freiburg3") != std::string::npos)
    return {"freiburg3", {535.4, 539.2, 320.1, 247.6}};
  return {"ROS default", {525.0, 525.0, 319.5, 239.5}};
}

}  // namespace dynslam::rawlog_tools::tum
