#pragma once
// A PNG summary of an evaluation, drawn with OpenCV only: top view of the reference and the
// aligned estimate (with legend and axes in metres) above the error over time.
#include <dynslam/core/Trajectory.h>

#include <string>
#include <vector>

namespace dynslam::evaluation {

/// Which two coordinates the top view shows (x-y by default; KITTI camera poses look down
/// their y axis, so x-z suits them better).
enum class PlotPlane { XY, XZ, YZ };

/// "xy", "xz" or "yz"; throws std::invalid_argument otherwise.
PlotPlane parsePlotPlane(const std::string& name);

struct PlotInput {
  std::string title;
  core::Trajectory reference;
  core::Trajectory estimate;        ///< already aligned
  std::vector<double> error_times;  ///< x of each error sample (e.g. seconds from start)
  std::vector<double> errors;       ///< same length as error_times
  std::string error_label;          ///< y axis label, e.g. "APE (m)"
  std::string time_label = "t (s)";
  PlotPlane plane = PlotPlane::XY;
};

/// Draws and writes the PNG; throws EvaluationError when the input is empty or the file cannot
/// be written.
void writePlotPng(const std::string& path, const PlotInput& input);

}  // namespace dynslam::evaluation
