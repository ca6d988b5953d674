#pragma once
// A simulated sequence: the static scene, the agents and the sensor path built once from a
// ScenarioOptions, then any frame rendered on demand (deterministically: frame i's noise comes
// from the seed and i alone, so frames may be rendered in any order or in parallel).
#include <dynslam/sim/GnssSynthesizer.h>
#include <dynslam/sim/ImuSynthesizer.h>
#include <dynslam/sim/Mesh.h>
#include <dynslam/sim/Person.h>
#include <dynslam/sim/Rasterizer.h>
#include <dynslam/sim/ScenarioOptions.h>
#include <dynslam/sim/SplineTrajectory.h>
#include <dynslam/sim/Texture.h>

#include <opencv2/core/types.hpp>

#include <memory>
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

struct SimFrame {
  size_t index = 0;
  double t = 0;  ///< s since the start of the sequence
  Eigen::Isometry3d T_world_camera = Eigen::Isometry3d::Identity();
  RenderOutput image;                ///< noisy colour and depth, exact labels
  std::vector<ObjectTruth> objects;  ///< objects at least partly inside the image
};

class Simulator {
 public:
  explicit Simulator(ScenarioOptions options);

  size_t frameCount() const;
  double frameTime(size_t index) const;
  void renderFrame(size_t index, SimFrame& out) const;

  const ScenarioOptions& options() const { return options_; }
  const core::CameraIntrinsics& camera() const { return camera_; }
  const SplineTrajectory& trajectory() const { return *trajectory_; }
  /// Camera pose in the IMU (body) frame.
  const Eigen::Isometry3d& T_body_camera() const { return T_body_camera_; }
  const std::vector<ImuMeasurement>& imu() const { return imu_; }
  const std::vector<GnssFixSample>& gnss() const { return gnss_; }

 private:
  struct Agent {
    uint16_t id;
    WalkPath path;
    PersonAppearance look;
  };
  Mesh agentMesh(const Agent& agent, double t) const;

  ScenarioOptions options_;
  core::CameraIntrinsics camera_;
  TextureLibrary textures_;
  Mesh static_mesh_;
  std::vector<Agent> people_;
  std::unique_ptr<SplineTrajectory> trajectory_;
  Eigen::Isometry3d T_body_camera_ = Eigen::Isometry3d::Identity();
  std::vector<ImuMeasurement> imu_;
  std::vector<GnssFixSample> gnss_;
};

}  // namespace dynslam::sim
