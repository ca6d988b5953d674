#include "dynslam/rawlog_tools/CommandLine.h"

#include "dynslam/rawlog_tools/ConversionError.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>

namespace dynslam::rawlog_tools {

CommandLine::CommandLine(std::set<std::string> valueFlags, std::set<std::string> switches)
    : valueFlags_(std::move(valueFlags)), switches_(std::move(switches)) {}

void CommandLine::parse(int argc, const char* const* argv) {
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--help" || arg == "-h") {
      help_ = true;
      continue;
    }
    const bool isValueFlag = valueFlags_.count(arg) > 0;
    if (!isValueFlag && switches_.count(arg) == 0)
      throw ConversionError("unknown argument '" + arg + "' (see --help)");
    if (values_.count(arg)) throw ConversionError("flag " + arg + " given twice");
    if (!isValueFlag) {
      values_[arg] = "";
      continue;
    }
    if (i + 1 >= argc) throw ConversionError("flag " + arg + " needs a value");
    values_[arg] = argv[++i];
  }
}

bool CommandLine::has(const std::string& flag) const { return values_.count(flag) > 0; }

std::string CommandLine::required(const std::string& flag) const {
  const auto it = values_.find(flag);
  if (it == values_.end() || it->second.empty())
    throw ConversionError("missing required flag " + flag + " (see --help)");
  return it->second;
}

std::string CommandLine::valueOr(const std::string& flag, const std::string& fallback) const {
  const auto it = values_.find(flag);
  return it == values_.end() ? fallback : it->second;
}

std::optional<double> CommandLine::optionalDouble(const std::string& flag) const {
  const auto it = values_.find(flag);
  if (it == values_.end()) return std::nullopt;
  const char* text = it->second.c_str();
  char* end = nullptr;
  errno = 0;
  const double v = std::strtod(text, &end);
  if (end == text || *end != '\0' || errno == ERANGE || !std::isfinite(v))
    throw ConversionError("flag " + flag + ": '" + it->second + "' is not a finite number");
  return v;
}

std::optional<long long> CommandLine::optionalInteger(const std::string& flag) const {
  const auto it = values_.find(flag);
  if (it == values_.end()) return std::nullopt;
  const char* text = it->second.c_str();
  char* end = nullptr;
  errno = 0;
  const long long v = std::strtoll(text, &end, 10);
  if (end == text || *end != '\0' || errno == ERANGE)
    throw ConversionError("flag " + flag + ": '" + it->second + "' is not an integer");
  return v;
}

}  // namespace dynslam::rawlog_tools
