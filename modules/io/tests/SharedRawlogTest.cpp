// Real rawlogs written by MRPT itself (../shared/data/mrpt) streamed through RawlogSource and
// SensorSync.
#include <dynslam/io/RawlogSource.h>
#include <dynslam/io/SensorSync.h>
#include <dynslam/testing/TestEnv.h>

#include <mrpt/obs/CObservation3DRangeScan.h>
#include <mrpt/obs/CObservationGPS.h>

#include <opencv2/core.hpp>

using namespace dynslam::io;

TEST(SharedRawlog, KinectRgbdDepthInMetresRegisteredToColour) {
  DYNSLAM_REQUIRE_SHARED(path, "data/mrpt/tests_rgbd.rawlog");
  RawlogSource src(path);
  SensorSync sync;
  std::vector<dynslam::core::Frame> frames;
  mrpt::obs::CObservation3DRangeScan::Ptr raw;
  while (auto obs = src.next()) {
    if (!raw) raw = std::dynamic_pointer_cast<mrpt::obs::CObservation3DRangeScan>(obs);
    sync.push(obs, frames);
  }
  sync.flush(frames);
  ASSERT_EQ(frames.size(), 1u);
  EXPECT_EQ(sync.counts().by_type.at("mrpt::obs::CObservation3DRangeScan"), 1u);
  const auto& f = frames[0];
  EXPECT_EQ(f.sensor_label, "OPENNI2");
  ASSERT_EQ(f.rgb.type(), CV_8UC3);
  ASSERT_EQ(f.depth.size(), f.rgb.size());

  // Depth in metres: the raw values times rangeUnits; an indoor Kinect sees 0.4-10 m.
  ASSERT_TRUE(raw);
  raw->load();
  double rawMax = 0;
  for (int r = 0; r < raw->rangeImage.rows(); ++r)
    for (int c = 0; c < raw->rangeImage.cols(); ++c)
      rawMax = std::max(rawMax, static_cast<double>(raw->rangeImage(r, c)));
  double mn = 0, mx = 0;
  cv::minMaxLoc(f.depth, &mn, &mx, nullptr, nullptr, f.depth > 0);
  EXPECT_GT(mn, 0.3);
  EXPECT_LT(mx, 10.0);
  EXPECT_NEAR(mx, rawMax * raw->rangeUnits, 0.25) << "registration may move, not rescale, depth";
  const double valid = cv::countNonZero(f.depth > 0) / static_cast<double>(f.depth.total());
  EXPECT_GT(valid, 0.5);
  std::cout << "[ INFO ] depth " << mn << ".." << mx << " m, " << 100 * valid << " % valid, "
            << (raw->doDepthAndIntensityCamerasCoincide() ? "coincident" : "registered")
            << " cameras\n";
}

TEST(SharedRawlog, RtkGgaFixesConvertedToEnu) {
  DYNSLAM_REQUIRE_SHARED(path, "data/mrpt/test_rtk_path.rawlog");
  RawlogSource src(path);
  SensorSyncOptions o;
  o.gnss_label = "GPS_RTK_FRONT_L";
  SensorSync sync(o);
  std::vector<dynslam::core::Frame> frames;
  size_t gps = 0;
  while (auto obs = src.next()) {
    gps += std::dynamic_pointer_cast<mrpt::obs::CObservationGPS>(obs) != nullptr;
    sync.push(obs, frames);
  }
  sync.flush(frames);
  EXPECT_EQ(frames.size(), 0u) << "no camera in this log";
  EXPECT_EQ(gps, 691u);
  EXPECT_EQ(sync.counts().observations, 692u);
  EXPECT_EQ(sync.counts().gnss, 307u) << "only the front-left receiver";
  EXPECT_EQ(sync.counts().other, 692u - 307u);
  ASSERT_TRUE(sync.gnssOrigin().has_value());
  const auto origin = *sync.gnssOrigin();
  std::cout << "[ INFO ] ENU origin lat " << origin[0] << " lon " << origin[1] << " alt "
            << origin[2] << ", " << sync.counts().gnss_dropped << " fixes dropped\n";
  EXPECT_NEAR(origin[0], 36.7, 0.1);  // Malaga, Spain
  EXPECT_NEAR(origin[1], -4.5, 0.1);
}
