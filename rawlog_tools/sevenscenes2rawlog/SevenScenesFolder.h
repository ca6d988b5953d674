#pragma once
// The Microsoft 7-Scenes sequence layout: frame-NNNNNN.color.jpg, frame-NNNNNN.depth.png
// (uint16 mm, 65535 = invalid), frame-NNNNNN.pose.txt (4x4 camera-to-world, metres) and
// camera-intrinsics.txt (3x3 K) in one folder.
#include <dynslam/rawlog_tools/ObservationBuilders.h>

#include <Eigen/Geometry>

#include <string>

namespace dynslam::rawlog_tools::sevenscenes {

struct FramePaths {
  std::string colour, depth, pose;
};

/// Paths of frame `index` (they are not checked here).
FramePaths framePaths(const std::string& dir, long long index);

/// The highest frame number whose colour image exists, or -1 when there is none.
long long lastFrameIndex(const std::string& dir);

/// fx, fy, cx, cy from camera-intrinsics.txt; throws naming the file when it is not a K matrix.
PinholeIntrinsics readIntrinsics(const std::string& dir);

/// The camera-to-world pose, rotation projected onto SO(3) (the files are orthonormal only to
/// ~3e-4); throws naming the file when it is not a rigid 4x4 matrix.
Eigen::Isometry3d readPose(const std::string& poseFile);

}  // namespace dynslam::rawlog_tools::sevenscenes
