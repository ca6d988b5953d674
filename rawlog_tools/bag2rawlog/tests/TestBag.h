#pragma once
// A small bag written by the tests, with what it holds known exactly:
//   /cam/color/image_raw              sensor_msgs/Image rgb8, 4 frames at t0 + 0.1 s * i
//   /cam/color/image_raw/compressed   the same frames as CompressedImage, PNG and JPEG
//   /cam/color/camera_info            CameraInfo (once)
//   /cam/aligned_depth/image_raw      16UC1 mm, 3 ms after each colour frame
//   /cam/depth_metres                 32FC1 m, the same depth
//   /cam/depth_compressed             the same depth, image_transport compressedDepth (PNG)
//   /cam/depth_shifted, /cam/depth/camera_info   a plane 1 m away (16UC1) seen by a depth
//                                     camera with the colour intrinsics, 0.2 m to its right
//                                     (not registered to colour)
//   /cam/depth_8bit                   mono8 "depth" (no depth encoding)
//   /imu                              Imu, gyro + accel, 200 Hz
//   /accel/sample, /gyro/sample       split Imu streams, 100 Hz and 200 Hz (RealSense)
//   /gps/fix                          NavSatFix: 2 fixes and one NO_FIX
//   /gps/nmea                         nmea_msgs/Sentence: nmeaSentences()
// Messages are recorded later than their header stamps (images 40 ms), as a real recorder does.
#include <opencv2/core/mat.hpp>

#include <array>
#include <string>
#include <vector>

namespace bagtest {

constexpr int kWidth = 8, kHeight = 6, kFrames = 4;
constexpr double kT0 = 1560000000.0;
constexpr double kFx = 5.0, kFy = 5.5, kCx = 3.5, kCy = 2.5;

double colourStamp(int frame);
cv::Mat expectedBgr(int frame);
cv::Mat expectedDepthMm(int frame);  ///< CV_16UC1, a few zeros (invalid)

/// Gyro and accelerometer of the combined /imu topic at time t (s): linear in t, so linear
/// interpolation of the accelerometer is exact.
std::array<double, 3> gyroAt(double t);
std::array<double, 3> accAt(double t);
std::vector<double> imuStamps();    ///< /imu and /gyro/sample
std::vector<double> accelStamps();  ///< /accel/sample

struct Fix {
  double t, latitude, longitude, altitude;
  bool valid;
};
std::vector<Fix> fixes();

/// NMEA sentences on /gps/nmea: two GGA (with checksums) and one no parser knows.
struct NmeaLine {
  double t;
  std::string sentence;
  double latitude, longitude;  ///< of a GGA sentence, in degrees
};
std::vector<NmeaLine> nmeaSentences();

/// The JPEG bytes of frame `frame` as written to the compressed topic (odd frames are JPEG).
std::vector<uint8_t> compressedBytes(int frame);

void writeTestBag(const std::string& path);

}  // namespace bagtest
