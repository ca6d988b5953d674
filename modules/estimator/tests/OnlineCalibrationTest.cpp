// The camera-IMU calibration the estimator is configured with (CalibrationParams in
// SlidingWindow.h, camera_in_imu) on synthetic frames (SyntheticFrames.h) whose images are taken
// late: a known offset corrects them; bad values are refused naming their key.
#include "StageTestSupport.h"
#include "SyntheticFrames.h"

#include <dynslam/estimator/EstimatorStage.h>
#include <dynslam/estimator/StateBlocks.h>

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>

using namespace dynslam;
using namespace dynslam::estimator;
using namespace dynslam::estimator::testing;

namespace {

/// camera_in_imu for the identity turned by `degrees` about `axis`.
std::string rotatedCamera(double degrees, const Eigen::Vector3d& axis) {
  const Eigen::Matrix3d R = Eigen::AngleAxisd(degrees * M_PI / 180, axis.normalized()).matrix();
  std::string out = "camera_in_imu =";
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c)
      out += " " + std::to_string(r < 3 && c < 3 ? R(r, c) : (r == c ? 1.0 : 0.0));
  return out + "\n";
}

}  // namespace

// A time offset known beforehand (configured, not estimated) moves every feature back to its
// state's time: on images taken 30 ms after their stamps the poses lose the lag.
TEST(OnlineCalibration, AKnownTimeOffsetTakesTheLagOutOfThePoses) {
  double rms[2] = {0, 0};
  for (const int corrected : {0, 1}) {
    SyntheticFramesOptions options;
    options.time_offset = 0.03;
    SyntheticFrames source(options);
    auto stage = makeStage(corrected ? "time_offset = 0.03\n" : "");
    double sum = 0;
    int n = 0;
    for (std::size_t i = 0; source.time(i) <= 6; ++i) {
      core::Frame f = source.frame(i);
      stage->process(f);
      ASSERT_TRUE(f.T_world_camera.has_value());
      if (f.index < 60) continue;  // after the IMU initialization
      sum += (f.T_world_camera->translation() - source.truth(i).translation()).squaredNorm();
      ++n;
    }
    rms[corrected] = std::sqrt(sum / n);
  }
  std::printf("images 30 ms late: position RMS %.2f mm as stamped, %.2f mm with time_offset\n",
              1e3 * rms[0], 1e3 * rms[1]);
  EXPECT_LT(rms[1], 0.003);
  EXPECT_LT(rms[1], 0.25 * rms[0]);
}

TEST(OnlineCalibration, ABadTimeOffsetPriorOrExtrinsicIsRefusedNamingTheKey) {
  EXPECT_NE(configRefusal("time_offset = 0.25\n").find("time_offset"), std::string::npos);
  EXPECT_NE(configRefusal("time_offset = -0.21\n").find("time_offset"), std::string::npos);
  EXPECT_EQ(configRefusal("time_offset = 0.2\n"), "");
  // A scaled rotation, a reflection, a matrix too short, a bottom row that is not 0 0 0 1.
  const std::string scaled = "camera_in_imu = 1.01 0 0 0  0 1 0 0  0 0 1 0  0 0 0 1\n";
  const std::string reflected = "camera_in_imu = -1 0 0 0  0 1 0 0  0 0 1 0  0 0 0 1\n";
  const std::string shortOne = "camera_in_imu = 1 0 0 0  0 1 0 0  0 0 1 0\n";
  const std::string bottom = "camera_in_imu = 1 0 0 0  0 1 0 0  0 0 1 0  0 0 1 1\n";
  for (const auto& bad : {scaled, reflected, shortOne, bottom}) {
    const std::string why = configRefusal(bad);
    EXPECT_NE(why.find("[Estimator] camera_in_imu"), std::string::npos) << bad << " -> " << why;
  }
  EXPECT_NE(configRefusal(scaled).find("orthonormal"), std::string::npos);
  EXPECT_EQ(configRefusal(rotatedCamera(2.0, Eigen::Vector3d::UnitZ())), "");
}
