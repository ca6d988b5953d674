#pragma once
// Reading a TUM RGB-D sequence folder (https://cvg.cit.tum.de/data/datasets/rgbd-dataset):
// rgb.txt / depth.txt ("timestamp path" per line), accelerometer.txt ("timestamp ax ay az"),
// and the per-camera default intrinsics the TUM site publishes.
#include <dynslam/rawlog_tools/ObservationBuilders.h>

#include <array>
#include <string>
#include <vector>

namespace dynslam::rawlog_tools::tum {

struct ImageEntry {
  double t = 0;
  std::string path;  ///< absolute or relative to the working directory (folder + list entry)
};

struct AccelerometerSample {
  double t = 0;
  std::array<double, 3> acc{};
};

/// rgb.txt or depth.txt; paths are resolved against the sequence folder.
std::vector<ImageEntry> readImageList(const std::string& sequenceDir, const std::string& listName);

/// accelerometer.txt (m/s^2); empty when the file is absent.
std::vector<AccelerometerSample> readAccelerometer(const std::string& file);

struct NamedIntrinsics {
  std::string name;  ///< "freiburg1", "freiburg2", "freiburg3" or "ROS default"
  PinholeIntrinsics intrinsics;
};

/// The published defaults chosen by "freiburg1/2/3" in the folder name; ROS defaults
/// (525, 525, 319.5, 239.5) when none matches.
NamedIntrinsics intrinsicsForSequenceName(const std::string& folderName);

}  // namespace dynslam::rawlog_tools::tum
