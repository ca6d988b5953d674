#include <dynslam/sim/GnssSynthesizer.h>

#include <mrpt/topography/conversions.h>

#include <cmath>
#include <stdexcept>
#include <string>

namespace dynslam::sim {
namespace {

constexpr double kDegToRad = 3.14159265358979323846 / 180;

void validate(const GnssOptions& o) {
  if (!(o.horizontal_sigma >= 0) || !(o.vertical_sigma >= 0) ||
      !std::isfinite(o.horizontal_sigma) || !std::isfinite(o.vertical_sigma)) {
    throw std::invalid_argument(
        "synthesizeGnss: horizontal_sigma and vertical_sigma must be >= 0 "
        "and finite");
  }
  if (!(std::abs(o.origin_latitude_deg) <= 90) || !(std::abs(o.origin_longitude_deg) <= 360) ||
      !std::isfinite(o.origin_altitude_m)) {
    throw std::invalid_argument(
        "synthesizeGnss: the geodetic origin is not a valid "
        "latitude/longitude/altitude");
  }
  if (!o.lever_arm.allFinite()) throw std::invalid_argument("synthesizeGnss: lever_arm not finite");
}

/// ENU (at a geodetic origin) -> geocentric, with the ENU axes of geodeticToENU_WGS84 (up = the
/// ellipsoid normal), so that function inverts it exactly. MRPT 2.5's ENUToGeocentric cannot be
/// used: it takes "up" along the geocentric direction of the origin, which is tilted ~0.19 deg
/// from the normal at mid latitudes (1.5 cm error at 5 m from the origin, 0.7 m at 1 km).
class EnuToGeocentric {
 public:
  EnuToGeocentric(const mrpt::topography::TGeodeticCoords& origin,
                  const mrpt::topography::TEllipsoid& ellipsoid) {
    mrpt::topography::TGeocentricCoords origin_geocentric;
    mrpt::topography::geodeticToGeocentric(origin, origin_geocentric, ellipsoid);
    origin_ << origin_geocentric.x, origin_geocentric.y, origin_geocentric.z;
    const double lat = origin.lat.getDecimalValue() * kDegToRad;
    const double lon = origin.lon.getDecimalValue() * kDegToRad;
    const double slat = std::sin(lat), clat = std::cos(lat);
    const double slon = std::sin(lon), clon = std::cos(lon);
    axes_.col(0) << -slon, clon, 0;                    // east
    axes_.col(1) << -slat * clon, -slat * slon, clat;  // north
    axes_.col(2) << clat * clon, clat * slon, slat;    // up
  }
  mrpt::topography::TGeocentricCoords operator()(const Eigen::Vector3d& enu) const {
    const Eigen::Vector3d p = origin_ + axes_ * enu;
    return {p.x(), p.y(), p.z()};
  }

 private:
  Eigen::Vector3d origin_;
  Eigen::Matrix3d axes_;  ///< columns: E, N, U in the geocentric frame
};

}  // namespace

std::vector<GnssFixSample> synthesizeGnss(const SplineTrajectory& trajectory, double t0, double t1,
                                          const GnssOptions& options, std::mt19937_64& rng) {
  validate(options);
  const std::vector<double> times = uniformSampleTimes(t0, t1, options.rate_hz);
  const mrpt::topography::TGeodeticCoords origin(
      options.origin_latitude_deg, options.origin_longitude_deg, options.origin_altitude_m);
  const auto wgs84 = mrpt::topography::TEllipsoid::Ellipsoid_WGS84();
  const EnuToGeocentric enuToGeocentric(origin, wgs84);
  std::normal_distribution<double> normal(0.0, 1.0);

  std::vector<GnssFixSample> out;
  out.reserve(times.size());
  for (const double t : times) {
    GnssFixSample fix;
    fix.t = t;
    fix.enu_true = trajectory.sample(t).T_world_body * options.lever_arm;
    // Explicit statements fix the draw order (argument evaluation order is unspecified).
    const double east_noise = normal(rng);
    const double north_noise = normal(rng);
    const double up_noise = normal(rng);
    const Eigen::Vector3d enu_measured =
        fix.enu_true + Eigen::Vector3d(options.horizontal_sigma * east_noise,
                                       options.horizontal_sigma * north_noise,
                                       options.vertical_sigma * up_noise);

    mrpt::topography::TGeodeticCoords geodetic;
    mrpt::topography::geocentricToGeodetic(enuToGeocentric(enu_measured), geodetic, wgs84);
    fix.latitude_deg = geodetic.lat.getDecimalValue();
    fix.longitude_deg = geodetic.lon.getDecimalValue();
    fix.altitude_m = geodetic.height;
    fix.fix_quality = options.fix_quality;
    fix.satellites = options.satellites;
    fix.hdop = options.hdop;
    out.push_back(fix);
  }
  return out;
}

}  // namespace dynslam::sim
