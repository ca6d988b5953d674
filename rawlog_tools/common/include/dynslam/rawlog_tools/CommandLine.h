#pragma once
// A small "--flag value" / "--switch" parser shared by the converters. Unknown flags, missing
// values and badly formed numbers are errors (ConversionError naming the flag), because a typo
// that silently falls back to a default produces a wrong dataset.
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace dynslam::rawlog_tools {

class CommandLine {
 public:
  /// valueFlags take a value ("--in DIR"); switches do not ("--embed-images"). Names include
  /// the leading "--". "--help" / "-h" is always accepted as a switch.
  CommandLine(std::set<std::string> valueFlags, std::set<std::string> switches);

  /// Throws ConversionError on unknown flags, repeated flags or a value flag without a value.
  void parse(int argc, const char* const* argv);

  bool helpRequested() const { return help_; }
  bool has(const std::string& flag) const;
  /// The value of a flag that must be given; throws naming the flag when absent.
  std::string required(const std::string& flag) const;
  std::string valueOr(const std::string& flag, const std::string& fallback) const;
  std::optional<double> optionalDouble(const std::string& flag) const;
  std::optional<long long> optionalInteger(const std::string& flag) const;

 private:
  std::set<std::string> valueFlags_;
  std::set<std::string> switches_;
  std::map<std::string, std::string> values_;
  bool help_ = false;
};

/// Runs a converter body, printing "<program>: error: <what>" to stderr and returning 1 on any
/// exception, 0 otherwise. Keeps every main() down to argument handling.
template <typename Body>
int runConverter(const char* program, Body&& body);

}  // namespace dynslam::rawlog_tools

#include <exception>
#include <iostream>

template <typename Body>
int dynslam::rawlog_tools::runConverter(const char* program, Body&& body) {
  try {
    return body();
  } catch (const std::exception& e) {
    std::cerr << program << ": error: " << e.what() << "\n";
    return 1;
  }
}
