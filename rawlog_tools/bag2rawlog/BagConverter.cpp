#include "BagConverter.h"

#include "BagMessages.h"
#include "StreamPairing.h"
#include "TimeOrderedWriter.h"

#include <dynslam/rawlog_tools/ConversionError.h>
#include <dynslam/rawlog_tools/RawlogWriter.h>
#include <dynslam/rawlog_tools/SensorLabels.h>
#include <dynslam/rawlog_tools/Timestamps.h>
#include <mrpt/core/bits_math.h>
#include <mrpt/obs/CObservation3DRangeScan.h>
#include <mrpt/obs/CObservationGPS.h>
#include <mrpt/obs/CObservationIMU.h>
#include <mrpt/poses/CPose3D.h>
#include <rosbag/bag.h>
#include <rosbag/view.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>

namespace fs = std::filesystem;

namespace dynslam::rawlog_tools::bag {
namespace {

constexpr Nanoseconds kSecond = 1000000000;

enum class Role { Colour, Depth, Imu, Accel, Gyro, Gnss, Nmea };

Nanoseconds toNanoseconds(double seconds) {
  return static_cast<Nanoseconds>(seconds * static_cast<double>(kSecond));
}

std::string stampName(Nanoseconds t) {
  char name[32];
  std::snprintf(name, sizeof name, "%lld.%09lld", static_cast<long long>(t / kSecond),
                static_cast<long long>(t % kSecond));
  return name;
}

/// Topic -> ROS type of every connection in the bag.
std::map<std::string, std::string> bagTopics(const rosbag::Bag& bag) {
  std::map<std::string, std::string> topics;
  rosbag::View all(bag);
  for (const rosbag::ConnectionInfo* c : all.getConnections()) topics[c->topic] = c->datatype;
  return topics;
}

void checkTopic(const std::map<std::string, std::string>& inBag, const std::string& bagPath,
                const std::string& topicsSource, const std::string& role,
                const std::string& topic) {
  const auto it = inBag.find(topic);
  if (it == inBag.end()) {
    std::string list;
    for (const auto& [name, type] : inBag) list += "\n  " + name + " (" + type + ")";
    throw ConversionError(topicsSource + ": " + role + " " + topic + " is not in " + bagPath +
                          "; the bag has these topics:" + (list.empty() ? " none" : list));
  }
  const auto accepted = acceptedTypes(role);
  if (std::find(accepted.begin(), accepted.end(), it->second) == accepted.end()) {
    std::string names;
    for (const auto& a : accepted) names += (names.empty() ? "" : " or ") + a;
    throw ConversionError(topicsSource + ": " + role + " " + topic + " is " + it->second + " in " +
                          bagPath + "; " + role + " needs " + names);
  }
}

/// The first CameraInfo of `topic` (the cameras are assumed fixed for the whole bag).
CameraIntrinsics firstCameraInfo(const rosbag::Bag& bag, const std::string& key,
                                 const std::string& topic, const std::string& bagPath) {
  rosbag::View view(bag, rosbag::TopicQuery(topic));
  for (const rosbag::MessageInstance& m : view) return readCameraInfo(m);
  throw ConversionError(key + " " + topic + " has no messages in " + bagPath);
}

void setDistortion(mrpt::img::TCamera& camera, const std::array<double, 5>& d) {
  for (size_t i = 0; i < d.size(); ++i) camera.dist[i] = d[i];
}

/// Puts a colour image where the rawlog expects it: compressed bytes are kept as they are
/// (no second JPEG loss), raw pixels become a PNG (or stay in the observation when embedded).
StoredColourImage storeColour(ColourImageStore& images, const ColourMessage& colour) {
  std::string name = stampName(colour.stamp);
  if (colour.encoded.empty() || images.storage() == ImageStorage::Embedded)
    return images.storePixels(colour.bgr, name);
  std::error_code ec;
  fs::create_directories(images.imagesDir(), ec);
  StoredColourImage stored;
  stored.width = colour.bgr.cols;
  stored.height = colour.bgr.rows;
  stored.externalName = name + colour.extension;
  const fs::path target = fs::path(images.imagesDir()) / stored.externalName;
  std::ofstream out(target, std::ios::binary);
  out.write(reinterpret_cast<const char*>(colour.encoded.data()),
            static_cast<std::streamsize>(colour.encoded.size()));
  if (!out) throw ConversionError("cannot write " + target.string());
  return stored;
}

mrpt::poses::CPose3D toPose(const Eigen::Isometry3d& T) {
  mrpt::math::CMatrixDouble44 m;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) m(r, c) = T.matrix()(r, c);
  return mrpt::poses::CPose3D(m);
}

class Converter {
 public:
  Converter(const TopicMap& topics, const CameraIntrinsics& intrinsics,
            const std::optional<CameraIntrinsics>& depthCamera, ColourImageStore& images,
            RawlogWriter& writer)
      : topics_(topics),
        intrinsics_(intrinsics),
        depthCamera_(depthCamera),
        images_(images),
        out_(writer),
        pairer_(toNanoseconds(topics.rgbd_max_dt)),
        window_(toNanoseconds(topics.reorder_window)),
        cameraPose_(parsePose(topics.camera_pose, "camera_pose")),
        imuPose_(parsePose(topics.imu_pose, "imu_pose")),
        gnssPose_(parsePose(topics.gnss_pose, "gnss_pose")) {
    const auto T_colour_depth = parsePose(topics.depth_to_colour_pose, "depth_to_colour_pose");
    // Colour optical frame in MRPT's depth frame (+X forward): the depth optical axes, then
    // the colour camera seen from the depth camera.
    const mrpt::poses::CPose3D opticalInDepth(0, 0, 0, mrpt::DEG2RAD(-90.0), 0,
                                              mrpt::DEG2RAD(-90.0));
    colourInDepth_ = opticalInDepth +
                     (T_colour_depth ? toPose(T_colour_depth->inverse()) : mrpt::poses::CPose3D());
  }

