#pragma once
// The run as a 3-D scene for MRPT's SceneViewer3D (map.3Dscene): a static coloured point map,
// the camera trajectory and each estimated object's track. Built frame by frame while the run
// goes, saved once at the end. MRPT-free header: the opengl types stay in MapScene.cpp.
#include <dynslam/core/Frame.h>

#include <Eigen/Core>

#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <unordered_map>
#include <vector>

#include <memory>

namespace mrpt::opengl {
class COpenGLScene;
}
namespace mrpt::maps {
class CColouredPointsMap;
}

namespace dynslam::viz {

/// Names of the objects in the saved scene (COpenGLScene::getByName finds them).
inline constexpr const char* kStaticMapName = "static_map";                ///< CPointCloudColoured
inline constexpr const char* kCameraTrajectoryName = "camera_trajectory";  ///< CSetOfLines
/// CSetOfLines of object `id` (the Track id, as in objects/<id>.tum): "object_<id>".
std::string objectTrackName(int id);

struct MapSceneOptions {
  /// Back-project one frame out of this many (of those with a camera pose): consecutive frames
  /// see nearly the same surfaces, and every frame would cost time for no new points.
  int every_n_frames = 10;
  int pixel_stride = 4;      ///< back-project every n-th pixel in x and y
  double voxel_size = 0.05;  ///< m; one point (mean position and colour) per occupied voxel
  double max_depth = 6.0;    ///< m; far depth is noisy (sigma grows with z^2)
  /// Occupied voxels at most (about 64 bytes each): the map grows with the space seen and, as
  /// the trajectory drifts, with the same walls seen again a little elsewhere (bench/
  /// estimator_soak.sh, 10,000 frames in one room: the process grew 31 MB with the map, 1 MB
  /// with --no-map); past this, new voxels are refused (counted) and the existing ones still
  /// average.
  std::size_t max_points = 1000000;
  /// Points of each trajectory line (the camera's, each object's) at most: one reaching it
  /// keeps every second point, so a long run keeps its whole extent at half the resolution
  /// (20,000 is 11 min of a 30 Hz camera at full resolution; 12 bytes a point).
  std::size_t max_track_points = 20000;
  /// staticPoints() (what System's map subscribers get) keeps only voxels hit in at least this
  /// many back-projected frames: a person's pixels that a missed detection let into the map come
  /// from one frame, and a navigator would take them for a wall. The saved scene keeps all.
  int min_frames = 1;
};

class MapSceneBuilder {
 public:
  explicit MapSceneBuilder(MapSceneOptions options = {});

  /// Takes the frame's camera pose, its object poses, and (every n-th posed frame) its static
  /// pixels: depth outside every object mask and outside the box of every track that has no
  /// mask this frame (a coasting track's object is still there, just not segmented).
  void addFrame(const core::Frame& frame);

  /// Writes the scene with COpenGLScene::saveToFile; throws std::runtime_error naming `path`.
  void save(const std::string& path) const;
  /// Inserts the same objects into `scene` (the live window's; cleared by the caller).
  void fill(mrpt::opengl::COpenGLScene& scene) const;

  /// The static map's points (one per voxel: mean position and colour) as an MRPT point map.
  std::shared_ptr<mrpt::maps::CColouredPointsMap> staticPoints() const;
  /// Frames back-projected into the static map so far: it changes when this does.
  std::size_t staticUpdates() const { return static_updates_; }

  std::size_t pointCount() const { return voxels_.size(); }
  /// Back-projected points that found no voxel because max_points was reached.
  std::size_t pointsRefused() const { return points_refused_; }
  std::size_t cameraPoses() const { return camera_.size(); }
  std::size_t objectTracks() const { return objects_.size(); }

 private:
  struct Voxel {
    Eigen::Vector3f position_sum = Eigen::Vector3f::Zero();
    Eigen::Vector3f bgr_sum = Eigen::Vector3f::Zero();
    std::uint32_t count = 0;
    std::uint32_t frames = 0;       // back-projected frames that hit it
    std::uint32_t last_update = 0;  // static_updates_ when it was last hit
  };
  void addStaticPoints(const core::Frame& frame);
  void appendToTrack(std::vector<Eigen::Vector3f>& track, const Eigen::Vector3f& point) const;

  MapSceneOptions options_;
  std::size_t posed_frames_ = 0;
  std::size_t points_refused_ = 0;
  std::size_t static_updates_ = 0;
  std::unordered_map<std::uint64_t, Voxel> voxels_;
  std::vector<Eigen::Vector3f> camera_;
  std::map<int, std::vector<Eigen::Vector3f>> objects_;
};

}  // namespace dynslam::viz
