#pragma once
// NMEA GGA-like fixes from a trajectory whose world frame is ENU at a geodetic origin: the
// antenna position (lever arm in the body frame) converted to latitude/longitude/altitude,
// with horizontal and vertical noise.
#include <dynslam/sim/SplineTrajectory.h>

#include <random>
#include <vector>

namespace dynslam::sim {

struct GnssOptions {
  double rate_hz = 10.0;
  double origin_latitude_deg = 36.7213;  ///< ENU origin (the world frame's origin)
  double origin_longitude_deg = -4.4214;
  double origin_altitude_m = 50.0;
  Eigen::Vector3d lever_arm = Eigen::Vector3d(0, 0, 0.5);  ///< antenna in the body frame, m
  double horizontal_sigma = 0.02;                          ///< m (RTK-like); 1.5 for a plain GPS
  double vertical_sigma = 0.04;                            ///< m
  int fix_quality = 4;                                     ///< GGA quality written (4 = RTK fixed)
  int satellites = 14;
  double hdop = 0.8;
};

struct GnssFixSample {
  double t = 0;
  double latitude_deg = 0, longitude_deg = 0, altitude_m = 0;
  Eigen::Vector3d enu_true = Eigen::Vector3d::Zero();  ///< antenna position without noise
  int fix_quality = 0, satellites = 0;
  double hdop = 0;
};

/// Samples at uniformSampleTimes(t0, t1, options.rate_hz) (t0, t0 + 1/rate, ... <= t1). Each
/// fix: enu_true = T_world_body(t) * lever_arm (world = ENU at the origin); the reported
/// position is enu_true + (N(0, horizontal_sigma), N(0, horizontal_sigma), N(0, vertical_sigma))
/// on (E, N, U), converted ENU -> geocentric -> geodetic on WGS84 (ENU axes with up = the
/// ellipsoid normal, as mrpt::topography::geodeticToENU_WGS84 uses, which therefore recovers the
/// position to well below a millimetre, also kilometres away). The rng is consumed in a fixed order
/// (E, N, U per fix, even when a sigma is 0), so a seed reproduces the sequence. Throws
/// std::invalid_argument for a bad rate, range, negative sigma or an origin off the globe, and
/// std::out_of_range when [t0, t1] is not inside the trajectory's time range.
std::vector<GnssFixSample> synthesizeGnss(const SplineTrajectory& trajectory, double t0, double t1,
                                          const GnssOptions& options, std::mt19937_64& rng);

}  // namespace dynslam::sim
