#include "dynslam/core/CommandLine.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>

namespace dynslam::core {

CommandLine::CommandLine(std::set<std::string> valueFlags, std::set<std::string> switches,
                         std::set<std::string> repeatableFlags, size_t maxPositional)
    : valueFlags_(std::move(valueFlags)),
      switches_(std::move(switches)),
      repeatable_(std::move(repeatableFlags)),
      maxPositional_(maxPositional) {
  valueFlags_.insert(repeatable_.begin(), repeatable_.end());
}

void CommandLine::parse(int argc, const char* const* argv) {
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--help" || arg == "-h") {
      help_ = true;
      continue;
    }
    if (arg.rfind("--", 0) != 0 || arg.size() == 2) {
      if (positional_.size() >= maxPositional_)
        throw UsageError("unexpected argument '" + arg + "'");
      positional_.push_back(arg);
      continue;
    }
    const bool isValueFlag = valueFlags_.count(arg) > 0;
    if (!isValueFlag && switches_.count(arg) == 0)
      throw UsageError("unknown argument '" + arg + "'");
    if (values_.count(arg) && !repeatable_.count(arg))
      throw UsageError("flag " + arg + " given twice");
    if (!isValueFlag) {
      values_[arg].push_back("");
      continue;
    }
    if (i + 1 >= argc) throw UsageError("flag " + arg + " needs a value");
    values_[arg].push_back(argv[++i]);
  }
}

bool CommandLine::has(const std::string& flag) const { return values_.count(flag) > 0; }

std::string CommandLine::required(const std::string& flag) const {
  const auto it = values_.find(flag);
  if (it == values_.end() || it->second.back().empty())
    throw UsageError("missing required flag " + flag);
  return it->second.back();
}

std::string CommandLine::valueOr(const std::string& flag, const std::string& fallback) const {
  const auto it = values_.find(flag);
  return it == values_.end() ? fallback : it->second.back();
}

std::vector<std::string> CommandLine::all(const std::string& flag) const {
  const auto it = values_.find(flag);
  return it == values_.end() ? std::vector<std::string>{} : it->second;
}

std::optional<double> CommandLine::optionalDouble(const std::string& flag) const {
  if (!has(flag)) return std::nullopt;
  const std::string value = valueOr(flag, "");
  char* end = nullptr;
  errno = 0;
  const double v = std::strtod(value.c_str(), &end);
  if (end == value.c_str() || *end != '\0' || errno == ERANGE || !std::isfinite(v))
    throw UsageError("flag " + flag + ": '" + value + "' is not a finite number");
  return v;
}

std::optional<long long> CommandLine::optionalInteger(const std::string& flag) const {
  if (!has(flag)) return std::nullopt;
  const std::string value = valueOr(flag, "");
  char* end = nullptr;
  errno = 0;
  const long long v = std::strtoll(value.c_str(), &end, 10);
  if (end == value.c_str() || *end != '\0' || errno == ERANGE)
    throw UsageError("flag " + flag + ": '" + value + "' is not an integer");
  return v;
}

std::string userMessage(const std::string& what) {
  if (what.rfind("==== MRPT exception", 0) != 0) return what;
  const auto message = what.find("Message:");
  const auto start =
      message == std::string::npos ? message : what.find_first_not_of(' ', message + 8);
  if (start == std::string::npos) return what;
  return what.substr(start, what.find('\n', start) - start);
}

}  // namespace dynslam::core
