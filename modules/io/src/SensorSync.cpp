#include "dynslam/io/SensorSync.h"

#include "dynslam/io/ObservationConversion.h"

#include <mrpt/obs/CObservation3DRangeScan.h>
#include <mrpt/obs/CObservationGPS.h>
#include <mrpt/obs/CObservationIMU.h>
#include <mrpt/topography/conversions.h>

#include <iomanip>
#include <sstream>

namespace dynslam::io {
namespace {

std::string stamp(double t) {
  std::ostringstream s;
  s << std::fixed << std::setprecision(6) << t;
  return s.str();
}

bool labelMatches(const std::string& wanted, const std::string& label) {
  return wanted.empty() || wanted == label;
}

}  // namespace

void SensorSyncOptions::describe(core::OptionVisitor& v) {
  v.key("camera_label", camera_label, "sensorLabel of the RGB-D camera (empty: any)");
  v.key("imu_label", imu_label, "sensorLabel of the IMU (empty: any)");
  v.key("gnss_label", gnss_label, "sensorLabel of the GNSS receiver (empty: any)");
  v.key("skip_frames_without_depth", skip_frames_without_depth,
        "true: drop RGB-D observations without depth; false: error");
  v.key("max_observation_mb", max_observation_mb, core::Range::above(0),
        "MB; an image, depth image, point cloud or string in a rawlog observation claiming more "
        "is an error before it is allocated (a corrupt size field)");
  v.key("queue_observations", queue_observations, core::Range::atLeast(1),
        "observations read ahead of the frame synchronisation at most (the reading thread waits "
        "while the queue is full): the memory of this many observations with their images");
  v.key("frames_ahead", frames_ahead, core::Range::atLeast(1),
        "frames made ahead of the pipeline at most");
}

SensorSync::SensorSync(SensorSyncOptions options) : options_(std::move(options)) {}

void SensorSync::checkOrder(const mrpt::obs::CObservation& obs, double t,
                            bool strictly_increasing) {
  const std::string sensor =
      std::string(obs.GetRuntimeClass()->className) + " '" + obs.sensorLabel + "'";
  const auto it = last_t_.find(sensor);
  if (it != last_t_.end() && (t < it->second || (strictly_increasing && t == it->second)))
    throw SyncError(
        "out-of-order timestamp: observation #" + std::to_string(counts_.observations - 1) + " (" +
        sensor + ") at t=" + stamp(t) + " is not after the previous one at t=" + stamp(it->second));
  last_t_[sensor] = t;
}

void SensorSync::checkNotLate(const char* what, double t) const {
  if (last_frame_t_ && t <= *last_frame_t_)
    throw SyncError(std::string("out-of-order timestamp: ") + what + " observation #" +
                    std::to_string(counts_.observations - 1) + " at t=" + stamp(t) +
                    " arrived after the frame at t=" + stamp(*last_frame_t_) +
                    " was handed out (the rawlog is not sorted by time)");
}

void SensorSync::push(const mrpt::obs::CObservation::Ptr& obs, std::vector<core::Frame>& out) {
  using namespace mrpt::obs;
  ++counts_.observations;
  ++counts_.by_type[obs->GetRuntimeClass()->className];
  const double t = mrpt::Clock::toDouble(obs->timestamp);
  if (auto scan = std::dynamic_pointer_cast<CObservation3DRangeScan>(obs);
      scan && labelMatches(options_.camera_label, obs->sensorLabel)) {
    checkOrder(*obs, t, true);
    emitUpTo(t, out);
    takeRgbd(*scan);
  } else if (auto imu = std::dynamic_pointer_cast<CObservationIMU>(obs);
             imu && labelMatches(options_.imu_label, obs->sensorLabel)) {
    checkOrder(*obs, t, false);
    emitUpTo(t, out);
    checkNotLate("IMU", t);
    takeImu(*imu);
  } else if (auto gps = std::dynamic_pointer_cast<CObservationGPS>(obs);
             gps && labelMatches(options_.gnss_label, obs->sensorLabel)) {
    checkOrder(*obs, t, false);
    emitUpTo(t, out);
    checkNotLate("GNSS", t);
    takeGnss(*gps);
  } else {
    ++counts_.other;
    emitUpTo(t, out);
  }
}

void SensorSync::takeRgbd(const mrpt::obs::CObservation3DRangeScan& scan) {
  ++counts_.rgbd;
  core::Frame frame;
  try {
    fillFrameFromRgbd(scan, frame);
  } catch (const ConversionError&) {
    if (!options_.skip_frames_without_depth || scan.hasRangeImage) throw;
    ++counts_.frames_without_depth;
    return;
  }
  waiting_.push_back(std::move(frame));
}

void SensorSync::takeImu(const mrpt::obs::CObservationIMU& imu) {
  ++counts_.imu;
  if (auto s = imuSampleFrom(imu)) {
    imu_.push_back(*s);
    T_body_imu_ = imuPoseOnBody(imu);
  }
}

void SensorSync::takeGnss(const mrpt::obs::CObservationGPS& gps) {
  ++counts_.gnss;
  auto fix = gnssFixFrom(gps);
  if (!fix || fix->fix_quality < 1) {  // GGA quality 0: no fix
    ++counts_.gnss_dropped;
    return;
  }
  if (!origin_) origin_ = Eigen::Vector3d(fix->latitude_deg, fix->longitude_deg, fix->altitude_m);
  mrpt::math::TPoint3D enu;
  mrpt::topography::geodeticToENU_WGS84(
      mrpt::topography::TGeodeticCoords(fix->latitude_deg, fix->longitude_deg, fix->altitude_m),
      enu, mrpt::topography::TGeodeticCoords((*origin_)[0], (*origin_)[1], (*origin_)[2]));
  fix->enu = {enu.x, enu.y, enu.z};
  gnss_.push_back(*fix);
}

void SensorSync::emitUpTo(double t, std::vector<core::Frame>& out) {
  while (!waiting_.empty() && waiting_.front().t < t) {
    emit(waiting_.front(), out);
    waiting_.pop_front();
  }
}

void SensorSync::flush(std::vector<core::Frame>& out) { emitUpTo(INFINITY, out); }

void SensorSync::emit(core::Frame& frame, std::vector<core::Frame>& out) {
  // Samples older than the previous frame were taken by it; the checks in push() guarantee
  // every buffered sample is later than last_frame_t_.
  while (!imu_.empty() && imu_.front().t <= frame.t) {
    frame.imu.push_back(imu_.front());
    imu_.pop_front();
  }
  while (!gnss_.empty() && gnss_.front().t <= frame.t) {
    frame.gnss.push_back(gnss_.front());
    gnss_.pop_front();
  }
  if (T_body_imu_) frame.T_body_imu = *T_body_imu_;
  frame.index = counts_.frames++;
  last_frame_t_ = frame.t;
  out.push_back(std::move(frame));
}

}  // namespace dynslam::io
