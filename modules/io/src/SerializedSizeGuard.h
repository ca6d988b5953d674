#pragma once
// Refuses a corrupt rawlog entry that claims a huge image, matrix, point count or string
// before MRPT allocates it. MRPT's deserializers read a size field and allocate (and often
// zero-fill) at once, so a flipped bit can ask for gigabytes and end in an OOM kill, a
// SIGSEGV on a failed aligned_alloc or std::terminate from a half-built observation. The only
// safe place to refuse is the Read() that delivers the size field, before MRPT sees it.
//
// The guard follows the bytes of one top-level object (the object header, nested objects and
// the fields of the classes it models, in the order MRPT 2.5.8 reads them) and throws from
// that Read(). Classes or versions it does not model are not watched further, but no single
// Read() may ask for more than the limit either.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>

namespace dynslam::io::detail {

/// What the guard throws. MRPT may wrap it in its own exceptions; refusal() keeps the text.
struct SizeLimitExceeded : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class SerializedSizeGuard {
 public:
  explicit SerializedSizeGuard(std::uint64_t max_field_bytes);
  ~SerializedSizeGuard();
  SerializedSizeGuard(const SerializedSizeGuard&) = delete;
  SerializedSizeGuard& operator=(const SerializedSizeGuard&) = delete;

  /// A new top-level object starts with the next byte; forgets any earlier refusal.
  void beginObject();
  /// Before a Read() of `count` bytes: throws SizeLimitExceeded when count is over the limit.
  void checkRequest(std::size_t count);
  /// The bytes a Read() delivered: throws SizeLimitExceeded when they complete a size field
  /// whose allocation would be over the limit.
  void observe(const void* data, std::size_t n);

  /// True once the current object's end byte was reached with every field followed (none of
  /// it unmodelled): tells tests that the model matches MRPT's format.
  bool followedToEnd() const;
  bool refused() const { return !refusal_.empty(); }
  /// The refusal's message ("" when none since beginObject()).
  const std::string& refusal() const { return refusal_; }
  std::uint64_t maxFieldBytes() const { return max_field_bytes_; }

  class Parser;  // the field-by-field model, in the .cpp

 private:
  [[noreturn]] void refuse(const std::string& message);

  std::uint64_t max_field_bytes_;
  std::unique_ptr<Parser> parser_;
  std::string refusal_;
};

/// "512 MB", "8.0 GB", "100 bytes": binary units, for messages.
std::string humanBytes(std::uint64_t bytes);

}  // namespace dynslam::io::detail
