#pragma once
// MRPT 2.5.8's binary object format as SerializedSizeGuard follows it: the object header and,
// for the classes that matter to a rawlog, the order and size of their fields in every
// version MRPT 2.5.8 reads, as far as needed to know which bytes are a size field.
//
// Each object (or string) being read is a Frame; step() says what the frame reads next: a
// field to look at, bytes to skip, a nested object, or that the class is not modelled.
#include <cstdint>
#include <limits>
#include <string>

namespace dynslam::io::detail::format {

// Header reads an object's marker, class name and version and then becomes one of the classes;
// String is a uint32 length and that many bytes inside an object.
enum class Kind {
  Header,
  String,
  Pose3D,
  Camera,
  MatrixF,
  MatrixD,
  Image,
  RangeScan,
  SensoryFrame,
  Imu,
  Gps,
  ObsImage
};

struct Frame {
  Frame(Kind k, const char* member_label) : kind(k), label(member_label) {}
  Kind kind;
  const char* label;  // the member of the enclosing object this is ("" at the top)
  std::string cls;    // class name without namespaces (objects only)
  int version = 0;
  int pc = 0;  // the next step of the class's field sequence
  bool flag = false;
  std::uint64_t n = 0, i = 0;  // a count and a loop index
  std::int64_t rows = 0, cols = 0;
};

// What a step asks for next: look at the next n bytes (a field), skip n bytes, a nested object,
// an inline sequence (a string), the end-of-object byte, the end of an inline sequence, the
// next step right away, or giving up on the whole top-level object.
struct Req {
  enum Op { Field, Skip, Object, Inline, End, Return, Again, Unwatch } op;
  std::uint64_t n = 0;
  Kind kind = Kind::Header;
  const char* label = "";
};

/// The field a step asked for, and where a step reports the bytes a size field implies.
class Fields {
 public:
  virtual std::uint8_t u8() const = 0;
  virtual std::uint32_t u32() const = 0;  // little-endian, as MRPT writes
  std::int32_t i32() const { return static_cast<std::int32_t>(u32()); }
  virtual std::string text() const = 0;  // the whole field
  /// Throws when `bytes` is over the limit; `what` says what was claimed.
  virtual void claim(const Frame& f, std::uint64_t bytes, const std::string& what) const = 0;

 protected:
  ~Fields() = default;
};

// Building blocks of the class steps.
inline Req field(std::uint64_t n) { return {Req::Field, n}; }
inline Req skip(std::uint64_t n) { return {Req::Skip, n}; }
inline Req object(const char* label) { return {Req::Object, 0, Kind::Header, label}; }
inline Req string(const char* label) { return {Req::Inline, 0, Kind::String, label}; }
inline Req end() { return {Req::End}; }
inline Req again() { return {Req::Again}; }
inline Req unwatch() { return {Req::Unwatch}; }
inline Req at(Frame& f, int pc, Req r) {
  f.pc = pc;
  return r;
}

// Products of stream values saturate instead of wrapping, so no claim can overflow to small.
inline std::uint64_t mul(std::uint64_t a, std::uint64_t b) {
  if (a != 0 && b > std::numeric_limits<std::uint64_t>::max() / a)
    return std::numeric_limits<std::uint64_t>::max();
  return a * b;
}
inline std::uint64_t positive(std::int64_t v) { return v > 0 ? static_cast<std::uint64_t>(v) : 0; }
inline std::string dims(std::int64_t rows, std::int64_t cols) {
  return std::to_string(rows) + " x " + std::to_string(cols);
}
inline std::string member(const Frame& f) {
  return *f.label ? std::string(" for ") + f.label : std::string();
}

// The steps of the observations (SerializedObservationFormat.cpp); the object header, strings
// and the member classes (CPose3D, TCamera, CMatrixF/D, CImage) are in SerializedFormat.cpp.
Req stepRangeScan(Frame& f, const Fields& p);
Req stepSensoryFrame(Frame& f, const Fields& p);
Req stepImu(Frame& f, const Fields& p);
Req stepGps(Frame& f, const Fields& p);
Req stepObsImage(Frame& f, const Fields& p);

/// The next request of frame `f`, after the field it asked for last (in `in`) arrived.
Req step(Frame& f, const Fields& in);
/// An observation (or sensory frame), which a refusal names as the claimant.
bool isObservation(Kind k);

constexpr std::uint8_t kEndFlag = 0x88;  // CArchive's SERIALIZATION_END_FLAG

}  // namespace dynslam::io::detail::format
