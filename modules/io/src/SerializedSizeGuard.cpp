#include "SerializedSizeGuard.h"

#include "SerializedFormat.h"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <vector>

namespace dynslam::io::detail {

using format::Frame;
using format::Kind;
using format::Req;

// Walks the bytes of one top-level object as they arrive, in whatever pieces the Read() calls
// cut them: a stack of frames (the object, its nested objects and strings), each stepped
// through its class's fields by format::step(). A field is gathered until complete, so a size
// is seen within the Read() that delivers its last byte.
class SerializedSizeGuard::Parser final : public format::Fields {
 public:
  explicit Parser(std::uint64_t limit) : limit_(limit) {}

  void begin() {
    stack_.clear();
    stack_.emplace_back(Kind::Header, "");
    active_ = true;
    done_ = false;
    skip_ = 0;
    run();
  }
  void abandon() { active_ = false; }
  bool done() const { return done_; }

  void feed(const std::uint8_t* p, std::size_t n) {
    while (active_ && n > 0) {
      if (skip_ > 0) {
        const auto take = static_cast<std::size_t>(std::min<std::uint64_t>(skip_, n));
        skip_ -= take;
        p += take;
        n -= take;
        if (skip_ == 0) run();
        continue;
      }
      const auto take = std::min(want_ - have_, n);
      std::memcpy(buf_.data() + have_, p, take);
      have_ += take;
      p += take;
      n -= take;
      if (have_ == want_) finishField();
    }
  }

  std::uint8_t u8() const override { return buf_[0]; }
  std::uint32_t u32() const override {
    std::uint32_t v;
    std::memcpy(&v, buf_.data(), 4);
    return v;
  }
  std::string text() const override {
    return std::string(reinterpret_cast<const char*>(buf_.data()), want_);
  }
  void claim(const Frame& f, std::uint64_t bytes, const std::string& what) const override;

 private:
  void finishField();
  void run();

  std::uint64_t limit_;
  std::vector<Frame> stack_;
  bool active_ = false;
  bool done_ = false;  // the top-level object's end byte was reached
  bool awaiting_end_ = false;
  std::uint64_t skip_ = 0;
  std::size_t want_ = 0, have_ = 0;
  std::vector<std::uint8_t> buf_ = std::vector<std::uint8_t>(128);  // longest class name: 127
};

void SerializedSizeGuard::Parser::finishField() {
  if (awaiting_end_) {
    awaiting_end_ = false;
    // A missing end flag makes MRPT throw; either way this object is over for the guard.
    if (u8() != format::kEndFlag) {
      active_ = false;
      return;
    }
    stack_.pop_back();
    if (stack_.empty()) {
      active_ = false;
      done_ = true;
      return;
    }
  }
  run();
}

// Steps the innermost frame until it asks for bytes (or the object is given up).
void SerializedSizeGuard::Parser::run() {
  while (active_) {
    const Req r = format::step(stack_.back(), *this);
    switch (r.op) {
      case Req::Field:
      case Req::End:
        want_ = static_cast<std::size_t>(r.op == Req::End ? 1 : r.n);
        have_ = 0;
        awaiting_end_ = r.op == Req::End;
        return;
      case Req::Skip:
        if (r.n == 0) continue;
        skip_ = r.n;
        return;
      case Req::Object:
        stack_.emplace_back(Kind::Header, r.label);
        continue;
      case Req::Inline:
        stack_.emplace_back(r.kind, r.label);
        continue;
      case Req::Return:
        stack_.pop_back();
        continue;
      case Req::Again:
        continue;
      case Req::Unwatch:
        active_ = false;
        return;
    }
  }
}

void SerializedSizeGuard::Parser::claim(const Frame& f, std::uint64_t bytes,
                                        const std::string& what) const {
  if (bytes <= limit_) return;
  // Name the observation that makes the claim, not a member object of it.
  std::string owner;
  for (auto it = stack_.rbegin(); it != stack_.rend() && owner.empty(); ++it)
    if (format::isObservation(it->kind)) owner = it->cls;
  if (owner.empty()) owner = !stack_.front().cls.empty() ? stack_.front().cls : f.cls;
  throw SizeLimitExceeded("a " + owner + " claims " + what + " (" + humanBytes(bytes) +
                          "), over the " + humanBytes(limit_) +
                          " limit for one field ([SensorSync] max_observation_mb)");
}

SerializedSizeGuard::SerializedSizeGuard(std::uint64_t max_field_bytes)
    : max_field_bytes_(max_field_bytes), parser_(std::make_unique<Parser>(max_field_bytes)) {}

SerializedSizeGuard::~SerializedSizeGuard() = default;

void SerializedSizeGuard::beginObject() {
  refusal_.clear();
  parser_->begin();
}

bool SerializedSizeGuard::followedToEnd() const { return parser_->done(); }

void SerializedSizeGuard::checkRequest(std::size_t count) {
  // The catch-all for what the parser does not model: no field is bigger than the limit.
  if (count > max_field_bytes_)
    refuse("a read of " + std::to_string(count) + " bytes (" + humanBytes(count) +
           ") is over the " + humanBytes(max_field_bytes_) +
           " limit for one field ([SensorSync] max_observation_mb)");
}

void SerializedSizeGuard::observe(const void* data, std::size_t n) {
  try {
    parser_->feed(static_cast<const std::uint8_t*>(data), n);
  } catch (const SizeLimitExceeded& e) {
    parser_->abandon();  // MRPT does not go on with this object; nothing more to follow
    refusal_ = e.what();
    throw;
  }
}

void SerializedSizeGuard::refuse(const std::string& message) {
  parser_->abandon();
  refusal_ = message;
  throw SizeLimitExceeded(message);
}

std::string humanBytes(std::uint64_t bytes) {
  static const char* const units[] = {"bytes", "KB", "MB", "GB", "TB", "PB", "EB"};
  double v = static_cast<double>(bytes);
  int u = 0;
  while (v >= 1024 && u < 6) {
    v /= 1024;
    ++u;
  }
  char text[48];
  if (u == 0 || v == static_cast<double>(static_cast<std::uint64_t>(v)))
    std::snprintf(text, sizeof text, "%.0f %s", v, units[u]);
  else
    std::snprintf(text, sizeof text, "%.1f %s", v, units[u]);
  return text;
}

}  // namespace dynslam::io::detail
