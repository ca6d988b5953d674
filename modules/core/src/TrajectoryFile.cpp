#include "dynslam/core/TrajectoryFile.h"

#include "dynslam/core/AtomicFile.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <limits>
#include <sstream>
#include <string_view>
#include <vector>

namespace dynslam::core {
namespace {

[[noreturn]] void failAtLine(const std::string& path, std::size_t line_no,
                             const std::string& what) {
  throw TrajectoryFileError(path + ":" + std::to_string(line_no) + ": " + what);
}

std::ifstream openForReading(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw TrajectoryFileError("cannot open trajectory file '" + path + "'");
  return in;
}

/// True for lines that carry no pose: blank ones and '#' comments (evo skips lines starting with
/// '#'; leading blanks before the '#' are tolerated too).
bool isSkippable(std::string_view line) {
  const auto first = line.find_first_not_of(" \t\r");
  return first == std::string_view::npos || line[first] == '#';
}

/// Splits a line into fields separated by blanks and/or commas. A run of blanks counts as one
/// separator; an empty field between two commas is kept so that it is reported, not skipped.
std::vector<std::string_view> splitFields(std::string_view line) {
  std::vector<std::string_view> fields;
  std::size_t i = 0;
  const auto isBlank = [](char c) { return c == ' ' || c == '\t' || c == '\r'; };
  while (i < line.size() && isBlank(line[i])) ++i;
  while (i < line.size()) {
    std::size_t end = i;
    while (end < line.size() && !isBlank(line[end]) && line[end] != ',') ++end;
    fields.push_back(line.substr(i, end - i));
    i = end;
    while (i < line.size() && isBlank(line[i])) ++i;
    if (i < line.size() && line[i] == ',') {
      ++i;
      while (i < line.size() && isBlank(line[i])) ++i;
      if (i == line.size()) fields.emplace_back();  // trailing comma: an empty last field
    }
  }
  return fields;
}

/// Parses every field as a finite double; reports the first bad field by its 1-based column.
std::vector<double> parseNumbers(const std::vector<std::string_view>& fields,
                                 const std::string& path, std::size_t line_no) {
  std::vector<double> values;
  values.reserve(fields.size());
  for (std::size_t k = 0; k < fields.size(); ++k) {
    std::string_view f = fields[k];
    if (!f.empty() && f.front() == '+') f.remove_prefix(1);  // from_chars rejects a '+' sign
    double v = 0.0;
    const auto [ptr, ec] = std::from_chars(f.data(), f.data() + f.size(), v);
    if (f.empty() || ec != std::errc() || ptr != f.data() + f.size() || !std::isfinite(v)) {
      failAtLine(path, line_no,
                 "field " + std::to_string(k + 1) + " ('" + std::string(fields[k]) +
                     "') is not a finite number");
    }
    values.push_back(v);
  }
  return values;
}

/// Rotation from a quaternion given as (w, x, y, z), normalised first (evo normalises too).
Eigen::Matrix3d rotationFromQuaternion(double w, double x, double y, double z,
                                       const std::string& path, std::size_t line_no) {
  const double norm = std::sqrt(w * w + x * x + y * y + z * z);
  if (!(norm > 1e-12)) failAtLine(path, line_no, "quaternion has zero length");
  return Eigen::Quaterniond(w / norm, x / norm, y / norm, z / norm).toRotationMatrix();
}

/// Visits every pose line of a file with its 1-based line number and its numbers, after
/// checking the field count.
template <typename OnLine>
void forEachDataLine(const std::string& path, std::size_t min_fields, std::size_t max_fields,
                     const char* layout, OnLine&& on_line) {
  std::ifstream in = openForReading(path);
  std::string line;
  std::size_t line_no = 0;
  while (std::getline(in, line)) {
    ++line_no;
    if (isSkippable(line)) continue;
    const auto fields = splitFields(line);
    if (fields.size() < min_fields || fields.size() > max_fields) {
      const std::string expected = min_fields == max_fields
                                       ? std::to_string(min_fields)
                                       : "at least " + std::to_string(min_fields);
      failAtLine(path, line_no,
                 "expected " + expected + " fields (" + layout + "), found " +
                     std::to_string(fields.size()));
    }
    on_line(line_no, parseNumbers(fields, path, line_no));
  }
  if (in.bad()) throw TrajectoryFileError("error while reading trajectory file '" + path + "'");
}

void requireSomePoses(const Trajectory& trajectory, const std::string& path) {
  if (trajectory.empty())
    throw TrajectoryFileError("trajectory file '" + path + "' holds no poses");
}

}  // namespace

TrajectoryFormat parseTrajectoryFormat(const std::string& name) {
  if (name == "tum") return TrajectoryFormat::Tum;
  if (name == "kitti") return TrajectoryFormat::Kitti;
  if (name == "euroc") return TrajectoryFormat::Euroc;
  throw std::invalid_argument("unknown trajectory format '" + name +
                              "' (expected tum, kitti or euroc)");
}

Trajectory readTrajectory(const std::string& path, TrajectoryFormat format) {
  switch (format) {
    case TrajectoryFormat::Tum:
      return readTum(path);
    case TrajectoryFormat::Kitti:
      return readKitti(path);
    case TrajectoryFormat::Euroc:
      return readEurocCsv(path);
  }
  throw std::invalid_argument("unknown trajectory format");
}

Trajectory readTum(const std::string& path) {
  Trajectory trajectory;
  forEachDataLine(path, 8, 8, "timestamp tx ty tz qx qy qz qw",
                  [&](std::size_t line_no, const std::vector<double>& v) {
                    StampedPose pose;
                    pose.t = v[0];
                    pose.T_world_body.linear() =
                        rotationFromQuaternion(v[7], v[4], v[5], v[6], path, line_no);
                    pose.T_world_body.translation() = Eigen::Vector3d(v[1], v[2], v[3]);
                    trajectory.push_back(pose);
                  });
  requireSomePoses(trajectory, path);
  return trajectory;
}

Trajectory readKitti(const std::string& path) {
  Trajectory trajectory;
  forEachDataLine(path, 12, 12, "row-major 3x4 [R|t]",
                  [&](std::size_t, const std::vector<double>& v) {
                    StampedPose pose;
                    // evo pairs KITTI poses by index, so the index is the time.
                    pose.t = static_cast<double>(trajectory.size());
                    // Kept exactly as written (not re-orthonormalised), as evo keeps them.
                    Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
                    for (int r = 0; r < 3; ++r)
                      for (int c = 0; c < 4; ++c) m(r, c) = v[static_cast<std::size_t>(4 * r + c)];
                    pose.T_world_body.matrix() = m;
                    trajectory.push_back(pose);
                  });
  requireSomePoses(trajectory, path);
  return trajectory;
}

Trajectory readEurocCsv(const std::string& path) {
  Trajectory trajectory;
  forEachDataLine(path, 8, std::numeric_limits<std::size_t>::max(),
                  "timestamp[ns], p_x, p_y, p_z, q_w, q_x, q_y, q_z, ...",
                  [&](std::size_t line_no, const std::vector<double>& v) {
                    StampedPose pose;
                    // Same arithmetic as evo (ns parsed as a double, then divided), so that
                    // associations with a tolerance edge come out the same.
                    pose.t = v[0] / 1e9;
                    pose.T_world_body.linear() =
                        rotationFromQuaternion(v[4], v[5], v[6], v[7], path, line_no);
                    pose.T_world_body.translation() = Eigen::Vector3d(v[1], v[2], v[3]);
                    trajectory.push_back(pose);
                  });
  requireSomePoses(trajectory, path);
  return trajectory;
}

void appendTumLine(std::ostream& out, const StampedPose& pose) {
  Eigen::Quaterniond q(pose.T_world_body.rotation());
  q.normalize();
  if (q.w() < 0) q.coeffs() = -q.coeffs();
  const Eigen::Vector3d p = pose.T_world_body.translation();
  const auto old_precision = out.precision(17);
  out << pose.t << ' ' << p.x() << ' ' << p.y() << ' ' << p.z() << ' ' << q.x() << ' ' << q.y()
      << ' ' << q.z() << ' ' << q.w() << '\n';
  out.precision(old_precision);
}

void writeTum(const std::string& path, const Trajectory& trajectory) {
  AtomicTextFile file(path);
  for (const auto& pose : trajectory) appendTumLine(file.stream(), pose);
  try {
    file.commit();
  } catch (const std::runtime_error& e) {
    throw TrajectoryFileError(std::string("trajectory file: ") + e.what());
  }
}

}  // namespace dynslam::core
