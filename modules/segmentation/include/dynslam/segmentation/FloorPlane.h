#pragma once
// The floor under the objects, fitted to the depth image (not the method). A person's box
// reaches down to the floor at its feet, where the floor has the person's depth, so the
// depth-threshold mask (method.md section 1) takes a band of floor; corners on that floor are
// then classified with the walker and lost as static constraints (how many: docs/notes/
// perception.md, 2026-11-28).
#include <dynslam/core/Frame.h>

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include <optional>
#include <vector>

namespace dynslam::segmentation {

/// The fit's settings. Keys, ranges, meanings: FloorRemovalOptions::describe() in
/// FloorRemovalStage.cpp; docs/parameters.md.
struct FloorPlaneParams {
  int sample_stride_px = 8;
  int iterations = 100;
  double inlier_m = 0.02;
  double depth_sigma_z2 = 0.0015;
  double max_depth_m = 8;
  double max_tilt_deg = 10;
  int min_inliers = 150;
};

/// A plane n . P + c = 0 in camera coordinates (metres), n a unit normal pointing to the side
/// of the camera, so height(P) > 0 above the floor.
struct FloorPlane {
  Eigen::Vector3d normal = Eigen::Vector3d(0, -1, 0);
  double offset = 0;  ///< c: the camera's height above the floor
  int inliers = 0;
  double height(const Eigen::Vector3d& P) const { return normal.dot(P) + offset; }
};

/// "Up" in the camera frame: the mean accelerometer reading of the frame's IMU samples turned
/// into the camera's axes (at rest it is the reaction to gravity), or the image's up (-y)
/// without an accelerometer.
Eigen::Vector3d upInCamera(const core::Frame& frame);

/// RANSAC plane over the depth samples outside `exclude` whose normal is within max_tilt_deg of
/// `up`, refined by least squares on its inliers; nullopt when none has min_inliers. The
/// hypotheses come from a fixed seed: the same frame gives the same plane.
std::optional<FloorPlane> fitFloorPlane(const cv::Mat& depth, const core::CameraIntrinsics& K,
                                        const std::vector<cv::Rect>& exclude,
                                        const Eigen::Vector3d& up, const FloorPlaneParams& params);

}  // namespace dynslam::segmentation
