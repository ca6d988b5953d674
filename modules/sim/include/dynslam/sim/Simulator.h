#pragma once
// A fully synthetic sequence: the scene ([Scenario] scene = room, corridor, market or
// street), its agents
// and the sensor's path built once from a ScenarioOptions, then any frame rendered on demand
// (deterministically: frame i's noise comes from the seed and i alone, so frames may be
// rendered in any order or in parallel).
#include <dynslam/sim/Scene.h>
#include <dynslam/sim/SimFrame.h>
#include <dynslam/sim/SplineTrajectory.h>
#include <dynslam/sim/SpritePeople.h>

#include <memory>

namespace dynslam::sim {

class Simulator : public Sequence {
 public:
  /// Throws std::invalid_argument when the scene cannot be built as configured (a hall too
  /// small for its aisles, a route too short, ...), naming what to change.
  explicit Simulator(ScenarioOptions options);

  size_t frameCount() const override;
  double frameTime(size_t index) const override;
  void renderFrame(size_t index, SimFrame& out) const override;
  /// The scene at time t (s since the start) seen from any camera pose (a robot driven in
  /// closed loop, not the scenario's path); the depth noise is that of frame `noise_index`.
  void renderAt(double t, const Eigen::Isometry3d& T_world_camera, size_t noise_index,
                SimFrame& out) const;
  /// The scene's static surfaces (walls, floor, furniture), world frame.
  const Mesh& staticMesh() const { return scene_.static_mesh; }
  const core::CameraIntrinsics& camera() const override { return camera_; }
  const std::vector<ImuMeasurement>& imu() const override { return imu_; }
  const std::vector<GnssFixSample>& gnss() const override { return gnss_; }
  double startTime() const override { return options_.world.start_time; }
  double maxRange() const override { return options_.noise.rgbd.max_range; }

  const ScenarioOptions& options() const { return options_; }
  const SplineTrajectory& trajectory() const override { return *trajectory_; }
  /// Camera pose in the IMU (body) frame.
  const Eigen::Isometry3d& T_body_camera() const override { return T_body_camera_; }
  const std::vector<Agent>& agents() const { return scene_.agents; }

 private:
  ScenarioOptions options_;
  core::CameraIntrinsics camera_;
  TextureLibrary textures_;
  Scene scene_;
  std::unique_ptr<SpritePeople> sprites_;  ///< [People] appearance = video
  std::unique_ptr<SplineTrajectory> trajectory_;
  Eigen::Isometry3d T_body_camera_ = Eigen::Isometry3d::Identity();
  std::vector<ImuMeasurement> imu_;
  std::vector<GnssFixSample> gnss_;
};

/// Camera optical axes (x right, y down, z forward) in the body frame (x forward, y left, z
/// up), then the small mounting rotation and offset of [Camera] cam_*.
Eigen::Isometry3d cameraInBody(const CameraMotionOptions& camera);

/// Intrinsics of [Scenario] width, height, fx, fy, cx, cy.
core::CameraIntrinsics intrinsicsOf(const WorldOptions& world);

}  // namespace dynslam::sim
