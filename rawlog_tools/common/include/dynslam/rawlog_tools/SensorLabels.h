#pragma once
// Sensor labels every converter (and every reader of their rawlogs) uses, so a stage can pick
// observations by label without knowing which dataset they came from.

namespace dynslam::rawlog_tools {

inline constexpr const char* kRgbdLabel = "RGBD";
inline constexpr const char* kImuLabel = "IMU";
inline constexpr const char* kGpsLabel = "GPS";

}  // namespace dynslam::rawlog_tools
