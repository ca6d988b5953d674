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

/// An object the estimator follows (objects/<id>.tum), as a planner reads it.
struct MovingObject {
  int id = -1;                    ///< the tracker's id: stable while tracked, never reused in a run
  std::string category;           ///< "person", "car", ... (the ini's Detection.class_map)
  mrpt::math::TPose3D pose;       ///< the object's frame in the map (its rigid set's centroid)
  mrpt::math::TPoint3D velocity;  ///< m/s in the map, from its last two poses (0 with one)
  /// m: width and height of the tracker's box at the object's depth, and that width again as
  /// its depth (a box sees no thickness).
  mrpt::math::TPoint3D extent;
  mrpt::Clock::time_point last_seen;  ///< stamp of the last frame that posed it
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
