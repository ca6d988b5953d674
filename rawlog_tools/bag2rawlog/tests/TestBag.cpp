#include "TestBag.h"

#include "NmeaSentence.h"

#include <rosbag/bag.h>
#include <sensor_msgs/CameraInfo.h>
#include <sensor_msgs/CompressedImage.h>
#include <sensor_msgs/Image.h>
#include <sensor_msgs/Imu.h>
#include <sensor_msgs/NavSatFix.h>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <cstring>

namespace bagtest {
namespace {

std_msgs::Header header(double t, const std::string& frame) {
  std_msgs::Header h;
  h.stamp = ros::Time(t);
  h.frame_id = frame;
  return h;
}

sensor_msgs::Image imageMessage(const cv::Mat& m, const std::string& encoding, double t) {
  sensor_msgs::Image msg;
  msg.header = header(t, "camera_color_optical_frame");
  msg.width = static_cast<uint32_t>(m.cols);
  msg.height = static_cast<uint32_t>(m.rows);
  msg.encoding = encoding;
  msg.step = static_cast<uint32_t>(m.cols * m.elemSize());
  msg.data.resize(msg.step * msg.height);
  for (int r = 0; r < m.rows; ++r) std::memcpy(&msg.data[r * msg.step], m.ptr(r), msg.step);
  return msg;
}

sensor_msgs::Imu imuMessage(double t, const std::array<double, 3>* gyro,
                            const std::array<double, 3>* acc) {
  sensor_msgs::Imu msg;
  msg.header = header(t, "imu");
  msg.orientation_covariance[0] = -1.0;  // no orientation, as RealSense publishes
  if (gyro) {
    msg.angular_velocity.x = (*gyro)[0];
    msg.angular_velocity.y = (*gyro)[1];
    msg.angular_velocity.z = (*gyro)[2];
  }
  if (acc) {
    msg.linear_acceleration.x = (*acc)[0];
    msg.linear_acceleration.y = (*acc)[1];
    msg.linear_acceleration.z = (*acc)[2];
  }
  return msg;
}

}  // namespace

double colourStamp(int frame) { return kT0 + 0.1 * frame; }

cv::Mat expectedBgr(int frame) {
  cv::Mat bgr(kHeight, kWidth, CV_8UC3);
  for (int r = 0; r < kHeight; ++r)
    for (int c = 0; c < kWidth; ++c)
      bgr.at<cv::Vec3b>(r, c) =
          cv::Vec3b(static_cast<uint8_t>(10 * c + frame), static_cast<uint8_t>(20 * r + 3),
                    static_cast<uint8_t>(200 - 7 * frame - r - c));
  return bgr;
}

cv::Mat expectedDepthMm(int frame) {
  cv::Mat depth(kHeight, kWidth, CV_16UC1);
  for (int r = 0; r < kHeight; ++r)
    for (int c = 0; c < kWidth; ++c)
      depth.at<uint16_t>(r, c) = static_cast<uint16_t>(1000 + 250 * frame + 37 * r + 11 * c);
  depth.at<uint16_t>(0, 0) = 0;  // invalid
  return depth;
}

std::array<double, 3> gyroAt(double t) {
  const double d = t - kT0;
  return {0.1 + d, -0.2 + 0.5 * d, 0.05 - d};
}

std::array<double, 3> accAt(double t) {
  const double d = t - kT0;
  return {0.3 + 2.0 * d, -0.1 - 0.5 * d, 9.81 + 0.25 * d};
}

std::vector<double> imuStamps() {
  std::vector<double> t;
  for (int k = 0; k < 80; ++k) t.push_back(kT0 - 0.05 + 0.005 * k);
  return t;
}

std::vector<double> accelStamps() {
  std::vector<double> t;
  for (int k = 0; k < 40; ++k) t.push_back(kT0 - 0.048 + 0.01 * k);
  return t;
}

std::vector<Fix> fixes() {
  return {{kT0 + 0.02, 48.137154, 11.576124, 519.5, true},
          {kT0 + 0.12, 0.0, 0.0, 0.0, false},
          {kT0 + 0.22, 48.137201, 11.576301, 520.25, true}};
}

std::vector<NmeaLine> nmeaSentences() {
  auto withChecksum = [](const std::string& body) {
    unsigned sum = 0;
    for (char ch : body) sum ^= static_cast<unsigned char>(ch);
    char tail[8];
    std::snprintf(tail, sizeof tail, "*%02X\r\n", sum);
    return "$" + body + tail;
  };
  return {{kT0 + 0.05,
           withChecksum("GPGGA,132000.05,4808.2292,N,01134.5674,E,1,08,0.9,519.5,M,47.0,M,,"),
           48.0 + 8.2292 / 60.0, 11.0 + 34.5674 / 60.0},
          {kT0 + 0.10, withChecksum("GPXYZ,1,2,3"), 0, 0},
          {kT0 + 0.15,
           withChecksum("GPGGA,132000.15,4808.2310,S,01134.5690,W,2,09,1.1,519.7,M,47.0,M,,"),
           -(48.0 + 8.2310 / 60.0), -(11.0 + 34.5690 / 60.0)}};
}

std::vector<uint8_t> compressedBytes(int frame) {
  std::vector<uint8_t> bytes;
  cv::imencode(frame % 2 ? ".jpg" : ".png", expectedBgr(frame), bytes);
  return bytes;
}

namespace {

/// When the recorder received a message stamped t: `latency` s later.
ros::Time recorded(double t, double latency) { return ros::Time(t + latency); }

/// The colour camera's CameraInfo, and the same for the depth camera (no distortion).
void writeCameraInfos(rosbag::Bag& bag) {
  sensor_msgs::CameraInfo info;
  info.header = header(colourStamp(0), "camera_color_optical_frame");
  info.width = kWidth;
  info.height = kHeight;
  info.distortion_model = "plumb_bob";
  info.D = {0.01, -0.02, 0.0, 0.0, 0.0};
  info.K = {kFx, 0, kCx, 0, kFy, kCy, 0, 0, 1};
  bag.write("/cam/color/camera_info", recorded(colourStamp(0), 0.04), info);
  info.header.frame_id = "camera_depth_optical_frame";
  info.D = {0, 0, 0, 0, 0};
  bag.write("/cam/depth/camera_info", recorded(colourStamp(0), 0.04), info);
}

/// One IMU stream with both, and RealSense's split gyro and accelerometer streams.
void writeImu(rosbag::Bag& bag) {
  for (const double t : imuStamps()) {
    const auto g = gyroAt(t), a = accAt(t);
    bag.write("/imu", recorded(t, 0.001), imuMessage(t, &g, &a));
    bag.write("/gyro/sample", recorded(t, 0.001), imuMessage(t, &g, nullptr));
  }
  for (const double t : accelStamps()) {
    const auto a = accAt(t);
    bag.write("/accel/sample", recorded(t, 0.001), imuMessage(t, nullptr, &a));
  }
}

/// NavSatFix messages (one without a fix) and raw NMEA sentences (one unknown to MRPT).
void writeGnss(rosbag::Bag& bag) {
  for (const Fix& f : fixes()) {
    sensor_msgs::NavSatFix msg;
    msg.header = header(f.t, "gps");
    msg.status.status =
        f.valid ? sensor_msgs::NavSatStatus::STATUS_FIX : sensor_msgs::NavSatStatus::STATUS_NO_FIX;
    msg.latitude = f.latitude;
    msg.longitude = f.longitude;
    msg.altitude = f.altitude;
    bag.write("/gps/fix", recorded(f.t, 0.01), msg);
  }
  for (const NmeaLine& line : nmeaSentences()) {
    nmea_msgs::Sentence msg;
    msg.header = header(line.t, "gps");
    msg.sentence = line.sentence;
    bag.write("/gps/nmea", recorded(line.t, 0.01), msg);
  }
}

/// Frame i's colour (raw and compressed) and its depth in every encoding the tests try.
void writeFrame(rosbag::Bag& bag, int i) {
  const double t = colourStamp(i), td = t + 0.003;
  cv::Mat rgb;
  cv::cvtColor(expectedBgr(i), rgb, cv::COLOR_BGR2RGB);
  bag.write("/cam/color/image_raw", recorded(t, 0.04), imageMessage(rgb, "rgb8", t));
  sensor_msgs::CompressedImage compressed;
  compressed.header = header(t, "camera_color_optical_frame");
  compressed.format = i % 2 ? "rgb8; jpeg compressed bgr8" : "rgb8; png compressed bgr8";
  compressed.data = compressedBytes(i);
  bag.write("/cam/color/image_raw/compressed", recorded(t, 0.04), compressed);
  const cv::Mat mm = expectedDepthMm(i);
  bag.write("/cam/aligned_depth/image_raw", recorded(td, 0.045), imageMessage(mm, "16UC1", td));
  cv::Mat metres;
  mm.convertTo(metres, CV_32FC1, 0.001);
  bag.write("/cam/depth_metres", recorded(td, 0.045), imageMessage(metres, "32FC1", td));
  // image_transport's compressedDepth: a 12-byte ConfigHeader (format, 2 floats), then PNG.
  sensor_msgs::CompressedImage packed;
  packed.header = header(td, "camera_depth_optical_frame");
  packed.format = "16UC1; compressedDepth png";
  packed.data.assign(12, 0);
  std::vector<uint8_t> png;
  cv::imencode(".png", mm, png);
  packed.data.insert(packed.data.end(), png.begin(), png.end());
  bag.write("/cam/depth_compressed", recorded(td, 0.045), packed);
  const cv::Mat plane(kHeight, kWidth, CV_16UC1, cv::Scalar(1000));
  bag.write("/cam/depth_shifted", recorded(td, 0.045), imageMessage(plane, "16UC1", td));
  cv::Mat eight(kHeight, kWidth, CV_8UC1, cv::Scalar(5));
  bag.write("/cam/depth_8bit", recorded(td, 0.045), imageMessage(eight, "mono8", td));
}

}  // namespace

void writeTestBag(const std::string& path) {
  rosbag::Bag bag(path, rosbag::bagmode::Write);
  writeCameraInfos(bag);
  writeImu(bag);
  writeGnss(bag);
  for (int i = 0; i < kFrames; ++i) writeFrame(bag, i);
  bag.close();
}

}  // namespace bagtest
