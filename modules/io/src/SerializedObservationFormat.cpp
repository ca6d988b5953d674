#include "SerializedFormat.h"

#include <mrpt/obs/CObservationIMU.h>
#include <mrpt/obs/gnss_messages_ascii_nmea.h>
#include <mrpt/obs/gnss_messages_topcon.h>
#include <mrpt/obs/gnss_messages_type_list.h>

#include <memory>

namespace dynslam::io::detail::format {
namespace {

// GNSS messages that are not one fixed-size block (uint32 length + bytes) in the stream.
bool isVariableGnssMessage(std::int32_t id) {
  using namespace mrpt::obs::gnss;
  return id == NV_OEM6_GENERIC_FRAME || id == NV_OEM6_GENERIC_SHORT_FRAME ||
         id == NV_OEM6_RANGECMP || id == NV_OEM6_VERSION || id == TOPCON_PZS || id == TOPCON_SATS;
}

// CObservation3DRangeScan, points and range image: float maxRange, CPose3D sensorPose, v1+
// bool hasPoints3D (always true in v0), uint32 N and the x y z floats (v0: + N validity bytes;
// v8+: + two uint16 index arrays), v1+ bool hasRangeImage, v9+ float rangeUnits, the range
// image (v<9 a CMatrixF; v9+ uint32 rows, cols and uint16 pixels).
Req stepScanGeometry(Frame& f, const Fields& p) {
  const int v = f.version;
  switch (f.pc) {
    case 0:
      return at(f, 1, skip(4));
    case 1:
      return at(f, 2, object("sensorPose"));
    case 2:
      return v > 0 ? at(f, 3, field(1)) : at(f, 4, field(4));
    case 3:
      return p.u8() ? at(f, 4, field(4)) : at(f, 5, again());
    case 4: {
      // resizePoints3DVectors(N) allocates x, y, z floats and two uint16 indices per point.
      const std::uint64_t n = p.u32();
      p.claim(f, mul(n, 16), std::to_string(n) + " 3D points");
      return at(f, 5, skip(mul(n, v == 0 ? 13 : v >= 8 ? 16 : 12)));
    }
    case 5:
      if (v == 0) return at(f, 40, again());
      return at(f, 6, field(1));
    case 6:
      f.flag = p.u8() != 0;
      return at(f, 7, skip(v >= 9 ? 4 : 0));
    case 7:
      if (!f.flag) return at(f, 20, again());
      return v < 9 ? at(f, 20, object("range image")) : at(f, 8, field(4));
    case 8:
      f.rows = p.u32();
      return at(f, 9, field(4));
    case 9: {
      f.cols = p.u32();
      const auto bytes = mul(mul(f.rows, f.cols), 2);
      p.claim(f, bytes, "a " + dims(f.rows, f.cols) + " range image");
      return at(f, 20, skip(bytes));
    }
    default:
      return unwatch();
  }
}

// CObservation3DRangeScan, images and cameras (v1+): bool + CImage intensityImage, bool +
// CImage confidenceImage, v2+ TCamera cameraParams, v4+ TCamera cameraParamsIntensity and
// CPose3D relativePoseIntensityWRTDepth.
Req stepScanImages(Frame& f, const Fields& p) {
  const int v = f.version;
  switch (f.pc) {
    case 20:
      return at(f, 21, field(1));
    case 21:
      return at(f, 22, p.u8() ? object("intensityImage") : again());
    case 22:
      return at(f, 23, field(1));
    case 23:
      return at(f, 24, p.u8() ? object("confidenceImage") : again());
    case 24:
      return at(f, 25, v >= 2 ? object("cameraParams") : again());
    case 25:
      return at(f, 26, v >= 4 ? object("cameraParamsIntensity") : again());
    case 26:
      return at(f, 40, v >= 4 ? object("relativePoseIntensityWRTDepth") : again());
    default:
      return unwatch();
  }
}

// CObservation3DRangeScan, the rest: float stdError, uint64 timestamp, sensorLabel, v3+ bool +
// points file and bool + range image file, v5+ bool range_is_depth, v6+ int8 channel, v7+
// bool pixel labels (not modelled), v10+ uint8 layer count and per layer a name, uint32 rows,
// cols and uint16 pixels.
Req stepScanTail(Frame& f, const Fields& p) {
  const int v = f.version;
  switch (f.pc) {
    case 40:
      return at(f, 41, skip(4 + 8));
    case 41:
      return at(f, 42, string("sensorLabel"));
    case 42:
      return v >= 3 ? at(f, 43, skip(1)) : at(f, 46, again());
    case 43:
      return at(f, 44, string("points3D file"));
    case 44:
      return at(f, 45, skip(1));
    case 45:
      return at(f, 46, string("rangeImage file"));
    case 46:
      return at(f, 47, skip((v >= 5 ? 1 : 0) + (v >= 6 ? 1 : 0)));
    case 47:
      return v >= 7 ? at(f, 48, field(1)) : end();
    case 48:
      if (p.u8()) return unwatch();  // TPixelLabelInfo
      return v >= 10 ? at(f, 50, field(1)) : end();
    case 50:
      f.n = p.u8();
      f.i = 0;
      return at(f, 51, again());
    case 51:
      if (f.i == f.n) return end();
      ++f.i;
      return at(f, 52, string("range layer name"));
    case 52:
      return at(f, 53, field(4));
    case 53:
      f.rows = p.u32();
      return at(f, 54, field(4));
    case 54: {
      f.cols = p.u32();
      const auto bytes = mul(mul(f.rows, f.cols), 2);
      p.claim(f, bytes, "a " + dims(f.rows, f.cols) + " extra range layer");
      return at(f, 51, skip(bytes));
    }
    default:
      return end();
  }
}

}  // namespace

Req stepRangeScan(Frame& f, const Fields& p) {
  if (f.pc >= 40) return stepScanTail(f, p);
  if (f.pc >= 20) return stepScanImages(f, p);
  return stepScanGeometry(f, p);
}

// CSensoryFrame: v<2 uint32 ID, v0 uint64 timestamp, uint32 count, the observations.
Req stepSensoryFrame(Frame& f, const Fields& p) {
  switch (f.pc) {
    case 0:
      return at(f, 1, skip((f.version < 2 ? 4 : 0) + (f.version == 0 ? 8 : 0)));
    case 1:
      return at(f, 2, field(4));
    case 2:
      f.n = p.u32();
      f.i = 0;
      // m_observations.resize(n) allocates a shared_ptr per observation.
      p.claim(f, mul(f.n, sizeof(std::shared_ptr<void>)), std::to_string(f.n) + " observations");
      return at(f, 3, again());
    default:
      if (f.i == f.n) return end();
      ++f.i;
      return object("observation");
  }
}

// CObservationIMU: CPose3D sensorPose; v4 fixed arrays of presence bytes, timestamp and
// doubles; v1-3 a vector<bool>, timestamp and vector<double> (v0: a CVectorFloat, not
// modelled); then sensorLabel.
Req stepImu(Frame& f, const Fields& p) {
  constexpr std::uint64_t fields = mrpt::obs::COUNT_IMU_DATA_FIELDS;
  switch (f.pc) {
    case 0:
      return at(f, 1, object("sensorPose"));
    case 1:
      return f.version == 4 ? at(f, 5, skip(fields + 8 + fields * 8)) : at(f, 2, field(4));
    case 2:
      f.n = p.u32();
      p.claim(f, f.n, "a " + std::to_string(f.n) + "-element dataIsPresent vector");
      return at(f, 3, skip(f.n + 8));
    case 3:
      return f.version >= 1 ? at(f, 4, field(4)) : unwatch();
    case 4:
      f.n = p.u32();
      p.claim(f, mul(f.n, 8), "a " + std::to_string(f.n) + "-element rawMeasurements vector");
      return at(f, 5, skip(mul(f.n, 8)));
    case 5:
      return at(f, 6, string("sensorLabel"));
    default:
      return end();
  }
}

namespace {

// CObservationGPS v1-9 stores GGA, RMC and TOPCON PZS fields one by one, and MRPT 2.5.8 reads
// each with the size of its member today (MRPT_READ_POD), so the sizes come from its headers.
std::uint64_t oldGgaBytes(int v) {
  const mrpt::obs::gnss::Message_NMEA_GGA::content_t* g = nullptr;  // only for sizeof
  return sizeof g->UTCTime.hour + sizeof g->UTCTime.minute + sizeof g->UTCTime.sec +
         sizeof g->latitude_degrees + sizeof g->longitude_degrees + sizeof g->fix_quality +
         sizeof g->altitude_meters +
         (v >= 9 ? sizeof g->geoidal_distance + sizeof g->orthometric_altitude +
                       sizeof g->corrected_orthometric_altitude
                 : 0) +
         sizeof g->satellitesUsed + sizeof g->thereis_HDOP + sizeof g->HDOP;
}

std::uint64_t oldRmcBytes() {
  const mrpt::obs::gnss::Message_NMEA_RMC::content_t* r = nullptr;
  return sizeof r->UTCTime.hour + sizeof r->UTCTime.minute + sizeof r->UTCTime.sec +
         sizeof r->validity_char + sizeof r->latitude_degrees + sizeof r->longitude_degrees +
         sizeof r->speed_knots + sizeof r->direction_degrees;
}

std::uint64_t oldPzsBytes(int v) {
  const mrpt::obs::gnss::Message_TOPCON_PZS* z = nullptr;
  std::uint64_t n = sizeof z->latitude_degrees + sizeof z->longitude_degrees +
                    sizeof z->height_meters + sizeof z->RTK_height_meters + sizeof z->PSigma +
                    sizeof z->angle_transmitter + sizeof z->nId + sizeof z->Fix +
                    sizeof z->TXBattery + sizeof z->RXBattery + sizeof z->error;
  if (v < 6) return n;
  static_assert(sizeof z->pos_covariance == 16 * sizeof(float), "4x4 floats, no padding");
  n += sizeof z->hasCartesianPosVel + 6 * sizeof z->cartesian_x + sizeof z->hasPosCov +
       sizeof z->pos_covariance + sizeof z->hasVelCov + sizeof z->vel_covariance +
       sizeof z->hasStats + sizeof z->stats_GPS_sats_used + sizeof z->stats_GLONASS_sats_used;
  return n + (v >= 8 ? sizeof z->stats_rtk_fix_progress : 0);
}

// CObservationGPS v0: bool + GGA block, bool + RMC block (sizeof each content). v1-9: v3+
// uint64 timestamp, bool + GGA fields, bool + RMC fields, v2+ sensorLabel, v4+ CPose3D, v5+
// bool + PZS fields, v7+ bool has SATS (which MRPT 2.5.8 refuses to read).
Req stepOldGps(Frame& f, const Fields& p) {
  using namespace mrpt::obs::gnss;
  const int v = f.version;
  switch (f.pc) {
    case 0:
      return at(f, 1, v == 0 ? again() : skip(v >= 3 ? 8 : 0));
    case 1:
      return at(f, 2, field(1));
    case 2:
      if (v == 0) return at(f, 3, skip(p.u8() ? sizeof(Message_NMEA_GGA::content_t) : 0));
      return at(f, 3, skip(p.u8() ? oldGgaBytes(v) : 0));
    case 3:
      return at(f, 4, field(1));
    case 4:
      if (v == 0) return at(f, 9, skip(p.u8() ? sizeof(Message_NMEA_RMC::content_t) : 0));
      return at(f, 5, skip(p.u8() ? oldRmcBytes() : 0));
    case 5:
      return at(f, 6, v >= 2 ? string("sensorLabel") : again());
    case 6:
      return at(f, 7, v >= 4 ? object("sensorPose") : again());
    case 7:
      return v >= 5 ? at(f, 8, field(1)) : at(f, 9, again());
    case 8:
      return at(f, 9, skip(p.u8() ? oldPzsBytes(v) : 0));
    case 9:
      return v >= 7 ? at(f, 10, field(1)) : end();
    default:
      return p.u8() ? unwatch() : end();
  }
}

}  // namespace

// CObservationGPS v10-11: two uint64 timestamps, sensorLabel, CPose3D sensorPose, v11 bool,
// uint32 message count; each message an int32 type and, for the fixed-size ones, uint32
// length and bytes (MRPT checks the length against the type's).
Req stepGps(Frame& f, const Fields& p) {
  if (f.version < 10) return stepOldGps(f, p);
  switch (f.pc) {
    case 0:
      return at(f, 1, skip(16));
    case 1:
      return at(f, 2, string("sensorLabel"));
    case 2:
      return at(f, 3, object("sensorPose"));
    case 3:
      return at(f, 4, skip(f.version >= 11 ? 1 : 0));
    case 4:
      return at(f, 5, field(4));
    case 5:
      f.n = p.u32();
      f.i = 0;
      return at(f, 6, again());
    case 6:
      if (f.i == f.n) return end();
      ++f.i;
      return at(f, 7, field(4));
    case 7:
      return isVariableGnssMessage(p.i32()) ? unwatch() : at(f, 8, field(4));
    case 8: {
      const std::uint64_t bytes = p.u32();
      p.claim(f, bytes, "a " + std::to_string(bytes) + "-byte GNSS message");
      return at(f, 6, skip(bytes));
    }
    default:
      return unwatch();
  }
}

// CObservationImage: CPose3D cameraPose, v4 TCamera (v<4 two CMatrixF), CImage image, v1+
// timestamp, v2-3 focal length double, v3+ sensorLabel.
Req stepObsImage(Frame& f, const Fields&) {
  const int v = f.version;
  switch (f.pc) {
    case 0:
      return at(f, 1, object("cameraPose"));
    case 1:
      return v >= 4 ? at(f, 3, object("cameraParams")) : at(f, 2, object("distortion"));
    case 2:
      return at(f, 3, object("intrinsicParams"));
    case 3:
      return at(f, 4, object("image"));
    case 4:
      return at(f, 5, skip((v >= 1 ? 8 : 0) + (v == 2 || v == 3 ? 8 : 0)));
    case 5:
      return at(f, 6, v >= 3 ? string("sensorLabel") : again());
    default:
      return end();
  }
}

}  // namespace dynslam::io::detail::format
