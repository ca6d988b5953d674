#pragma once
// MRPT observations -> the project's value types. Each function checks what it reads and
// throws ConversionError naming the observation's field when a value is missing or not finite.
#include <dynslam/core/Frame.h>

#include <optional>
#include <stdexcept>

namespace mrpt::obs {
class CObservation3DRangeScan;
class CObservationIMU;
class CObservationGPS;
}  // namespace mrpt::obs

namespace dynslam::io {

struct ConversionError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// Fills t, sensor_label, rgb (BGR), depth (metres along the optical axis, registered to the
/// colour camera when the two cameras differ), the colour intrinsics and T_body_camera (the
/// colour optical frame on the body: sensorPose * relativePoseIntensityWRTDepth, or
/// sensorPose * the optical axes of the depth frame without colour). Loads externally stored
/// images and unloads them again. Throws ConversionError when there is no range image.
void fillFrameFromRgbd(const mrpt::obs::CObservation3DRangeScan& obs, core::Frame& frame);

/// The gyro and/or accelerometer of an IMU observation; nullopt when it has neither (e.g. a
/// magnetometer-only message). Throws ConversionError for a NaN or infinite component.
std::optional<core::ImuSample> imuSampleFrom(const mrpt::obs::CObservationIMU& obs);

/// The IMU's axes on the body frame: its sensorPose.
Eigen::Isometry3d imuPoseOnBody(const mrpt::obs::CObservationIMU& obs);

/// The GGA fix of a GNSS observation (enu left at zero: the origin is the caller's); nullopt
/// when it carries no GGA message.
std::optional<core::GnssFix> gnssFixFrom(const mrpt::obs::CObservationGPS& obs);

}  // namespace dynslam::io
