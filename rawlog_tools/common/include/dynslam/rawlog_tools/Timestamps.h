#pragma once
// Conversions from dataset time stamps to MRPT's clock (100 ns ticks since 1601).
// Stamps given as seconds (TUM, 7-Scenes) go through mrpt::Clock::fromDouble directly: a double
// Unix time is only good to ~0.2 us anyway. EuRoC stamps are integer nanoseconds, beyond
// double's 53 bits, so they get an exact integer path here.
#include <mrpt/core/Clock.h>

#include <cstdint>

namespace dynslam::rawlog_tools {

/// Integer nanoseconds since the Unix epoch to MRPT time, rounded to the nearest 100 ns tick.
mrpt::Clock::time_point timeFromNanoseconds(int64_t nanoseconds);

/// Nanoseconds to seconds with the integer part converted separately, so the fraction keeps
/// full double precision.
double secondsFromNanoseconds(int64_t nanoseconds);

}  // namespace dynslam::rawlog_tools
