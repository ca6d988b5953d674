#pragma once
// The one error type converters throw: its message names the file (and line, column or field)
// that is wrong, so main() only has to print it and exit non-zero.
#include <stdexcept>
#include <string>

namespace dynslam::rawlog_tools {

struct ConversionError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace dynslam::rawlog_tools
