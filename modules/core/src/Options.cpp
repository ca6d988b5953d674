#include "dynslam/core/Options.h"

#include <mrpt/config/CConfigFileBase.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>

namespace dynslam::core {

bool Range::contains(double v) const {
  if (std::isnan(v)) return false;
  const bool aboveMin = min_open ? v > min : v >= min;
  const bool belowMax = max_open ? v < max : v <= max;
  return aboveMin && belowMax;
}

std::string Range::text() const {
  const bool hasMin = std::isfinite(min), hasMax = std::isfinite(max);
  if (!hasMin && !hasMax) return "any";
  if (!hasMax) return (min_open ? "> " : ">= ") + formatNumber(min);
  if (!hasMin) return (max_open ? "< " : "<= ") + formatNumber(max);
  return (min_open ? "(" : "[") + formatNumber(min) + ", " + formatNumber(max) +
         (max_open ? ")" : "]");
}

std::string formatNumber(double value) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.10g", value);
  return buf;
}

namespace {

std::string trimmed(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r\n");
  if (b == std::string::npos) return {};
  return s.substr(b, s.find_last_not_of(" \t\r\n") - b + 1);
}

void requireInRange(const std::string& name, double value, const Range& range) {
  if (!range.contains(value))
    throw std::invalid_argument(name + " = " + formatNumber(value) + ": must be " +
                                (range.text()[0] == '[' || range.text()[0] == '(' ? "in " : "") +
                                range.text());
}

void requireBoth(const std::string& name, bool is_set, const std::string& needed,
                 bool needed_holds) {
  if (is_set && !needed_holds)
    throw std::invalid_argument(name + " is set, but it acts only with " + needed +
                                ": set both, or neither");
}

/// Reads each key present in the section, refusing what is not a value of its kind.
class Loader : public OptionVisitor {
 public:
  Loader(const mrpt::config::CConfigFileBase& c, const std::string& section)
      : c_(c), section_(section) {}

  void key(const std::string& name, double& value, Range range, const std::string&) override {
    if (!present(name)) return;
    const std::string text = raw(name);
    char* end = nullptr;
    errno = 0;
    const double v = std::strtod(text.c_str(), &end);
    if (text.empty() || *end != '\0' || errno == ERANGE)
      throw std::invalid_argument(name + " = '" + text + "': expected a number");
    requireInRange(name, v, range);
    value = v;
  }
  void key(const std::string& name, int& value, Range range, const std::string&) override {
    if (!present(name)) return;
    const std::string text = raw(name);
    char* end = nullptr;
    errno = 0;
    const long v = std::strtol(text.c_str(), &end, 10);
    if (text.empty() || *end != '\0' || errno == ERANGE || v < INT32_MIN || v > INT32_MAX)
      throw std::invalid_argument(name + " = '" + text + "': expected a whole number");
    requireInRange(name, double(v), range);
    value = int(v);
  }
  void key(const std::string& name, bool& value, const std::string&) override {
    value = readBool(c_, section_, name, value);
  }
  void key(const std::string& name, std::string& value, const std::string&) override {
    value = c_.read_string(section_, name, value);
  }
  void word(const std::string& name, std::string& value, const std::vector<std::string>& words,
            const std::string&) override {
    value = readOneOf(c_, section_, name, value, words);
  }
  /// Only a key the section itself sets: a default that acts through a setting the ini turned
  /// off (reid_max_distance = 0 with reid_memory's default) is the ini's intent, not a mistake.
  void requires(const std::string& name, bool is_set, const std::string& needed,
                bool needed_holds) override {
    if (present(name)) requireBoth(name, is_set, needed, needed_holds);
  }

 private:
  bool present(const std::string& name) const { return c_.keyExists(section_, name); }
  std::string raw(const std::string& name) const {
    return trimmed(c_.read_string(section_, name, ""));
  }

  const mrpt::config::CConfigFileBase& c_;
  const std::string& section_;
};

/// Checks the values the struct holds now.
class Checker : public OptionVisitor {
 public:
  void key(const std::string& name, double& value, Range range, const std::string&) override {
    requireInRange(name, value, range);
  }
  void key(const std::string& name, int& value, Range range, const std::string&) override {
    requireInRange(name, value, range);
  }
  void key(const std::string&, bool&, const std::string&) override {}
  void key(const std::string&, std::string&, const std::string&) override {}
  void word(const std::string& name, std::string& value, const std::vector<std::string>& words,
            const std::string&) override {
    for (const auto& w : words)
      if (w == value) return;
    throw std::invalid_argument(name + " = '" + value + "': not one of its words");
  }
  void requires(const std::string& name, bool is_set, const std::string& needed,
                bool needed_holds) override {
    requireBoth(name, is_set, needed, needed_holds);
  }
};

class Saver : public OptionVisitor {
 public:
  Saver(mrpt::config::CConfigFileBase& c, const std::string& section) : c_(c), section_(section) {}

  void key(const std::string& name, double& value, Range, const std::string& meaning) override {
    writeKey(c_, section_, name, value, meaning);
  }
  void key(const std::string& name, int& value, Range, const std::string& meaning) override {
    writeKey(c_, section_, name, value, meaning);
  }
  void key(const std::string& name, bool& value, const std::string& meaning) override {
    writeKey(c_, section_, name, value, meaning);
  }
  void key(const std::string& name, std::string& value, const std::string& meaning) override {
    writeKey(c_, section_, name, value, meaning);
  }
  void word(const std::string& name, std::string& value, const std::vector<std::string>&,
            const std::string& meaning) override {
    writeKey(c_, section_, name, value, meaning);
  }

 private:
  mrpt::config::CConfigFileBase& c_;
  const std::string& section_;
};

class Documenter : public OptionVisitor {
 public:
  std::vector<KeyDoc> keys;

  void key(const std::string& name, double& value, Range range,
           const std::string& meaning) override {
    keys.push_back({name, formatNumber(value), range.text(), meaning});
  }
  void key(const std::string& name, int& value, Range range, const std::string& meaning) override {
    keys.push_back({name, std::to_string(value), range.text(), meaning});
  }
  void key(const std::string& name, bool& value, const std::string& meaning) override {
    keys.push_back({name, value ? "true" : "false", "true | false", meaning});
  }
  void key(const std::string& name, std::string& value, const std::string& meaning) override {
    keys.push_back({name, value, "", meaning});
  }
  void word(const std::string& name, std::string& value, const std::vector<std::string>& words,
            const std::string& meaning) override {
    std::string accepts;
    for (const auto& w : words) accepts += (accepts.empty() ? "" : " | ") + w;
    keys.push_back({name, value, accepts, meaning});
  }
  void requires(const std::string& name, bool, const std::string& needed, bool) override {
    for (auto& k : keys)
      if (k.key == name) k.meaning += " (needs " + needed + ")";
  }
};

/// describe() for the visitors that only read the fields.
void describeReading(const Options& options, OptionVisitor& v) {
  const_cast<Options&>(options).describe(v);
}

}  // namespace

void Options::loadFromConfigFile(const mrpt::config::CConfigFileBase& c,
                                 const std::string& section) {
  Loader loader(c, section);
  describe(loader);
}

void Options::saveToConfigFile(mrpt::config::CConfigFileBase& c,
                               const std::string& section) const {
  Saver saver(c, section);
  describeReading(*this, saver);
}

void Options::check() const {
  Checker checker;
  describeReading(*this, checker);
}

std::vector<KeyDoc> describeKeys(const Options& options) {
  Documenter doc;
  describeReading(options, doc);
  return doc.keys;
}

}  // namespace dynslam::core
