#pragma once
// PNG plots drawn with OpenCV only: the summary of an evaluation (top view of the reference and
// the aligned estimate, with legend and axes in metres, above the error over time), and a bar
// chart comparing figures across groups (bench/paper_tables: APE per scenario and variant).
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

/// Grouped bars (e.g. APE RMSE per scenario, one bar per variant), with the value above each
/// bar and a legend of the series; the value axis starts at zero.
struct BarChartInput {
  std::string title;
  std::vector<std::string> groups;          ///< along the horizontal axis
  std::vector<std::string> series;          ///< one bar of each per group (at most 6)
  std::vector<std::vector<double>> values;  ///< values[group][series]; NaN: no bar (missing)
  std::string value_label;                  ///< vertical axis title, e.g. "APE RMSE (m)"
};

/// Draws and writes the PNG; throws EvaluationError when there is no group or series, the
/// values do not match them in number, a value is negative, or the file cannot be written.
void writeBarChartPng(const std::string& path, const BarChartInput& input);

}  // namespace dynslam::evaluation
