#include "dynslam/sim/ScenarioOptions.h"

#include "dynslam/sim/ScenarioPaths.h"

#include <dynslam/core/Config.h>

#include <mrpt/config/CConfigFileBase.h>

#include <utility>

// Nested option structs have keys that differ from their C++ names, so the MRPT_*_CONFIG_VAR
// macros (which use the variable's spelling) do not fit; these keep one line per key.
#define SIM_READ(type, field, key) field = c.read_##type(s, key, field)
#define SIM_WRITE(field, key, comment) core::writeKey(c, s, key, field, comment)

namespace dynslam::sim {

void WorldOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& c,
                                      const std::string& s) {
  MRPT_LOAD_CONFIG_VAR(scene, string, c, s);
  MRPT_LOAD_CONFIG_VAR(seed, uint64_t, c, s);
  MRPT_LOAD_CONFIG_VAR(duration, double, c, s);
  MRPT_LOAD_CONFIG_VAR(start_time, double, c, s);
  MRPT_LOAD_CONFIG_VAR(fps, double, c, s);
  MRPT_LOAD_CONFIG_VAR(width, int, c, s);
  MRPT_LOAD_CONFIG_VAR(height, int, c, s);
  MRPT_LOAD_CONFIG_VAR(fx, double, c, s);
  MRPT_LOAD_CONFIG_VAR(fy, double, c, s);
  MRPT_LOAD_CONFIG_VAR(cx, double, c, s);
  MRPT_LOAD_CONFIG_VAR(cy, double, c, s);
  MRPT_LOAD_CONFIG_VAR(render_threads, int, c, s);
  MRPT_LOAD_CONFIG_VAR(room_size_x, double, c, s);
  MRPT_LOAD_CONFIG_VAR(room_size_y, double, c, s);
  MRPT_LOAD_CONFIG_VAR(room_height, double, c, s);
  MRPT_LOAD_CONFIG_VAR(shelves, int, c, s);
  MRPT_LOAD_CONFIG_VAR(aisles, int, c, s);
  MRPT_LOAD_CONFIG_VAR(street_length, double, c, s);
  MRPT_LOAD_CONFIG_VAR(road_width, double, c, s);
  MRPT_LOAD_CONFIG_VAR(sidewalk_width, double, c, s);
}

void WorldOptions::saveToConfigFile(mrpt::config::CConfigFileBase& c, const std::string& s) const {
  MRPT_SAVE_CONFIG_VAR_COMMENT(scene, "room | corridor | market | street | augment");
  MRPT_SAVE_CONFIG_VAR_COMMENT(seed, "seed of every random choice and of all noise");
  MRPT_SAVE_CONFIG_VAR_COMMENT(duration, "s");
  MRPT_SAVE_CONFIG_VAR_COMMENT(start_time, "Unix time of the first frame, s");
  MRPT_SAVE_CONFIG_VAR_COMMENT(fps, "camera frames per second");
  MRPT_SAVE_CONFIG_VAR_COMMENT(width, "image width, px");
  MRPT_SAVE_CONFIG_VAR_COMMENT(height, "image height, px");
  MRPT_SAVE_CONFIG_VAR_COMMENT(fx, "focal length, px");
  MRPT_SAVE_CONFIG_VAR_COMMENT(fy, "focal length, px");
  MRPT_SAVE_CONFIG_VAR_COMMENT(cx, "principal point, px");
  MRPT_SAVE_CONFIG_VAR_COMMENT(cy, "principal point, px");
  MRPT_SAVE_CONFIG_VAR_COMMENT(render_threads, "0: one per core (the pixels do not depend on it)");
  MRPT_SAVE_CONFIG_VAR_COMMENT(room_size_x, "m (room, corridor, market hall)");
  MRPT_SAVE_CONFIG_VAR_COMMENT(room_size_y, "m");
  MRPT_SAVE_CONFIG_VAR_COMMENT(room_height, "m");
  MRPT_SAVE_CONFIG_VAR_COMMENT(shelves, "room: shelf units along the walls");
  MRPT_SAVE_CONFIG_VAR_COMMENT(aisles, "market: aisles between rows of shelves");
  MRPT_SAVE_CONFIG_VAR_COMMENT(street_length, "m (street)");
  MRPT_SAVE_CONFIG_VAR_COMMENT(road_width, "m: two lanes and two parking strips");
  MRPT_SAVE_CONFIG_VAR_COMMENT(sidewalk_width, "m; facades stand behind the sidewalks");
}

void CameraMotionOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& c,
                                             const std::string& s) {
  MRPT_LOAD_CONFIG_VAR(path, string, c, s);
  MRPT_LOAD_CONFIG_VAR(orbit_radius, double, c, s);
  MRPT_LOAD_CONFIG_VAR(orbit_period, double, c, s);
  MRPT_LOAD_CONFIG_VAR(height, double, c, s);
  MRPT_LOAD_CONFIG_VAR(speed, double, c, s);
  MRPT_LOAD_CONFIG_VAR(ramp, double, c, s);
  MRPT_LOAD_CONFIG_VAR(bob_amplitude, double, c, s);
  MRPT_LOAD_CONFIG_VAR(look_at_height, double, c, s);
  MRPT_LOAD_CONFIG_VAR(knot_interval, double, c, s);
  MRPT_LOAD_CONFIG_VAR(cam_x, double, c, s);
  MRPT_LOAD_CONFIG_VAR(cam_y, double, c, s);
  MRPT_LOAD_CONFIG_VAR(cam_z, double, c, s);
  MRPT_LOAD_CONFIG_VAR(cam_roll_deg, double, c, s);
  MRPT_LOAD_CONFIG_VAR(cam_pitch_deg, double, c, s);
  MRPT_LOAD_CONFIG_VAR(cam_yaw_deg, double, c, s);
}

void CameraMotionOptions::saveToConfigFile(mrpt::config::CConfigFileBase& c,
                                           const std::string& s) const {
  MRPT_SAVE_CONFIG_VAR_COMMENT(path, "orbit (handheld, circling) | drive (robot on the route)");
  MRPT_SAVE_CONFIG_VAR_COMMENT(orbit_radius, "m");
  MRPT_SAVE_CONFIG_VAR_COMMENT(orbit_period, "s per turn");
  MRPT_SAVE_CONFIG_VAR_COMMENT(height, "m; body (IMU) above the floor");
  MRPT_SAVE_CONFIG_VAR_COMMENT(speed, "m/s (drive)");
  MRPT_SAVE_CONFIG_VAR_COMMENT(ramp, "s of speed-up and slow-down (drive)");
  MRPT_SAVE_CONFIG_VAR_COMMENT(bob_amplitude, "m of vertical hand motion");
  MRPT_SAVE_CONFIG_VAR_COMMENT(look_at_height, "m; height of the point looked at");
  MRPT_SAVE_CONFIG_VAR_COMMENT(knot_interval, "s between spline control points");
  MRPT_SAVE_CONFIG_VAR_COMMENT(cam_x, "camera centre in the IMU frame, m");
  MRPT_SAVE_CONFIG_VAR_COMMENT(cam_y, "m");
  MRPT_SAVE_CONFIG_VAR_COMMENT(cam_z, "m");
  MRPT_SAVE_CONFIG_VAR_COMMENT(cam_roll_deg, "extra camera rotation about the IMU x axis, deg");
  MRPT_SAVE_CONFIG_VAR_COMMENT(cam_pitch_deg, "about y, deg");
  MRPT_SAVE_CONFIG_VAR_COMMENT(cam_yaw_deg, "about z, deg");
}

void PeopleOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& c,
                                       const std::string& s) {
  MRPT_LOAD_CONFIG_VAR(walkers, int, c, s);
  MRPT_LOAD_CONFIG_VAR(standing, int, c, s);
  MRPT_LOAD_CONFIG_VAR(speed, double, c, s);
  MRPT_LOAD_CONFIG_VAR(interaction, string, c, s);
  MRPT_LOAD_CONFIG_VAR(stride, double, c, s);
  MRPT_LOAD_CONFIG_VAR(waypoints, string, c, s);
}

void PeopleOptions::saveToConfigFile(mrpt::config::CConfigFileBase& c, const std::string& s) const {
  MRPT_SAVE_CONFIG_VAR_COMMENT(walkers, "people walking");
  MRPT_SAVE_CONFIG_VAR_COMMENT(standing, "people standing still (a dynamic class, not moving)");
  MRPT_SAVE_CONFIG_VAR_COMMENT(speed, "walking speed, m/s");
  MRPT_SAVE_CONFIG_VAR_COMMENT(interaction,
                               "high: paths cross each other in front of the camera; low: along "
                               "the walls");
  MRPT_SAVE_CONFIG_VAR_COMMENT(stride, "m per gait cycle (two steps)");
  MRPT_SAVE_CONFIG_VAR_COMMENT(waypoints, "extra people: x,y x,y | x,y (one point: standing)");
}

void CarOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& c, const std::string& s) {
  MRPT_LOAD_CONFIG_VAR(driving, int, c, s);
  MRPT_LOAD_CONFIG_VAR(parked, int, c, s);
  MRPT_LOAD_CONFIG_VAR(speed, double, c, s);
  MRPT_LOAD_CONFIG_VAR(waypoints, string, c, s);
}

void CarOptions::saveToConfigFile(mrpt::config::CConfigFileBase& c, const std::string& s) const {
  MRPT_SAVE_CONFIG_VAR_COMMENT(driving, "cars driving round the block");
  MRPT_SAVE_CONFIG_VAR_COMMENT(parked, "cars parked at the kerb (a dynamic class, not moving)");
  MRPT_SAVE_CONFIG_VAR_COMMENT(speed, "m/s");
  MRPT_SAVE_CONFIG_VAR_COMMENT(waypoints, "extra cars: x,y x,y x,y (a loop) | x,y (parked)");
}

void ImuSectionOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& c,
                                           const std::string& s) {
  SIM_READ(double, imu.rate_hz, "rate_hz");
  SIM_READ(double, imu.gyro_noise_density, "gyro_noise_density");
  SIM_READ(double, imu.gyro_bias_random_walk, "gyro_bias_random_walk");
  SIM_READ(double, imu.acc_noise_density, "acc_noise_density");
  SIM_READ(double, imu.acc_bias_random_walk, "acc_bias_random_walk");
  for (int i = 0; i < 3; ++i) {
    SIM_READ(double, imu.gyro_bias0[i], std::string("gyro_bias0_") + "xyz"[i]);
    SIM_READ(double, imu.acc_bias0[i], std::string("acc_bias0_") + "xyz"[i]);
  }
  SIM_READ(double, imu.gravity, "gravity");
  SIM_READ(bool, imu.noise, "noise");
}

void ImuSectionOptions::saveToConfigFile(mrpt::config::CConfigFileBase& c,
                                         const std::string& s) const {
  SIM_WRITE(imu.rate_hz, "rate_hz", "Hz");
  SIM_WRITE(imu.gyro_noise_density, "gyro_noise_density", "rad/s/sqrt(Hz)");
  SIM_WRITE(imu.gyro_bias_random_walk, "gyro_bias_random_walk", "rad/s^2/sqrt(Hz)");
  SIM_WRITE(imu.acc_noise_density, "acc_noise_density", "m/s^2/sqrt(Hz)");
  SIM_WRITE(imu.acc_bias_random_walk, "acc_bias_random_walk", "m/s^3/sqrt(Hz)");
  for (int i = 0; i < 3; ++i) {
    SIM_WRITE(imu.gyro_bias0[i], std::string("gyro_bias0_") + "xyz"[i], "initial gyro bias, rad/s");
    SIM_WRITE(imu.acc_bias0[i], std::string("acc_bias0_") + "xyz"[i], "initial acc bias, m/s^2");
  }
  SIM_WRITE(imu.gravity, "gravity", "m/s^2");
  SIM_WRITE(imu.noise, "noise", "false: exact measurements, constant biases");
}

void GnssSectionOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& c,
                                            const std::string& s) {
  SIM_READ(bool, enabled, "enabled");
  SIM_READ(double, gnss.rate_hz, "rate_hz");
  SIM_READ(double, gnss.origin_latitude_deg, "origin_latitude_deg");
  SIM_READ(double, gnss.origin_longitude_deg, "origin_longitude_deg");
  SIM_READ(double, gnss.origin_altitude_m, "origin_altitude_m");
  for (int i = 0; i < 3; ++i)
    SIM_READ(double, gnss.lever_arm[i], std::string("lever_arm_") + "xyz"[i]);
  SIM_READ(double, gnss.horizontal_sigma, "horizontal_sigma");
  SIM_READ(double, gnss.vertical_sigma, "vertical_sigma");
  SIM_READ(int, gnss.fix_quality, "fix_quality");
  SIM_READ(int, gnss.satellites, "satellites");
  SIM_READ(double, gnss.hdop, "hdop");
}

void GnssSectionOptions::saveToConfigFile(mrpt::config::CConfigFileBase& c,
                                          const std::string& s) const {
  SIM_WRITE(enabled, "enabled", "write GGA fixes (outdoor scenes)");
  SIM_WRITE(gnss.rate_hz, "rate_hz", "Hz");
  SIM_WRITE(gnss.origin_latitude_deg, "origin_latitude_deg", "ENU origin = world origin");
  SIM_WRITE(gnss.origin_longitude_deg, "origin_longitude_deg", "deg");
  SIM_WRITE(gnss.origin_altitude_m, "origin_altitude_m", "m");
  for (int i = 0; i < 3; ++i)
    SIM_WRITE(gnss.lever_arm[i], std::string("lever_arm_") + "xyz"[i],
              "antenna in the IMU frame, m");
  SIM_WRITE(gnss.horizontal_sigma, "horizontal_sigma", "m");
  SIM_WRITE(gnss.vertical_sigma, "vertical_sigma", "m");
  SIM_WRITE(gnss.fix_quality, "fix_quality", "GGA quality written (4 = RTK fixed)");
  SIM_WRITE(gnss.satellites, "satellites", "satellites in use written");
  SIM_WRITE(gnss.hdop, "hdop", "HDOP written");
}

void NoiseSectionOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& c,
                                             const std::string& s) {
  SIM_READ(double, rgbd.colour_sigma, "colour_sigma");
  SIM_READ(double, rgbd.depth_sigma_z2, "depth_sigma_z2");
  SIM_READ(double, rgbd.depth_sigma_min, "depth_sigma_min");
  SIM_READ(double, rgbd.max_range, "max_range");
  SIM_READ(double, rgbd.min_range, "min_range");
  SIM_READ(double, rgbd.edge_jump, "edge_jump");
  SIM_READ(int, rgbd.edge_hole_width, "edge_hole_width");
}

void NoiseSectionOptions::saveToConfigFile(mrpt::config::CConfigFileBase& c,
                                           const std::string& s) const {
  SIM_WRITE(rgbd.colour_sigma, "colour_sigma", "grey levels per channel");
  SIM_WRITE(rgbd.depth_sigma_z2, "depth_sigma_z2", "1/m: depth sigma = min + this * z^2");
  SIM_WRITE(rgbd.depth_sigma_min, "depth_sigma_min", "m");
  SIM_WRITE(rgbd.max_range, "max_range", "m; farther depth is invalid (0)");
  SIM_WRITE(rgbd.min_range, "min_range", "m; nearer depth is invalid (0)");
  SIM_WRITE(rgbd.edge_jump, "edge_jump", "m; depth steps larger than this leave holes");
  SIM_WRITE(rgbd.edge_hole_width, "edge_hole_width", "px removed beside such a step");
}

void ScenarioOptions::load(const core::IniConfig& cfg) {
  core::loadOptionsStrict(world, cfg, "Scenario");
  core::loadOptionsStrict(camera, cfg, "Camera");
  core::loadOptionsStrict(people, cfg, "People");
  core::loadOptionsStrict(cars, cfg, "Cars");
  core::loadOptionsStrict(imu, cfg, "Imu");
  core::loadOptionsStrict(gnss, cfg, "Gnss");
  core::loadOptionsStrict(noise, cfg, "Noise");
  core::loadOptionsStrict(augment, cfg, "Augment");
  core::rejectUnknownSections(
      cfg, {"Scenario", "Camera", "People", "Cars", "Imu", "Gnss", "Noise", "Augment"});
  const auto& scene = world.scene;
  if (scene != "room" && scene != "corridor" && scene != "market" && scene != "street" &&
      scene != "augment")
    throw core::ConfigError("[Scenario] scene = '" + scene + "' in " + cfg.source() +
                            ": expected room, corridor, market, street or augment");
  if (scene != "street" && scene != "augment" && (cars.driving > 0 || cars.parked > 0))
    throw core::ConfigError("[Cars] in " + cfg.source() + ": cars drive and park in the street " +
                            "(and augment) scenes, not in scene = " + scene);
  for (const auto& [section, text] :
       {std::pair{"People", people.waypoints}, std::pair{"Cars", cars.waypoints}}) {
    try {
      parseWaypointList(text);
    } catch (const std::invalid_argument& e) {
      throw core::ConfigError("[" + std::string(section) + "] waypoints in " + cfg.source() + ": " +
                              e.what());
    }
    if (scene == "augment" && !text.empty())
      throw core::ConfigError("[" + std::string(section) + "] waypoints in " + cfg.source() +
                              ": augment mode places its movers on the real floor itself");
  }
  if (scene == "augment") {
    try {
      augment.validate();
    } catch (const core::ConfigError& e) {
      throw core::ConfigError(std::string(e.what()) + " in " + cfg.source());
    }
  }
  if (people.interaction != "high" && people.interaction != "low")
    throw core::ConfigError("[People] interaction = '" + people.interaction + "' in " +
                            cfg.source() + ": expected high or low");
  if (camera.path != "orbit" && camera.path != "drive")
    throw core::ConfigError("[Camera] path = '" + camera.path + "' in " + cfg.source() +
                            ": expected orbit or drive");
}

}  // namespace dynslam::sim
