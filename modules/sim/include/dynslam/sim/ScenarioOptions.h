#pragma once
// Everything a simulated sequence is made of, one core::Options struct per ini section, so a
// scenario is an ini file (params/sim/*.ini) and a sweep is a --set away. Unknown keys and
// sections are errors (core::loadOptionsStrict / rejectUnknownSections).
// Keys, ranges, meanings: describe() in ScenarioOptions.cpp and AugmentOptions.cpp;
// docs/parameters.md.
#include <dynslam/core/Config.h>
#include <dynslam/core/Options.h>
#include <dynslam/sim/AugmentOptions.h>
#include <dynslam/sim/CalibrationErrors.h>
#include <dynslam/sim/GnssSynthesizer.h>
#include <dynslam/sim/ImuSynthesizer.h>
#include <dynslam/sim/SensorNoise.h>

#include <string>

namespace dynslam::sim {

/// [Scenario]: the world and the sensor's image.
struct WorldOptions : core::Options {
  std::string scene = "room";
  int seed = 1;
  double duration = 30.0;
  double start_time = 1.7e9;
  double fps = 30.0;
  int width = 640, height = 480;
  double fx = 525, fy = 525, cx = 319.5, cy = 239.5;
  int render_threads = 0;
  double room_size_x = 5.0, room_size_y = 6.0, room_height = 2.8;
  int shelves = 4;
  int aisles = 4;
  double street_length = 150.0;
  double road_width = 10.0;
  double sidewalk_width = 4.0;

  void describe(core::OptionVisitor& v) override;
};

/// [Camera]: how the sensor moves and where the camera sits on the IMU (body) frame.
struct CameraMotionOptions : core::Options {
  std::string path = "orbit";
  double orbit_radius = 1.8;
  double orbit_period = 24.0;
  double height = 1.4;
  double speed = 1.5;
  double ramp = 2.0;
  double bob_amplitude = 0.04;
  double look_at_height = 1.2;
  double knot_interval = 0.25;
  double cam_x = 0.03, cam_y = -0.01, cam_z = 0.02;
  double cam_roll_deg = 0.5, cam_pitch_deg = -0.3, cam_yaw_deg = 0.2;

  void describe(core::OptionVisitor& v) override;
};

/// [People]: walkers and people standing still.
struct PeopleOptions : core::Options {
  int walkers = 3;
  int standing = 1;
  double speed = 1.2;
  std::string interaction = "high";
  double stride = 1.4;
  std::string waypoints;
  std::string appearance = "rendered";  ///< rendered | video (SpritePeople.h)
  std::string sprites;                  ///< the sprite bank for appearance = video

  void describe(core::OptionVisitor& v) override;
};

/// [Cars]: cars driving round the block and cars parked at the kerb (street).
struct CarOptions : core::Options {
  int driving = 0;
  int parked = 0;
  double speed = 8.0;
  std::string waypoints;

  void describe(core::OptionVisitor& v) override;
};

/// [Imu], [Gnss], [Noise] wrap the synthesizers' option structs.
struct ImuSectionOptions : core::Options {
  ImuNoiseOptions imu;
  void describe(core::OptionVisitor& v) override;
};

struct GnssSectionOptions : core::Options {
  bool enabled = false;
  GnssOptions gnss;
  void describe(core::OptionVisitor& v) override;
};

struct NoiseSectionOptions : core::Options {
  RgbdNoiseOptions rgbd;
  void describe(core::OptionVisitor& v) override;
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
  CalibrationErrorOptions calibration;  ///< [Calibration]

  /// Loads every section strictly, rejects sections no struct reads, and checks what spans
  /// sections (cars only in street and augment scenes, waypoints, [Augment] for augment).
  void load(const core::IniConfig& cfg);
};

}  // namespace dynslam::sim
