#include "dynslam/sim/ScenarioOptions.h"

#include "dynslam/sim/ScenarioPaths.h"

#include <dynslam/core/Config.h>

#include <utility>

namespace dynslam::sim {

using core::Range;

namespace {
constexpr core::Keyword<DepthModel> kDepthModels[] = {
    {"structured_light", DepthModel::StructuredLight}, {"stereo", DepthModel::Stereo}};
}  // namespace

void WorldOptions::describe(core::OptionVisitor& v) {
  const Range positive = Range::above(0), count = Range::atLeast(0);
  v.word("scene", scene, {"room", "corridor", "market", "street", "augment"},
         "room: a furnished room; corridor: a long narrow one with doors; market: a hall with "
         "aisles of shelves; street: a road between building rows with sidewalks; augment: a real "
         "sequence ([Augment]) with movers inserted");
  v.key("seed", seed, count, "seed of every random choice and of all noise");
  v.key("duration", duration, positive, "s");
  v.key("start_time", start_time, positive, "Unix time of the first frame (rawlog stamps), s");
  v.key("fps", fps, positive, "camera frames per second");
  v.key("width", width, Range::atLeast(1), "image width, px");
  v.key("height", height, Range::atLeast(1), "image height, px");
  v.key("fx", fx, positive, "focal length, px");
  v.key("fy", fy, positive, "focal length, px");
  v.key("cx", cx, Range::any(), "principal point, px");
  v.key("cy", cy, Range::any(), "principal point, px");
  v.key("render_threads", render_threads, count,
        "threads the rasterizer renders a frame with; 0: one per core (the pixels do not depend "
        "on it)");
  v.key("room_size_x", room_size_x, positive, "m (room, corridor, market hall)");
  v.key("room_size_y", room_size_y, positive, "m");
  v.key("room_height", room_height, positive, "m");
  v.key("shelves", shelves, count, "room: shelf units along the walls");
  v.key("aisles", aisles, count, "market: aisles between rows of shelves");
  v.key("street_length", street_length, positive, "m (street)");
  v.key("road_width", road_width, positive, "m: two lanes and two parking strips");
  v.key("sidewalk_width", sidewalk_width, positive, "m; facades stand behind the sidewalks");
}

void CameraMotionOptions::describe(core::OptionVisitor& v) {
  const Range positive = Range::above(0);
  v.word("path", path, {"orbit", "drive"},
         "orbit: handheld, circling the scene's centre; drive: a ground robot on the scene's "
         "route (street: out along one sidewalk and back; market: through the aisles; room: "
         "round the room), there and back as often as the duration needs");
  v.key("orbit_radius", orbit_radius, positive, "m (people keep 0.7 m inside this circle)");
  v.key("orbit_period", orbit_period, Range::any(),
        "s per turn (rotation rate = 360 / period deg/s; negative: the other way round)");
  v.key("height", height, Range::any(), "m; body (IMU) above the floor");
  v.key("speed", speed, positive, "m/s (drive)");
  v.key("ramp", ramp, Range::atLeast(0), "s of speed-up and slow-down at the route's ends (drive)");
  v.key("bob_amplitude", bob_amplitude, Range::any(), "m of vertical hand motion");
  v.key("look_at_height", look_at_height, Range::any(),
        "m; the camera looks across the room at this height");
  v.key("knot_interval", knot_interval, positive, "s between spline control points");
  v.key("cam_x", cam_x, Range::any(), "camera optical centre in the IMU frame, m");
  v.key("cam_y", cam_y, Range::any(), "m");
  v.key("cam_z", cam_z, Range::any(), "m");
  v.key("cam_roll_deg", cam_roll_deg, Range::any(),
        "extra camera rotation about the IMU x axis, on top of the axis change optical -> body, "
        "deg");
  v.key("cam_pitch_deg", cam_pitch_deg, Range::any(), "about y, deg");
  v.key("cam_yaw_deg", cam_yaw_deg, Range::any(), "about z, deg");
}

void PeopleOptions::describe(core::OptionVisitor& v) {
  v.key("walkers", walkers, Range::atLeast(0), "people walking");
  v.key("standing", standing, Range::atLeast(0),
        "people standing still (a dynamic class, not moving)");
  v.key("speed", speed, Range::above(0), "walking speed, m/s");
  v.word("interaction", interaction, {"high", "low"},
         "high: paths cross each other in front of the camera; low: along the walls");
  v.key("stride", stride, Range::above(0), "m per gait cycle (two steps)");
  v.key("waypoints", waypoints,
        "extra people (not in augment mode): one path per |-separated group of x,y floor points "
        "(m, world frame), walked back and forth at speed; one point: a person standing there; "
        "e.g. -2,0 2,0 | 0,-1.5");
  v.word("appearance", appearance, {"rendered", "video"},
         "rendered: textured bodies; video: real people's pixels from a sprite bank (sprites), "
         "each on a body-shaped surface at a height of 1.55-1.90 m");
  v.path("sprites", sprites,
         "the sprite bank folder for appearance = video (dynslam-sprites --out DIR; relative: "
         "from the working directory, else the ini's folder)");
  v.requires("sprites", !sprites.empty(), "appearance = video", appearance == "video");
}

void CarOptions::describe(core::OptionVisitor& v) {
  v.key("driving", driving, Range::atLeast(0), "cars driving round the block");
  v.key("parked", parked, Range::atLeast(0),
        "cars parked at the kerb (a dynamic class, not moving)");
  v.key("speed", speed, Range::above(0), "m/s");
  v.key("waypoints", waypoints,
        "extra cars, as [People] waypoints: a car drives its points round as a closed loop at "
        "speed; one point: a parked car (facing +x)");
}

void ImuSectionOptions::describe(core::OptionVisitor& v) {
  const Range density = Range::atLeast(0);
  v.key("rate_hz", imu.rate_hz, Range::above(0), "Hz");
  v.key("gyro_noise_density", imu.gyro_noise_density, density, "rad/s/sqrt(Hz)");
  v.key("gyro_bias_random_walk", imu.gyro_bias_random_walk, density, "rad/s^2/sqrt(Hz)");
  v.key("acc_noise_density", imu.acc_noise_density, density, "m/s^2/sqrt(Hz)");
  v.key("acc_bias_random_walk", imu.acc_bias_random_walk, density, "m/s^3/sqrt(Hz)");
  for (int i = 0; i < 3; ++i) {
    v.key(std::string("gyro_bias0_") + "xyz"[i], imu.gyro_bias0[i], Range::any(),
          "initial gyro bias, rad/s");
    v.key(std::string("acc_bias0_") + "xyz"[i], imu.acc_bias0[i], Range::any(),
          "initial acc bias, m/s^2");
  }
  v.key("gravity", imu.gravity, Range::atLeast(0), "m/s^2");
  v.key("noise", imu.noise, "false: exact measurements, constant biases");
}

void GnssSectionOptions::describe(core::OptionVisitor& v) {
  const Range sigma = Range::atLeast(0);
  v.key("enabled", enabled, "write GGA fixes (outdoor scenes)");
  v.key("rate_hz", gnss.rate_hz, Range::above(0), "Hz");
  v.key("origin_latitude_deg", gnss.origin_latitude_deg, Range::closed(-90, 90),
        "ENU origin = world origin, deg");
  v.key("origin_longitude_deg", gnss.origin_longitude_deg, Range::closed(-180, 180), "deg");
  v.key("origin_altitude_m", gnss.origin_altitude_m, Range::any(), "m");
  for (int i = 0; i < 3; ++i)
    v.key(std::string("lever_arm_") + "xyz"[i], gnss.lever_arm[i], Range::any(),
          "antenna in the IMU frame, m");
  v.key("horizontal_sigma", gnss.horizontal_sigma, sigma, "m (RTK-like 0.02; a plain GPS 1.5)");
  v.key("vertical_sigma", gnss.vertical_sigma, sigma, "m");
  v.key("fix_quality", gnss.fix_quality, Range::closed(0, 8),
        "GGA quality written (4 = RTK fixed)");
  v.key("satellites", gnss.satellites, Range::atLeast(0), "satellites in use written");
  v.key("hdop", gnss.hdop, Range::atLeast(0), "HDOP written");
}

void NoiseSectionOptions::describe(core::OptionVisitor& v) {
  const Range off = Range::atLeast(0);
  v.key("colour_sigma", rgbd.colour_sigma, off, "grey levels per channel");
  v.key("depth_sigma_z2", rgbd.depth_sigma_z2, off, "1/m: depth sigma = min + this * z^2");
  v.key("depth_sigma_min", rgbd.depth_sigma_min, off, "m");
  v.key("max_range", rgbd.max_range, Range::above(0), "m; farther depth is invalid (0)");
  v.key("min_range", rgbd.min_range, off, "m; nearer depth is invalid (0)");
  v.key("edge_jump", rgbd.edge_jump, Range::above(0),
        "m; depth steps larger than this leave holes");
  v.key("edge_hole_width", rgbd.edge_hole_width, off, "px removed beside such a step");
  v.key("depth_model", rgbd.depth_model, kDepthModels,
        "structured_light: sigma = min + depth_sigma_z2 z^2 (Kinect-like); stereo: sigma = min + "
        "z^2 disparity_sigma / (fx stereo_baseline), and the background left of near objects "
        "that the right imager cannot see is a hole (RealSense D4xx-like)");
  v.key("stereo_baseline", rgbd.stereo_baseline, Range::above(0), "m (stereo)");
  v.key("disparity_sigma", rgbd.disparity_sigma, Range::above(0), "px (stereo)");
  const bool stereo = rgbd.depth_model == DepthModel::Stereo;
  const RgbdNoiseOptions defaults;
  v.requires("stereo_baseline", rgbd.stereo_baseline != defaults.stereo_baseline,
             "depth_model = stereo", stereo);
  v.requires("disparity_sigma", rgbd.disparity_sigma != defaults.disparity_sigma,
             "depth_model = stereo", stereo);
  v.requires("depth_sigma_z2", rgbd.depth_sigma_z2 != defaults.depth_sigma_z2,
             "depth_model = structured_light", !stereo);
}

void ScenarioOptions::load(const core::IniConfig& cfg) {
  core::loadOptionsStrict(world, cfg, "Scenario");
  core::loadOptionsStrict(camera, cfg, "Camera");
  core::loadOptionsStrict(people, cfg, "People");
  core::loadOptionsStrict(cars, cfg, "Cars");
  core::loadOptionsStrict(imu, cfg, "Imu");
  core::loadOptionsStrict(gnss, cfg, "Gnss");
  core::loadOptionsStrict(noise, cfg, "Noise");
  noise.rgbd.focal_px = world.fx;
  core::loadOptionsStrict(augment, cfg, "Augment");
  core::loadOptionsStrict(calibration, cfg, "Calibration");
  calibration.seed = world.seed;
  core::rejectUnknownSections(cfg, {"Scenario", "Camera", "People", "Cars", "Imu", "Gnss", "Noise",
                                    "Augment", "Calibration"});
  const auto& scene = world.scene;
  if (people.appearance == "video" && people.sprites.empty())
    throw core::ConfigError("[People] in " + cfg.source() +
                            ": appearance = video needs sprites = DIR (a sprite bank made by "
                            "dynslam-sprites --video FILE --out DIR)");
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
}

}  // namespace dynslam::sim
