#pragma once
// What a simulated sequence gives per frame (images and object ground truth), and the interface
// every sequence source implements: the fully synthetic Simulator and the Augmenter that inserts
// rendered movers into a real RGB-D sequence. The writer (rawlog + ground truth files) and
// dynslam-sim only see this interface.
#include <dynslam/core/Frame.h>
#include <dynslam/core/ObjectGroundTruth.h>
#include <dynslam/sim/GnssSynthesizer.h>
#include <dynslam/sim/ImuSynthesizer.h>
#include <dynslam/sim/Rasterizer.h>
#include <dynslam/sim/SplineTrajectory.h>

#include <Eigen/Geometry>
#include <opencv2/core/types.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace dynslam::sim {

/// Ground truth of one object in one frame.
struct ObjectTruth {
  uint16_t id = 0;       ///< the value of its pixels in the label image
  std::string category;  ///< "person" or "car"
  bool moving = false;
  Eigen::Isometry3d T_world_object = Eigen::Isometry3d::Identity();  ///< rigid core
  cv::Rect box;                 ///< amodal 2-D box (whole body, occluded parts too), clipped
  int visible_pixels = 0;       ///< pixels with its label
  double visible_fraction = 0;  ///< visible / pixels it would cover with nothing in front
};

/// The objects.txt row of `truth` in frame `frame` stamped `stamp` (Unix seconds).
inline core::ObjectGroundTruthRow groundTruthRow(size_t frame, double stamp,
                                                 const ObjectTruth& truth) {
  core::ObjectGroundTruthRow row;
  row.frame = frame;
  row.t = stamp;
  row.id = truth.id;
  row.category = truth.category;
  row.moving = truth.moving;
  row.T_world_object = truth.T_world_object;
  row.box = truth.box;
  row.visible_pixels = truth.visible_pixels;
  row.visible_fraction = truth.visible_fraction;
  return row;
}

struct SimFrame {
  size_t index = 0;
  double t = 0;  ///< s since the start of the sequence
  Eigen::Isometry3d T_world_camera = Eigen::Isometry3d::Identity();
  RenderOutput image;                ///< noisy colour and depth, exact labels
  std::vector<ObjectTruth> objects;  ///< objects at least partly inside the image
};

/// A sequence of RGB-D frames with IMU (and GNSS) samples and full ground truth. Frames are
/// rendered on demand and deterministically (frame i depends on the seed and i alone).
class Sequence {
 public:
  virtual ~Sequence() = default;
  virtual size_t frameCount() const = 0;
  virtual double frameTime(size_t index) const = 0;  ///< s since the start
  virtual void renderFrame(size_t index, SimFrame& out) const = 0;
  virtual const core::CameraIntrinsics& camera() const = 0;
  virtual const std::vector<ImuMeasurement>& imu() const = 0;  ///< t in s since the start
  virtual const std::vector<GnssFixSample>& gnss() const = 0;  ///< t in s since the start
  virtual double startTime() const = 0;  ///< Unix time of t = 0 (the rawlog stamps)
  virtual double maxRange() const = 0;   ///< m; the depth sensor's range (0 beyond it)
  /// The colour camera's optical frame (x right, y down, z forward) in the body frame (x
  /// forward, y left, z up): what the writer stores as the RGB-D observations' sensorPose.
  virtual const Eigen::Isometry3d& T_body_camera() const = 0;
  /// The body's trajectory (t in s since the start), which the IMU is synthesized from.
  virtual const SplineTrajectory& trajectory() const = 0;
  /// The camera's (optical frame) true pose at any time t (s since the start) on trajectory():
  /// the ground truth of a stamp that is not a render time ([Calibration] time offset and
  /// jitter). Nothing outside the trajectory's time range.
  std::optional<Eigen::Isometry3d> cameraPoseAt(double t) const {
    const SplineTrajectory& path = trajectory();
    if (t < path.startTime() || t > path.endTime()) return std::nullopt;
    return path.sample(t).T_world_body * T_body_camera();
  }
  /// The IMU's axes in the body frame. The simulated body is the IMU itself (the samples are
  /// synthesized with this extrinsic), so identity unless a source says otherwise.
  virtual Eigen::Isometry3d T_body_imu() const { return Eigen::Isometry3d::Identity(); }
  /// What the sequence changed from its ini to fit its data (augment mode on a floor with
  /// little room: shorter walks, fewer walkers), one line each; dynslam-sim prints them.
  virtual std::vector<std::string> notes() const { return {}; }
};

}  // namespace dynslam::sim