  void handle(Role role, const rosbag::MessageInstance& m) {
    switch (role) {
      case Role::Colour: {
        ColourMessage c = readColour(m);
        see(c.stamp);
        pairer_.addColour(std::move(c));
        break;
      }
      case Role::Depth: {
        DepthMessage d = readDepth(m, topics_.depth_unit);
        see(d.stamp);
        pairer_.addDepth(std::move(d));
        break;
      }
      case Role::Imu: {
        auto imu = readImu(m, kImuLabel);
        if (imuPose_) imu->sensorPose = toPose(*imuPose_);
        const Nanoseconds t = stampOf(*imu);
        see(t);
        ordered_.add(t, imu);
        break;
      }
      case Role::Accel: {
        const Vector3Sample a = readAccel(m);
        see(a.stamp);
        combiner_.addAccel(a);
        break;
      }
      case Role::Gyro: {
        const Vector3Sample g = readGyro(m);
        see(g.stamp);
        combiner_.addGyro(g);
        break;
      }
      case Role::Gnss: {
        auto gps = readNavSatFix(m, kGpsLabel);
        if (!gps) {
          ++summary_.gnssWithoutFix;
          break;
        }
        addGnss(gps);
        break;
      }
      case Role::Nmea: {
        auto gps = readNmeaSentence(m, kGpsLabel);
        if (!gps) {
          ++summary_.nmeaSkipped;
          break;
        }
        addGnss(gps);
        break;
      }
    }
    ++summary_.messages;
    drain(false);
  }

  ConversionSummary finish() {
    drain(true);
    ordered_.flushAll();
    summary_.unmatchedColour = pairer_.unmatchedColour();
    summary_.unmatchedDepth = pairer_.unmatchedDepth();
    summary_.droppedGyro = combiner_.droppedGyro();
    summary_.outOfOrderImu = combiner_.outOfOrder();
    summary_.late = ordered_.late();
    return summary_;
  }

 private:
  static Nanoseconds stampOf(const mrpt::obs::CObservation& o) {
    // MRPT ticks are 100 ns since 1601; back to Unix nanoseconds for ordering.
    return (o.timestamp.time_since_epoch().count() - INT64_C(116444736000000000)) * 100;
  }

  void see(Nanoseconds t) { newest_ = std::max(newest_, t); }

