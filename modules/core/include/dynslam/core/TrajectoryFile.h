#pragma once
// Reading and writing trajectory files in the layouts evo reads:
//  - TUM:   "timestamp tx ty tz qx qy qz qw" per line; fields separated by blanks and/or
//           commas; blank lines and '#' comments skipped; the quaternion is normalised.
//  - KITTI: 12 numbers per line (row-major 3x4 [R|t]), kept as written (not re-orthonormalised);
//           no timestamps: pose i gets t = i, as evo pairs KITTI files by index.
//  - EuRoC: the ground-truth csv "#timestamp[ns], p_x, p_y, p_z, q_w, q_x, q_y, q_z, ..." (extra
//           columns such as velocity and biases ignored); t = ns / 1e9 in double, like evo.
// Errors throw TrajectoryFileError naming the file and, for a malformed line, its 1-based line
// number ("path:line: what"); a missing, unreadable or pose-less file is an error too.
#include <dynslam/core/Trajectory.h>

#include <iosfwd>
#include <stdexcept>
#include <string>

namespace dynslam::core {

enum class TrajectoryFormat { Tum, Kitti, Euroc };

struct TrajectoryFileError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// Parses "tum", "kitti" or "euroc"; throws std::invalid_argument otherwise.
TrajectoryFormat parseTrajectoryFormat(const std::string& name);

Trajectory readTrajectory(const std::string& path, TrajectoryFormat format);
Trajectory readTum(const std::string& path);
Trajectory readKitti(const std::string& path);
Trajectory readEurocCsv(const std::string& path);

/// Writes TUM lines with full double precision (17 significant digits), quaternion with qw >= 0.
/// Throws TrajectoryFileError when the file cannot be written.
void writeTum(const std::string& path, const Trajectory& trajectory);

/// Appends one pose as a TUM line to an open stream (writers that flush as they go use it).
void appendTumLine(std::ostream& out, const StampedPose& pose);

}  // namespace dynslam::core
