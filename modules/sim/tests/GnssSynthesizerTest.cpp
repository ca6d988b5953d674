// synthesizeGnss: noise-free fixes convert back (with MRPT's inverse conversion) to the true
// antenna position, the sampling rule and copied fields, the noise sigmas, determinism, errors.
#include <dynslam/sim/GnssSynthesizer.h>
#include <dynslam/sim/TrajectoryPaths.h>

#include <gtest/gtest.h>
#include <mrpt/topography/conversions.h>

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace dynslam::sim {
namespace {

/// The fix's position back in the ENU frame at the options' origin.
Eigen::Vector3d toEnu(const GnssFixSample& fix, const GnssOptions& o) {
  mrpt::math::TPoint3D enu;
  mrpt::topography::geodeticToENU_WGS84(
      mrpt::topography::TGeodeticCoords(fix.latitude_deg, fix.longitude_deg, fix.altitude_m), enu,
      mrpt::topography::TGeodeticCoords(o.origin_latitude_deg, o.origin_longitude_deg,
                                        o.origin_altitude_m));
  return {enu.x, enu.y, enu.z};
}

GnssOptions exactOptions() {
  GnssOptions o;
  o.horizontal_sigma = 0;
  o.vertical_sigma = 0;
  o.lever_arm = Eigen::Vector3d(0.1, -0.2, 0.5);
  return o;
}

SplineTrajectory stationary(const Eigen::Vector3d& position, double duration) {
  const auto n = static_cast<std::size_t>(std::ceil(duration)) + 3;
  return SplineTrajectory(std::vector<Eigen::Vector3d>(n, position),
                          std::vector<Eigen::Vector3d>(n, Eigen::Vector3d(0.4, 0, 0)), 1.0);
}

TEST(GnssSynthesizer, NoiseFreeFixesConvertBackToTheTrueAntennaPosition) {
  const GnssOptions options = exactOptions();
  // A room-sized orbit and a 2 km drive (where the Earth's curvature matters: ~30 cm drop).
  const SplineTrajectory orbit =
      makeOrbit({2.5, 3.0, 0.0}, 1.3, 1.4, 10.0, 10.0, {2.5, 3.0, 1.2}, 0.05, 0.25, 1.0);
  const SplineTrajectory drive =
      makeDrivePath({{0, 0}, {1200, 0}, {1200, 800}, {-300, 900}}, 25.0, 1.5, 1.0);
  for (const SplineTrajectory* trajectory : {&orbit, &drive}) {
    std::mt19937_64 rng(3);
    const auto fixes = synthesizeGnss(*trajectory, 0.0, trajectory->endTime(), options, rng);
    double worst = 0, farthest = 0;
    for (const GnssFixSample& fix : fixes) {
      const Eigen::Vector3d antenna = trajectory->sample(fix.t).T_world_body * options.lever_arm;
      EXPECT_NEAR((fix.enu_true - antenna).norm(), 0, 1e-12);
      worst = std::max(worst, (toEnu(fix, options) - fix.enu_true).norm());
      farthest = std::max(farthest, fix.enu_true.norm());
    }
    EXPECT_LT(worst, 1e-3) << "farthest fix " << farthest << " m from the origin";
    std::ostringstream value;
    value << worst;
    RecordProperty(farthest > 100 ? "drive_worst_roundtrip_m" : "orbit_worst_roundtrip_m",
                   value.str());
  }
}

TEST(GnssSynthesizer, TheOriginMapsToTheOriginCoordinates) {
  GnssOptions options = exactOptions();
  options.lever_arm = Eigen::Vector3d::Zero();
  std::mt19937_64 rng(3);
  const auto fixes = synthesizeGnss(stationary({0, 0, 0}, 1.0), 0.0, 1.0, options, rng);
  ASSERT_FALSE(fixes.empty());
  EXPECT_NEAR(fixes[0].latitude_deg, options.origin_latitude_deg, 1e-10);
  EXPECT_NEAR(fixes[0].longitude_deg, options.origin_longitude_deg, 1e-10);
  EXPECT_NEAR(fixes[0].altitude_m, options.origin_altitude_m, 1e-6);
}

TEST(GnssSynthesizer, RatesCountsAndCopiedFields) {
  GnssOptions options = exactOptions();
  options.fix_quality = 5;
  options.satellites = 9;
  options.hdop = 1.7;
  const SplineTrajectory still = stationary({1, 2, 3}, 12.0);
  std::mt19937_64 rng(3);
  const auto at10hz = synthesizeGnss(still, 0.0, 10.0, options, rng);
  ASSERT_EQ(at10hz.size(), 101u);
  for (std::size_t k = 0; k < at10hz.size(); ++k) {
    EXPECT_DOUBLE_EQ(at10hz[k].t, k / 10.0);
    EXPECT_EQ(at10hz[k].fix_quality, 5);
    EXPECT_EQ(at10hz[k].satellites, 9);
    EXPECT_DOUBLE_EQ(at10hz[k].hdop, 1.7);
  }
  options.rate_hz = 5.0;
  const auto at5hz = synthesizeGnss(still, 1.0, 3.3, options, rng);
  ASSERT_EQ(at5hz.size(), 12u);  // 1.0, 1.2, ..., 3.2
  EXPECT_DOUBLE_EQ(at5hz.back().t, 1.0 + 11 / 5.0);
}

TEST(GnssSynthesizer, NoiseSigmasMatchInEnu) {
  GnssOptions options = exactOptions();
  options.horizontal_sigma = 1.5;  // a plain GPS
  options.vertical_sigma = 3.0;
  options.rate_hz = 100.0;
  const SplineTrajectory still = stationary({10, -20, 1}, 30.0);
  std::mt19937_64 rng(11);
  const auto fixes = synthesizeGnss(still, 0.0, 30.0, options, rng);
  ASSERT_EQ(fixes.size(), 3001u);
  Eigen::Array3d sum = Eigen::Array3d::Zero(), sq = Eigen::Array3d::Zero();
  for (const GnssFixSample& fix : fixes) {
    const Eigen::Array3d e = (toEnu(fix, options) - fix.enu_true).array();
    sum += e;
    sq += e * e;
  }
  const double n = static_cast<double>(fixes.size());
  const Eigen::Array3d mean = sum / n, std_dev = (sq / n - mean.square()).sqrt();
  EXPECT_NEAR(std_dev[0] / 1.5, 1.0, 0.1);
  EXPECT_NEAR(std_dev[1] / 1.5, 1.0, 0.1);
  EXPECT_NEAR(std_dev[2] / 3.0, 1.0, 0.1);
  EXPECT_LT(mean.abs().maxCoeff(), 0.2);  // 4 standard errors of the mean at most
}

TEST(GnssSynthesizer, SameSeedSameFixes) {
  const GnssOptions options;  // RTK-like defaults, noise on
  const SplineTrajectory still = stationary({0, 0, 0}, 5.0);
  std::mt19937_64 a(5), b(5), c(6);
  const auto first = synthesizeGnss(still, 0.0, 5.0, options, a);
  const auto again = synthesizeGnss(still, 0.0, 5.0, options, b);
  const auto other = synthesizeGnss(still, 0.0, 5.0, options, c);
  ASSERT_EQ(first.size(), again.size());
  for (std::size_t i = 0; i < first.size(); ++i) {
    EXPECT_EQ(first[i].latitude_deg, again[i].latitude_deg);
    EXPECT_EQ(first[i].longitude_deg, again[i].longitude_deg);
    EXPECT_EQ(first[i].altitude_m, again[i].altitude_m);
  }
  EXPECT_NE(first[3].latitude_deg, other[3].latitude_deg);
}

TEST(GnssSynthesizer, RejectsBadOptionsAndRanges) {
  const SplineTrajectory still = stationary({0, 0, 0}, 2.0);
  std::mt19937_64 rng(1);
  EXPECT_THROW(synthesizeGnss(still, 0.0, 9.0, GnssOptions(), rng), std::out_of_range);
  GnssOptions bad;
  bad.horizontal_sigma = -1;
  EXPECT_THROW(synthesizeGnss(still, 0.0, 1.0, bad, rng), std::invalid_argument);
  bad = GnssOptions();
  bad.rate_hz = 0;
  EXPECT_THROW(synthesizeGnss(still, 0.0, 1.0, bad, rng), std::invalid_argument);
  bad = GnssOptions();
  bad.origin_latitude_deg = 91;
  EXPECT_THROW(synthesizeGnss(still, 0.0, 1.0, bad, rng), std::invalid_argument);
}

}  // namespace
}  // namespace dynslam::sim