  void addGnss(const std::shared_ptr<mrpt::obs::CObservationGPS>& gps) {
    if (gnssPose_) gps->sensorPose = toPose(*gnssPose_);
    const Nanoseconds t = stampOf(*gps);
    see(t);
    ordered_.add(t, gps);
  }

  void drain(bool end) {
    for (auto& [colour, depth] : pairer_.takeReady(newest_, window_, end))
      ordered_.add(colour.stamp, makeRgbd(colour, depth));
    for (const ImuSample& s : combiner_.takeReady(end)) {
      auto imu = makeImuObservation(timeFromNanoseconds(s.stamp), kImuLabel, s.gyro, s.acc);
      if (imuPose_) imu->sensorPose = toPose(*imuPose_);
      ordered_.add(s.stamp, imu);
    }
    if (end) return;
    // Nothing older than what the joins still hold, or than the reorder window, is final.
    Nanoseconds horizon = newest_ - window_;
    if (auto p = pairer_.oldestPending()) horizon = std::min(horizon, *p);
    if (auto p = combiner_.oldestPending()) horizon = std::min(horizon, *p);
    ordered_.flushBefore(horizon);
  }

  std::shared_ptr<mrpt::obs::CObservation3DRangeScan> makeRgbd(const ColourMessage& colour,
                                                               const DepthMessage& depth) {
    if (intrinsics_.width > 0 &&
        (intrinsics_.width != colour.bgr.cols || intrinsics_.height != colour.bgr.rows))
      throw ConversionError(
          "colour image at " + stampName(colour.stamp) + " is " + std::to_string(colour.bgr.cols) +
          "x" + std::to_string(colour.bgr.rows) + " but camera_info_topic " +
          topics_.camera_info_topic + " is for " + std::to_string(intrinsics_.width) + "x" +
          std::to_string(intrinsics_.height));
    RgbdFrame frame;
    frame.timestamp = timeFromNanoseconds(colour.stamp);
    frame.sensorLabel = kRgbdLabel;
    frame.depth = depth.depth;
    frame.rangeUnits = depth.rangeUnits;
    frame.maxRange = static_cast<float>(topics_.max_depth);
    frame.intrinsics = intrinsics_.k;
    frame.depthSourceName =
        topics_.depth_topic + " at " + stampName(depth.stamp) +
        (depthCamera_ ? ""
                      : " (must be registered to colour: use the aligned depth topic, or set "
                        "depth_camera_info_topic)");
    frame.colour = storeColour(images_, colour);
    if (!depthCamera_) {
      auto obs = makeRgbdObservation(frame);
      setDistortion(obs->cameraParams, intrinsics_.distortion);
      setDistortion(obs->cameraParamsIntensity, intrinsics_.distortion);
      if (cameraPose_) setCameraPoseOnBody(*obs, *cameraPose_);
      return obs;
    }
    if (depthCamera_->width > 0 &&
        (depthCamera_->width != depth.depth.cols || depthCamera_->height != depth.depth.rows))
      throw ConversionError(frame.depthSourceName + " is " + std::to_string(depth.depth.cols) +
                            "x" + std::to_string(depth.depth.rows) + " but " +
                            topics_.depth_camera_info_topic + " is for " +
                            std::to_string(depthCamera_->width) + "x" +
                            std::to_string(depthCamera_->height));
    // makeRgbdObservation builds registered frames (one camera, one size): it is given the depth
    // size, and the colour camera's own size, the depth camera and the pose between them are
    // put in afterwards. dynslam::io registers such depth to colour when reading.
    const StoredColourImage colourImage = frame.colour;
    frame.colour.width = depth.depth.cols;
    frame.colour.height = depth.depth.rows;
    auto obs = makeRgbdObservation(frame);
    const PinholeIntrinsics& dk = depthCamera_->k;
    obs->cameraParams.setIntrinsicParamsFromValues(dk.fx, dk.fy, dk.cx, dk.cy);
    setDistortion(obs->cameraParams, depthCamera_->distortion);
    obs->cameraParamsIntensity.ncols = static_cast<uint32_t>(colourImage.width);
    obs->cameraParamsIntensity.nrows = static_cast<uint32_t>(colourImage.height);
    setDistortion(obs->cameraParamsIntensity, intrinsics_.distortion);
    obs->relativePoseIntensityWRTDepth = colourInDepth_;
    if (cameraPose_) setCameraPoseOnBody(*obs, *cameraPose_);
    return obs;
  }

