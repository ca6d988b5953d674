#pragma once
// What System hands an embedding program. The pose and map updates are shaped like MOLA's
// LocalizationSourceBase / MapSourceBase updates (timestamp, reference frame, pose with an
// optional covariance; a named metric map), so a thin MOLA module can forward them; we do not
// depend on MOLA (it is not in Debian 12).
#include <mrpt/core/Clock.h>
#include <mrpt/math/CMatrixFixed.h>
#include <mrpt/math/TPoint3D.h>
#include <mrpt/math/TPose3D.h>

#include <memory>
#include <optional>
#include <string>

namespace mrpt::maps {
class CMetricMap;
}

namespace dynslam::system {

/// The camera's pose in the map after one frame.
struct LocalizationUpdate {
  mrpt::Clock::time_point timestamp;  ///< the RGB-D observation's stamp
  std::string reference_frame = "map";
  std::string method = "dynslam";
  /// The colour camera's optical frame (x right, y down, z forward), as trajectory.tum holds it.
  std::string child_frame = "camera";
  mrpt::math::TPose3D pose;
  /// Not estimated yet (the window's marginals are not computed): always empty today.
  std::optional<mrpt::math::CMatrixDouble66> cov;
};

/// The static point map (every moving object's pixels left out), voxel means in the map frame.
struct MapUpdate {
  mrpt::Clock::time_point timestamp;
  std::string reference_frame = "map";
  std::string method = "dynslam";
  std::string map_name = "static_points";
  std::shared_ptr<mrpt::maps::CMetricMap> map;  ///< a mrpt::maps::CColouredPointsMap
};

/// An object the system follows, as a planner reads it. With the ObjectStates stage in the
/// pipeline (params/sim_vio.ini has it) these are its filtered states: the body's centre,
/// velocity and their covariance, kept through short occlusions. Without it, each object the
/// estimator poses (its rigid set's centroid), with the velocity from its last two poses.
struct MovingObject {
  /// Stable while followed, never reused in a run: the state's id (ObjectStates), else the
  /// tracker's id.
  int id = -1;
  std::string category;  ///< "person", "car", ... (the ini's Detection.class_map)
  /// In the map: the body's centre with the map's axes (ObjectStates), else the object's frame.
  mrpt::math::TPose3D pose;
  mrpt::math::TPoint3D velocity;  ///< m/s in the map
  /// m: width (across the line of sight), height and depth (along it). ObjectStates: the
  /// state's, its depth assumed from the width; else the tracker's box width and height at the
  /// object's depth, and that width again as its depth.
  mrpt::math::TPoint3D extent;
  /// Of (centre, velocity) in the map's axes, m and m/s (ObjectStates only).
  std::optional<mrpt::math::CMatrixDouble66> cov;
  bool moving = false;    ///< faster than [ObjectStates] moving_speed (ObjectStates only)
  bool measured = false;  ///< seen in the last frame, else predicted (ObjectStates only)
  mrpt::Clock::time_point last_seen;  ///< stamp of the last frame that measured or posed it
};

enum class TrackingStatus {
  Initializing,   ///< no pose yet
  Tracking,       ///< the last frame was posed
  LostRestarting  ///< a pose was estimated before, but the last frame was not posed, or the
                  ///< window restarted at it
};

/// "initializing", "tracking" or "lost_restarting".
const char* toString(TrackingStatus status);

}  // namespace dynslam::system
