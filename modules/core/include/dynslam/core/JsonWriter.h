#pragma once
// A small streaming JSON writer for result files (summary.json, evaluation results): objects,
// arrays, strings with escaping, numbers at full double precision (non-finite -> null).
#include <ostream>
#include <string>
#include <vector>

namespace dynslam::core {

class JsonWriter {
 public:
  explicit JsonWriter(std::ostream& out) : out_(out) {}

  JsonWriter& beginObject();
  JsonWriter& endObject();
  JsonWriter& beginArray();
  JsonWriter& endArray();
  /// Starts a member of the current object; follow with a value or a begin*.
  JsonWriter& key(const std::string& name);

  JsonWriter& value(const std::string& s);
  JsonWriter& value(const char* s) { return value(std::string(s)); }
  JsonWriter& value(double v);
  JsonWriter& value(long long v);
  JsonWriter& value(size_t v) { return value(static_cast<long long>(v)); }
  JsonWriter& value(int v) { return value(static_cast<long long>(v)); }
  JsonWriter& value(bool b);
  JsonWriter& null();

  template <class T>
  JsonWriter& member(const std::string& name, const T& v) {
    key(name);
    return value(v);
  }

  static std::string escape(const std::string& s);

 private:
  void separate();  // comma and indentation before an element
  std::ostream& out_;
  std::vector<bool> first_;  // per open container: no element written yet
  bool after_key_ = false;
};

}  // namespace dynslam::core
