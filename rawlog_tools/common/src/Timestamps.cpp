#include "dynslam/rawlog_tools/Timestamps.h"

namespace dynslam::rawlog_tools {
namespace {
// 100 ns ticks between MRPT's epoch (1601-01-01) and the Unix epoch, as in Clock::fromDouble.
constexpr int64_t kUnixEpochInMrptTicks = INT64_C(116444736000000000);
}  // namespace

mrpt::Clock::time_point timeFromNanoseconds(int64_t nanoseconds) {
  // Round to the nearest tick (floor division works for negative stamps too).
  const int64_t shifted = nanoseconds + 50;
  int64_t ticks = shifted / 100;
  if (shifted % 100 < 0) --ticks;
  return mrpt::Clock::time_point(mrpt::Clock::duration(ticks + kUnixEpochInMrptTicks));
}

double secondsFromNanoseconds(int64_t nanoseconds) {
  const int64_t whole = nanoseconds / 1'000'000'000;
  const int64_t rest = nanoseconds % 1'000'000'000;
  return static_cast<double>(whole) + static_cast<double>(rest) * 1e-9;
}

}  // namespace dynslam::rawlog_tools
