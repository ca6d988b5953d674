#include "SevenScenesFolder.h"

#include <dynslam/rawlog_tools/ConversionError.h>
#include <dynslam/rawlog_tools/TextTables.h>

#include <Eigen/SVD>

#include <cstdio>
#include <filesystem>
#include <regex>

namespace fs = std::filesystem;

namespace dynslam::rawlog_tools::sevenscenes {

FramePaths framePaths(const std::string& dir, long long index) {
  char stem[32];
  std::snprintf(stem, sizeof(stem), "frame-%06lld", index);
  const fs::path base = fs::path(dir) / stem;
  return {base.string() + ".color.jpg", base.string() + ".depth.png", base.string() + ".pose.txt"};
}

long long lastFrameIndex(const std::string& dir) {
  static const std::regex colourName(R"(frame-(\d+)\.color\.jpg)");
  long long last = -1;
  for (const auto& entry : fs::directory_iterator(dir)) {
    std::smatch m;
    const std::string name = entry.path().filename().string();
    if (std::regex_match(name, m, colourName)) last = std::max(last, std::stoll(m[1].str()));
  }
  return last;
}

PinholeIntrinsics readIntrinsics(const std::string& dir) {
  const std::string file = (fs::path(dir) / "camera-intrinsics.txt").string();
  if (!fs::exists(file)) throw ConversionError("missing " + file);
  const std::vector<double> k = readNumberGrid(file, 9);
  if (k[1] != 0.0 || k[3] != 0.0 || k[6] != 0.0 || k[7] != 0.0 || k[8] != 1.0 || k[0] <= 0 ||
      k[4] <= 0)
    throw ConversionError(file + ": not a pinhole K matrix [fx 0 cx; 0 fy cy; 0 0 1]");
  return {k[0], k[4], k[2], k[5]};
}

Eigen::Isometry3d readPose(const std::string& poseFile) {
  if (!fs::exists(poseFile)) throw ConversionError("missing pose file " + poseFile);
  const std::vector<double> m = readNumberGrid(poseFile, 16);
  Eigen::Matrix4d matrix;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) matrix(r, c) = m[static_cast<size_t>(4 * r + c)];
  // KinectFusion's rotations in 7-Scenes are orthonormal only to ~3e-4 (R^T R - I), so they
  // are projected onto the nearest rotation (SVD) rather than rejected; 1e-2 still catches
  // matrices that are not rotations at all.
  const Eigen::Matrix3d rotation = matrix.topLeftCorner<3, 3>();
  const double orthonormalityError =
      (rotation.transpose() * rotation - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff();
  if (matrix.row(3) != Eigen::RowVector4d(0, 0, 0, 1) || orthonormalityError > 1e-2 ||
      rotation.determinant() <= 0)
    throw ConversionError(poseFile +
                          ": not a rigid transform (last row must be 0 0 0 1 and the "
                          "top-left 3x3 a rotation)");
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(rotation, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = svd.matrixU() * svd.matrixV().transpose();
  pose.translation() = matrix.topRightCorner<3, 1>();
  return pose;
}

}  // namespace dynslam::rawlog_tools::sevenscenes
