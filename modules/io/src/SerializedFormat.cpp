#include "SerializedFormat.h"

#include <algorithm>
#include <cstdlib>

namespace dynslam::io::detail::format {
namespace {

// Bytes per pixel of MRPT's PixelDepth (D8U, D8S, D16U, D16S, D32S, D32F, D64F); 1 for values
// MRPT does not know, the least any pixel can take.
std::uint64_t pixelBytes(std::uint32_t depth) {
  static const std::uint64_t bytes[] = {1, 1, 2, 2, 4, 4, 8};
  return depth < 7 ? bytes[depth] : 1;
}

struct ClassModel {
  const char* name;
  Kind kind;
  int min_version, max_version;
};

// The class/version pairs modelled: MRPT 2.5.8 writes the highest version of each and reads
// all of these.
const ClassModel kModels[] = {
    {"CPose3D", Kind::Pose3D, 0, 3},
    {"TCamera", Kind::Camera, 0, 6},
    {"CMatrixF", Kind::MatrixF, 0, 0},
    {"CMatrixD", Kind::MatrixD, 0, 0},
    {"CImage", Kind::Image, 0, 9},
    {"CImage", Kind::Image, 100, 100},
    {"CObservation3DRangeScan", Kind::RangeScan, 0, 10},
    {"CSensoryFrame", Kind::SensoryFrame, 0, 2},
    {"CObservationIMU", Kind::Imu, 0, 4},
    {"CObservationGPS", Kind::Gps, 0, 11},
    {"CObservationImage", Kind::ObsImage, 0, 4},
};

const ClassModel* findModel(const std::string& cls, int version) {
  for (const auto& m : kModels)
    if (cls == m.name && version >= m.min_version && version <= m.max_version) return &m;
  return nullptr;
}

Req stepString(Frame& f, const Fields& p) {
  switch (f.pc) {
    case 0:
      return at(f, 1, field(4));
    case 1:
      f.n = p.u32();
      p.claim(f, f.n, "a " + std::to_string(f.n) + "-byte " + f.label + " string");
      return at(f, 2, skip(f.n));
    default:
      return {Req::Return};
  }
}

// CPose3D: v0 a CMatrixF, v1 a CMatrixD, v2 7 doubles (x y z + quaternion), v3 12 doubles.
Req stepPose3D(Frame& f, const Fields&) {
  if (f.pc == 1) return end();
  if (f.version <= 1) return at(f, 1, object("pose matrix"));
  return at(f, 1, skip(f.version == 2 ? 7 * 8 : 12 * 8));
}

// TCamera: focal length, 5 (v3+: 8) distortion doubles, v<4 a 3x3 CMatrixD (v4+: fx fy cx
// cy), v0 a 1x5 CMatrixD, v2+ nrows ncols, v5+ cameraName, v6+ the distortion model byte.
Req stepCamera(Frame& f, const Fields&) {
  const int v = f.version;
  switch (f.pc) {
    case 0:
      return at(f, 1, skip(8 + 5 * 8 + (v >= 3 ? 3 * 8 : 0)));
    case 1:
      return at(f, 2, v < 4 ? object("intrinsicParams") : skip(4 * 8));
    case 2:
      return at(f, 3, v == 0 ? object("distortionParams") : again());
    case 3:
      return at(f, 4, skip(v >= 2 ? 8 : 0));
    case 4:
      return at(f, 5, v >= 5 ? string("cameraName") : again());
    case 5:
      return at(f, 6, skip(v >= 6 ? 1 : 0));
    default:
      return end();
  }
}

// CMatrixF / CMatrixD v0: uint32 rows, uint32 cols, then the elements (setSize allocates).
Req stepMatrix(Frame& f, const Fields& p) {
  const std::uint64_t elem = f.kind == Kind::MatrixF ? 4 : 8;
  switch (f.pc) {
    case 0:
      return at(f, 1, field(4));
    case 1:
      f.rows = p.u32();
      return at(f, 2, field(4));
    case 2: {
      f.cols = p.u32();
      const auto bytes = mul(mul(f.rows, f.cols), elem);
      p.claim(f, bytes, "a " + dims(f.rows, f.cols) + " " + f.label + " matrix");
      return at(f, 3, skip(bytes));
    }
    default:
      return end();
  }
}

// CImage grey (v2-9): int32 width, height, origin, imageSize, v9+ int32 pixel depth, then
// v5+ a "zipped" byte and the raw pixels. resize() allocates before imageSize is checked.
Req stepGreyImage(Frame& f, const Fields& p) {
  const int v = f.version;
  switch (f.pc) {
    case 10:
      return at(f, 11, field(4));
    case 11:
      f.cols = p.i32();
      return at(f, 12, field(4));
    case 12:
      f.rows = p.i32();
      return at(f, 13, skip(4));  // origin
    case 13:
      return at(f, 14, field(4));
    case 14:
      f.n = p.u32();
      return at(f, 15, v >= 9 ? field(4) : again());
    case 15: {
      const std::uint64_t px = v >= 9 ? pixelBytes(p.u32()) : 1;
      p.claim(f, mul(mul(positive(f.cols), positive(f.rows)), px),
              "a " + dims(f.cols, f.rows) + " grey image" + member(f));
      if (v >= 5) return at(f, 16, field(1));
      // v3 and v4 (over 16 KB) were zipped, which MRPT 2.5.8 refuses after one more field.
      if (v == 2 || (v == 4 && f.n <= 16 * 1024)) return at(f, 17, skip(f.n));
      return unwatch();
    }
    case 16:
      return p.u8() ? unwatch() : at(f, 17, skip(f.n));
    default:
      return end();
  }
}

// CImage colour: v7+ int32 width, height (both >= 1: JPEG follows; both negative: raw BGR of
// -w x -h; otherwise an empty image), then for JPEG uint32 nBytes and the bytes. The JPEG
// decoder allocates by the JPEG's own header, so width x height of a JPEG is checked too: a
// valid stream's values are the image's.
Req stepColourImage(Frame& f, const Fields& p) {
  switch (f.pc) {
    case 20:
      return at(f, 21, field(4));
    case 21:
      f.cols = p.i32();
      return at(f, 22, field(4));
    case 22: {
      f.rows = p.i32();
      const bool raw = f.cols < 0 && f.rows < 0;
      if (!raw && (f.cols < 1 || f.rows < 1)) return end();
      const auto bytes = mul(mul(raw ? -f.cols : f.cols, raw ? -f.rows : f.rows), 3);
      p.claim(f, bytes,
              "a " + dims(std::llabs(f.cols), std::llabs(f.rows)) + " colour image" + member(f));
      return raw ? at(f, 24, skip(bytes)) : at(f, 23, field(4));
    }
    case 23: {
      const std::uint64_t bytes = p.u32();
      p.claim(f, bytes, "a " + std::to_string(bytes) + "-byte JPEG" + member(f));
      return at(f, 24, skip(bytes));
    }
    default:
      return end();
  }
}

// CImage v0: uint32 width, height, channels, uint8 origin, uint32 length, raw bytes.
// v1: uint32 nBytes of JPEG.
Req stepOldImage(Frame& f, const Fields& p) {
  switch (f.pc) {
    case 30:
      return at(f, 31, field(4));
    case 31:
      f.cols = p.u32();
      return at(f, 32, field(4));
    case 32:
      f.rows = p.u32();
      return at(f, 33, field(4));
    case 33:
      f.n = std::max<std::uint32_t>(p.u32(), 1);
      return at(f, 34, skip(1));
    case 34:
      return at(f, 35, field(4));
    case 35: {
      const std::uint64_t length = p.u32();
      p.claim(f, std::max(mul(mul(f.cols, f.rows), f.n), length),
              "a " + dims(f.cols, f.rows) + " image of " + std::to_string(f.n) + " channels" +
                  member(f));
      return at(f, 99, skip(length));
    }
    case 40:
      return at(f, 41, field(4));
    case 41: {
      const std::uint64_t bytes = p.u32();
      p.claim(f, bytes, "a " + std::to_string(bytes) + "-byte JPEG" + member(f));
      return at(f, 99, skip(bytes));
    }
    default:
      return end();
  }
}

Req stepImage(Frame& f, const Fields& p) {
  const int v = f.version;
  if (f.pc >= 30) return stepOldImage(f, p);
  if (f.pc >= 20) return stepColourImage(f, p);
  if (f.pc >= 10) return stepGreyImage(f, p);
  switch (f.pc) {
    case 0:
      if (v == 0) return at(f, 30, again());
      if (v == 1) return at(f, 40, again());
      return v >= 6 ? at(f, 1, field(1)) : at(f, 2, again());
    case 1:  // external storage: just the file name
      if (p.u8()) return at(f, 3, string("externalFile"));
      return v == 100 ? end() : at(f, 2, again());
    case 2:
      return at(f, 4, field(1));  // has colour
    case 4:
      if (!p.u8()) return at(f, 10, again());
      return v >= 7 ? at(f, 20, again()) : at(f, 23, field(4));
    default:
      return end();
  }
}

// Object header (CArchive::internal_ReadObjectHeader): a byte 0x80 | name length, the class
// name, and unless it is "nullptr" a version byte; the object then reads as its class.
Req stepHeader(Frame& f, const Fields& in) {
  switch (f.pc) {
    case 0:
      return at(f, 1, field(1));
    case 1: {
      const std::uint8_t b = in.u8();
      const auto len = static_cast<std::size_t>(b & 0x7F);
      // Without the 0x80 bit it is the pre-0.5.5 header, not modelled.
      if (!(b & 0x80) || len == 0 || len > 120) return unwatch();
      return at(f, 2, field(len));
    }
    case 2: {
      const std::string name = in.text();
      if (name == "nullptr") return end();
      const auto colon = name.rfind("::");
      f.cls = colon == std::string::npos ? name : name.substr(colon + 2);
      return at(f, 3, field(1));
    }
    default: {
      f.version = in.u8();
      const ClassModel* m = findModel(f.cls, f.version);
      if (!m) return unwatch();
      f.kind = m->kind;
      return at(f, 0, again());
    }
  }
}

}  // namespace

Req step(Frame& f, const Fields& in) {
  switch (f.kind) {
    case Kind::Header:
      return stepHeader(f, in);
    case Kind::String:
      return stepString(f, in);
    case Kind::Pose3D:
      return stepPose3D(f, in);
    case Kind::Camera:
      return stepCamera(f, in);
    case Kind::MatrixF:
    case Kind::MatrixD:
      return stepMatrix(f, in);
    case Kind::Image:
      return stepImage(f, in);
    case Kind::RangeScan:
      return stepRangeScan(f, in);
    case Kind::SensoryFrame:
      return stepSensoryFrame(f, in);
    case Kind::Imu:
      return stepImu(f, in);
    case Kind::Gps:
      return stepGps(f, in);
    case Kind::ObsImage:
      return stepObsImage(f, in);
  }
  return unwatch();
}

bool isObservation(Kind k) {
  return k == Kind::RangeScan || k == Kind::SensoryFrame || k == Kind::Imu || k == Kind::Gps ||
         k == Kind::ObsImage;
}

}  // namespace dynslam::io::detail::format
