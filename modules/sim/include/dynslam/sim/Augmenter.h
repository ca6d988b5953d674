#pragma once
// Augment mode ([Scenario] scene = augment): a real static RGB-D sequence with ground-truth
// poses (sevenscenes2rawlog output, [Augment]) with rendered people and cars inserted, occluded
// by and occluding the real depth, and an IMU synthesised from a spline fitted to the real
// camera motion. Real background, real camera motion, known movers.
//
// Frames: the rawlog's RGB-D observations that have a ground-truth pose (same stamp within
// 1 ms), in file order; their stamps, image size and intrinsics are the real ones ([Scenario]
// duration, fps, start_time, width, height, fx... are not used; [Camera] only for cam_*, the
// IMU's extrinsic). Output frame ("world" of SimFrame, groundtruth.tum and objects) is the
// floor frame F: z up along the real floor's normal, origin on the floor at the centre of the
// region the agents use. Colour and depth of 7-Scenes are not perfectly registered; the
// compositing takes them as registered (as the dataset's own tools do), so at real depth edges
// the inserted movers may be cut a few pixels off the colour edge they belong to.
#include <dynslam/sim/Agent.h>
#include <dynslam/sim/FloorPlane.h>
#include <dynslam/sim/GroundTruthSpline.h>
#include <dynslam/sim/ScenarioOptions.h>
#include <dynslam/sim/SimFrame.h>
#include <dynslam/sim/SplineTrajectory.h>
#include <dynslam/sim/SpritePeople.h>
#include <dynslam/sim/Texture.h>

#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace dynslam::sim {

class FloorMap;
class RealRgbdStream;
struct CameraTrack;

/// What the Augmenter found in the real sequence (for logs and tests).
struct AugmentSummary {
  FloorFit floor;                       ///< in the ground truth's world frame
  Eigen::Isometry3d T_world_floor;      ///< F in the ground truth's world frame
  Eigen::Vector2d region_extent_m;      ///< size of the clear floor's bounding box, m
  int clear_cells = 0;                  ///< of the floor map (cell size in [Augment])
  SplineFitError spline_error;          ///< camera poses: spline vs ground truth
  std::size_t frames_without_pose = 0;  ///< RGB-D observations with no ground truth
  /// Over all frames, m on the floor: the closest two agents came to each other (infinity for
  /// fewer than two) and the closest any agent came to the camera's optical centre.
  double min_agent_separation = 0, min_camera_distance = 0;
  /// What the floor planner placed instead of the ini's people when they did not fit.
  std::vector<std::string> fallbacks;
};

class Augmenter : public Sequence {
 public:
  /// Reads the ground truth, scans the rawlog once (stamps; the depth of [Augment]
  /// floor_frames frames for the floor), places the agents and synthesises the IMU. Throws
  /// core::ConfigError for an [Augment] value out of range, and std::runtime_error (or the
  /// readers' errors) naming the file for a missing or unreadable rawlog or ground truth, no
  /// frame with a pose, no floor found, or no clear floor for the agents.
  explicit Augmenter(const ScenarioOptions& options);
  ~Augmenter() override;

  size_t frameCount() const override { return frames_.size(); }
  double frameTime(size_t index) const override;
  /// Thread-safe (frames are read from one stream under a lock); increasing indices read the
  /// rawlog once, going back re-opens it.
  void renderFrame(size_t index, SimFrame& out) const override;
  const core::CameraIntrinsics& camera() const override { return camera_; }
  const std::vector<ImuMeasurement>& imu() const override { return imu_; }
  const std::vector<GnssFixSample>& gnss() const override { return gnss_; }
  double startTime() const override { return start_time_; }
  double maxRange() const override { return options_.noise.rgbd.max_range; }

  const std::vector<Agent>& agents() const { return agents_; }
  const TextureLibrary& textures() const { return textures_; }
  const AugmentSummary& summary() const { return summary_; }
  std::vector<std::string> notes() const override { return summary_.fallbacks; }
  /// Body (IMU) trajectory in F, t in s since the first frame.
  const SplineTrajectory& trajectory() const override { return *trajectory_; }
  const Eigen::Isometry3d& T_body_camera() const override { return T_body_camera_; }
  /// Ground-truth camera pose of frame `index` in F (what renderFrame writes).
  Eigen::Isometry3d T_floor_camera(size_t index) const;

 private:
  struct RealFrame {
    std::size_t rgbd_number;  ///< position among the rawlog's RGB-D observations
    double stamp;             ///< s (Unix time)
    Eigen::Isometry3d T_world_camera;
  };
  /// The ground truth and the rawlog's RGB-D stamps: frames_ (those with a pose).
  void readRealFrames();
  /// Floor plane, floor frame F (origin at the most-seen clear floor), free-floor map, then the
  /// people's and cars' paths on it (in F).
  void findFloorAndPlaceAgents(const std::vector<PointGrid>& grids,
                               const std::vector<cv::Mat>& depths,
                               const std::vector<std::size_t>& sampled, std::mt19937_64& rng);
  /// The free-floor map in the first floor frame (map), and the cameras' track on it.
  FloorMap buildFloorMap(const std::vector<PointGrid>& grids, const std::vector<cv::Mat>& depths,
                         const std::vector<std::size_t>& sampled,
                         const Eigen::Isometry3d& T_map_world, CameraTrack& track) const;
  /// summary_'s clear cells and the extent of the clear floor.
  void summariseClearFloor(const FloorMap& map);
  /// The people's and cars' paths on the clear floor around `region`, and how close they come.
  void placeAgents(const FloorMap& map, const Eigen::Vector2d& region, const CameraTrack& track,
                   std::mt19937_64& rng);
  /// The IMU (and GNSS) from a spline through the real camera poses, in F.
  void synthesizeInertialSensors();

  ScenarioOptions options_;
  std::unique_ptr<SpritePeople> sprites_;  ///< [People] appearance = video
  std::string rawlog_path_;
  std::vector<RealFrame> frames_;
  double start_time_ = 0;
  core::CameraIntrinsics camera_;
  Eigen::Isometry3d T_floor_world_ = Eigen::Isometry3d::Identity();
  Eigen::Isometry3d T_body_camera_ = Eigen::Isometry3d::Identity();
  TextureLibrary textures_;
  std::vector<Agent> agents_;
  std::unique_ptr<SplineTrajectory> trajectory_;
  std::vector<ImuMeasurement> imu_;
  std::vector<GnssFixSample> gnss_;
  AugmentSummary summary_;
  mutable std::mutex stream_mutex_;
  mutable std::unique_ptr<RealRgbdStream> stream_;
};

}  // namespace dynslam::sim
