#pragma once
// Everything a simulated sequence is made of, one CLoadableOptions struct per ini section, so a
// scenario is an ini file (params/sim/*.ini) and a sweep is a --set away. Unknown keys and
// sections are errors (core::loadOptionsStrict / rejectUnknownSections).
#include <dynslam/core/Config.h>
#include <dynslam/sim/AugmentOptions.h>
#include <dynslam/sim/GnssSynthesizer.h>
#include <dynslam/sim/ImuSynthesizer.h>
#include <dynslam/sim/SensorNoise.h>

#include <mrpt/config/CLoadableOptions.h>

#include <string>

namespace dynslam::sim {

/// [Scenario]: the world and the sensor's image.
struct WorldOptions : mrpt::config::CLoadableOptions {
  /// room: a furnished room; corridor: a long narrow one with doors; market: a hall with
  /// aisles of shelves; street: a road between building rows with sidewalks; augment: a real
  /// sequence ([Augment]) with movers inserted.
  std::string scene = "room";
  uint64_t seed = 1;          ///< every random choice and all noise derive from it
  double duration = 30.0;     ///< s
  double start_time = 1.7e9;  ///< s since the Unix epoch of the first frame (rawlog stamps)
  double fps = 30.0;
  int width = 640, height = 480;
  double fx = 525, fy = 525, cx = 319.5, cy = 239.5;
  /// Threads the rasterizer renders a frame with (0: one per core). The pixels do not depend
  /// on it.
  int render_threads = 0;
  double room_size_x = 5.0, room_size_y = 6.0,
         room_height = 2.8;      ///< m (room, corridor, market hall)
  int shelves = 4;               ///< room: shelf units along the walls
  int aisles = 4;                ///< market: aisles between rows of shelves
  double street_length = 150.0;  ///< m (street)
  double road_width = 10.0;      ///< m: two lanes plus a parking strip on each side
  double sidewalk_width = 4.0;   ///< m; building facades stand behind the sidewalks

  void loadFromConfigFile(const mrpt::config::CConfigFileBase& c, const std::string& s) override;
  void saveToConfigFile(mrpt::config::CConfigFileBase& c, const std::string& s) const override;
};

/// [Camera]: how the sensor moves and where the camera sits on the IMU (body) frame.
struct CameraMotionOptions : mrpt::config::CLoadableOptions {
  /// orbit: handheld, circling the scene's centre; drive: a ground robot following the
  /// scene's route (street: out along one sidewalk and back; market: through the aisles; room:
  /// round the room), repeated there and back as often as the duration needs.
  std::string path = "orbit";
  double orbit_radius = 1.8;    ///< m (people keep 0.7 m inside this circle)
  double orbit_period = 24.0;   ///< s per turn (rotation rate = 360 / period deg/s)
  double height = 1.4;          ///< m; body (IMU) height above the floor
  double speed = 1.5;           ///< m/s (drive)
  double ramp = 2.0;            ///< s of smooth speed-up and slow-down at the route's ends (drive)
  double bob_amplitude = 0.04;  ///< m of vertical hand motion
  double look_at_height = 1.2;  ///< m; the camera looks across the room at this height
  double knot_interval = 0.25;  ///< s between spline control points
  /// Camera optical centre in the IMU frame (m) and a small extra rotation (deg, roll pitch
  /// yaw about the IMU axes) on top of the axis change optical -> body.
  double cam_x = 0.03, cam_y = -0.01, cam_z = 0.02;
  double cam_roll_deg = 0.5, cam_pitch_deg = -0.3, cam_yaw_deg = 0.2;

  void loadFromConfigFile(const mrpt::config::CConfigFileBase& c, const std::string& s) override;
  void saveToConfigFile(mrpt::config::CConfigFileBase& c, const std::string& s) const override;
};

/// [People]: walkers and people standing still.
struct PeopleOptions : mrpt::config::CLoadableOptions {
  int walkers = 3;
  int standing = 1;
  double speed = 1.2;                ///< m/s
  std::string interaction = "high";  ///< high: paths cross in front of the camera; low: along walls
  double stride = 1.4;               ///< m per gait cycle (two steps)
  /// People on paths of your own, besides the generated ones (not in augment mode): one path per
  /// `|`-separated group of "x,y" floor points (m, world frame), walked back and forth at
  /// `speed`; a single point is a person standing there. E.g. "-2,0 2,0 | 0,-1.5".
  std::string waypoints;

  void loadFromConfigFile(const mrpt::config::CConfigFileBase& c, const std::string& s) override;
  void saveToConfigFile(mrpt::config::CConfigFileBase& c, const std::string& s) const override;
};

/// [Cars]: cars driving round the block and cars parked at the kerb (street).
struct CarOptions : mrpt::config::CLoadableOptions {
  int driving = 0;
  int parked = 0;
  double speed = 8.0;  ///< m/s
  /// Cars on routes of your own, as [People] waypoints; a car drives its points round as a
  /// closed loop at `speed`, a single point is a parked car (facing +x).
  std::string waypoints;

  void loadFromConfigFile(const mrpt::config::CConfigFileBase& c, const std::string& s) override;
  void saveToConfigFile(mrpt::config::CConfigFileBase& c, const std::string& s) const override;
};

/// [Imu], [Gnss], [Noise] wrap the synthesizers' option structs.
struct ImuSectionOptions : mrpt::config::CLoadableOptions {
  ImuNoiseOptions imu;
  void loadFromConfigFile(const mrpt::config::CConfigFileBase& c, const std::string& s) override;
  void saveToConfigFile(mrpt::config::CConfigFileBase& c, const std::string& s) const override;
};

struct GnssSectionOptions : mrpt::config::CLoadableOptions {
  bool enabled = false;
  GnssOptions gnss;
  void loadFromConfigFile(const mrpt::config::CConfigFileBase& c, const std::string& s) override;
  void saveToConfigFile(mrpt::config::CConfigFileBase& c, const std::string& s) const override;
};

struct NoiseSectionOptions : mrpt::config::CLoadableOptions {
  RgbdNoiseOptions rgbd;
  void loadFromConfigFile(const mrpt::config::CConfigFileBase& c, const std::string& s) override;
  void saveToConfigFile(mrpt::config::CConfigFileBase& c, const std::string& s) const override;
};

struct ScenarioOptions {
  WorldOptions world;
  CameraMotionOptions camera;
  PeopleOptions people;
  CarOptions cars;
  ImuSectionOptions imu;
  GnssSectionOptions gnss;
  NoiseSectionOptions noise;
  AugmentOptions augment;

  /// Loads every section strictly and rejects sections no struct reads.
  void load(const core::IniConfig& cfg);
};

}  // namespace dynslam::sim