  const TopicMap& topics_;
  CameraIntrinsics intrinsics_;
  std::optional<CameraIntrinsics> depthCamera_;
  mrpt::poses::CPose3D colourInDepth_;
  ColourImageStore& images_;
  RawlogWriter& out_;
  TimeOrderedWriter ordered_{out_};
  RgbdPairer pairer_;
  ImuCombiner combiner_;
  Nanoseconds window_;
  Nanoseconds newest_ = 0;
  std::optional<Eigen::Isometry3d> cameraPose_, imuPose_, gnssPose_;
  ConversionSummary summary_;
};

}  // namespace

ConversionSummary convertBag(const std::string& bagPath, const TopicMap& topics,
                             const std::string& topicsSource, ColourImageStore& images,
                             RawlogWriter& writer, std::FILE* progress) {
  if (!fs::is_regular_file(bagPath)) throw ConversionError("bag " + bagPath + " does not exist");
  rosbag::Bag bag;
  try {
    bag.open(bagPath, rosbag::bagmode::Read);
  } catch (const rosbag::BagException& e) {
    throw ConversionError("cannot read bag " + bagPath + ": " + e.what());
  }

  const std::map<std::string, std::string> inBag = bagTopics(bag);
  std::map<std::string, Role> roles;
  auto map = [&](const std::string& key, const std::string& topic, Role role) {
    if (topic.empty()) return;
    checkTopic(inBag, bagPath, topicsSource, key, topic);
    if (!roles.emplace(topic, role).second)
      throw ConversionError(topicsSource + ": topic " + topic + " is given for two roles");
  };
  map("rgb_topic", topics.rgb_topic, Role::Colour);
  map("depth_topic", topics.depth_topic, Role::Depth);
  map("imu_topic", topics.imu_topic, Role::Imu);
  map("accel_topic", topics.accel_topic, Role::Accel);
  map("gyro_topic", topics.gyro_topic, Role::Gyro);
  map("gnss_topic", topics.gnss_topic, Role::Gnss);
  map("nmea_topic", topics.nmea_topic, Role::Nmea);
  CameraIntrinsics intrinsics;
  intrinsics.k = {topics.fx, topics.fy, topics.cx, topics.cy};
  std::optional<CameraIntrinsics> depthCamera;
  if (topics.hasRgbd() && !topics.camera_info_topic.empty()) {
    checkTopic(inBag, bagPath, topicsSource, "camera_info_topic", topics.camera_info_topic);
    intrinsics = firstCameraInfo(bag, "camera_info_topic", topics.camera_info_topic, bagPath);
  }
  if (topics.hasRgbd() && !topics.depthRegistered()) {
    const std::string& topic = topics.depth_camera_info_topic;
    checkTopic(inBag, bagPath, topicsSource, "depth_camera_info_topic", topic);
    depthCamera = firstCameraInfo(bag, "depth_camera_info_topic", topic, bagPath);
  }

  std::vector<std::string> topicList;
  for (const auto& [topic, role] : roles) topicList.push_back(topic);
  rosbag::View view(bag, rosbag::TopicQuery(topicList));
  const size_t total = view.size();
  Converter converter(topics, intrinsics, depthCamera, images, writer);
  using Clock = std::chrono::steady_clock;
  auto lastReport = Clock::now();
  size_t done = 0;
  for (const rosbag::MessageInstance& m : view) {
    converter.handle(roles.at(m.getTopic()), m);
    ++done;
    if (progress && Clock::now() - lastReport > std::chrono::seconds(2)) {
      std::fprintf(
          progress, "[bag2rawlog] %zu / %zu messages (%.0f%%)\n", done, total,
          100.0 * static_cast<double>(done) / static_cast<double>(std::max<size_t>(total, 1)));
      lastReport = Clock::now();
    }
  }
  if (progress) std::fprintf(progress, "[bag2rawlog] %zu / %zu messages done\n", done, total);
  return converter.finish();
}

}  // namespace dynslam::rawlog_tools::bag
