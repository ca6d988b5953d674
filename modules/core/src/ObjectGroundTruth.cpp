#include "dynslam/core/ObjectGroundTruth.h"

#include "dynslam/core/Config.h"

#include <charconv>
#include <cmath>
#include <fstream>
#include <iterator>
#include <mutex>
#include <ostream>
#include <sstream>

namespace dynslam::core {

const char* const kObjectGroundTruthHeader =
    "# dynslam-sim object ground truth: one line per frame and object at least partly in view\n"
    "# frame t id class moving tx ty tz qx qy qz qw box_x box_y box_w box_h visible_pixels "
    "visible_fraction\n"
    "# pose: the object's rigid core in the world (a person's torso centre, a car's body\n"
    "# centre); box: amodal, in pixels, clipped to the image (an object hidden behind a wall\n"
    "# is listed with 0 visible pixels); visible_fraction: visible pixels / pixels it would\n"
    "# cover with nothing in front of it; labels/NNNNNN.png holds `id` at the visible pixels.\n"
    "# class: person | car; moving: 1 when it moves at t (0: standing person, parked car).\n";

void writeObjectGroundTruthRow(std::ostream& out, const ObjectGroundTruthRow& r) {
  const auto precision = out.precision(17);
  const Eigen::Quaterniond q(r.T_world_object.rotation());
  const Eigen::Vector3d p = r.T_world_object.translation();
  out << r.frame << ' ' << r.t << ' ' << r.id << ' ' << r.category << ' ' << (r.moving ? 1 : 0)
      << ' ' << p.x() << ' ' << p.y() << ' ' << p.z() << ' ' << q.x() << ' ' << q.y() << ' '
      << q.z() << ' ' << q.w() << ' ' << r.box.x << ' ' << r.box.y << ' ' << r.box.width << ' '
      << r.box.height << ' ' << r.visible_pixels << ' ' << r.visible_fraction << '\n';
  out.precision(precision);
}

namespace {

constexpr const char* kLayout =
    "frame t id class moving tx ty tz qx qy qz qw box_x box_y box_w box_h visible_pixels "
    "visible_fraction";
constexpr std::size_t kFieldCount = 18;

[[noreturn]] void failAtLine(const std::string& path, std::size_t line_no,
                             const std::string& what) {
  throw ObjectGroundTruthError(path + ":" + std::to_string(line_no) + ": " + what);
}

/// Parses fields of one line by their 1-based column, so an error can name the column.
class LineFields {
 public:
  LineFields(const std::string& path, std::size_t line_no, std::vector<std::string> fields)
      : path_(path), line_no_(line_no), fields_(std::move(fields)) {}

  double real(std::size_t column) const {
    const std::string& f = fields_[column - 1];
    double v = 0;
    const char* begin = f.data() + (!f.empty() && f[0] == '+' ? 1 : 0);
    const auto [ptr, ec] = std::from_chars(begin, f.data() + f.size(), v);
    if (f.empty() || ec != std::errc() || ptr != f.data() + f.size() || !std::isfinite(v))
      fail(column, "is not a finite number");
    return v;
  }

  long integer(std::size_t column) const {
    const std::string& f = fields_[column - 1];
    long v = 0;
    const auto [ptr, ec] = std::from_chars(f.data(), f.data() + f.size(), v);
    if (f.empty() || ec != std::errc() || ptr != f.data() + f.size())
      fail(column, "is not an integer");
    return v;
  }

  long nonNegative(std::size_t column) const {
    const long v = integer(column);
    if (v < 0) fail(column, "is negative");
    return v;
  }

  const std::string& text(std::size_t column) const { return fields_[column - 1]; }

  [[noreturn]] void fail(std::size_t column, const std::string& what) const {
    failAtLine(path_, line_no_,
               "field " + std::to_string(column) + " ('" + fields_[column - 1] + "') " + what);
  }

 private:
  const std::string& path_;
  std::size_t line_no_;
  std::vector<std::string> fields_;
};

ObjectGroundTruthRow parseRow(const LineFields& f) {
  ObjectGroundTruthRow row;
  row.frame = static_cast<std::size_t>(f.nonNegative(1));
  row.t = f.real(2);
  row.id = static_cast<int>(f.nonNegative(3));
  row.category = f.text(4);
  const long moving = f.integer(5);
  if (moving != 0 && moving != 1) f.fail(5, "is not 0 or 1");
  row.moving = moving == 1;
  const Eigen::Vector3d p(f.real(6), f.real(7), f.real(8));
  Eigen::Quaterniond q(f.real(12), f.real(9), f.real(10), f.real(11));  // w, x, y, z
  if (!(q.norm() > 1e-12)) f.fail(12, "ends a quaternion of zero length");
  q.normalize();
  row.T_world_object = Eigen::Isometry3d::Identity();
  row.T_world_object.linear() = q.toRotationMatrix();
  row.T_world_object.translation() = p;
  row.box = cv::Rect(static_cast<int>(f.integer(13)), static_cast<int>(f.integer(14)),
                     static_cast<int>(f.nonNegative(15)), static_cast<int>(f.nonNegative(16)));
  row.visible_pixels = static_cast<int>(f.nonNegative(17));
  row.visible_fraction = f.real(18);
  if (row.visible_fraction < 0 || row.visible_fraction > 1 + 1e-9)
    f.fail(18, "is not a fraction in [0, 1]");
  return row;
}

}  // namespace

std::vector<ObjectGroundTruthRow> readObjectGroundTruth(const std::string& path) {
  std::ifstream in(path);
  if (!in)
    throw ObjectGroundTruthError("cannot open object ground truth file '" + path + "'" +
                                 pathLookup(path));
  std::vector<ObjectGroundTruthRow> rows;
  std::string line;
  std::size_t line_no = 0;
  while (std::getline(in, line)) {
    ++line_no;
    const auto first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos || line[first] == '#') continue;
    std::istringstream words(line);
    std::vector<std::string> fields{std::istream_iterator<std::string>(words),
                                    std::istream_iterator<std::string>()};
    if (fields.size() != kFieldCount)
      failAtLine(path, line_no,
                 "expected " + std::to_string(kFieldCount) + " fields (" + kLayout + "), found " +
                     std::to_string(fields.size()));
    rows.push_back(parseRow(LineFields(path, line_no, std::move(fields))));
  }
  if (in.bad()) throw ObjectGroundTruthError("error while reading '" + path + "'");
  return rows;
}

const std::vector<ObjectGroundTruthRow> ObjectGroundTruthIndex::kNone;

ObjectGroundTruthIndex::ObjectGroundTruthIndex(std::vector<ObjectGroundTruthRow> rows) {
  for (auto& row : rows) add(std::move(row));
}

void ObjectGroundTruthIndex::add(ObjectGroundTruthRow row) {
  frame_by_time_.emplace(row.t, row.frame);
  by_frame_[row.frame].push_back(std::move(row));
}

std::shared_ptr<ObjectGroundTruthFeed> ObjectGroundTruthFeed::named(const std::string& name) {
  static std::mutex mutex;
  static std::map<std::string, std::shared_ptr<ObjectGroundTruthFeed>> feeds;
  std::lock_guard<std::mutex> lock(mutex);
  auto& feed = feeds[name];
  if (!feed) feed = std::make_shared<ObjectGroundTruthFeed>();
  return feed;
}

void ObjectGroundTruthFeed::add(const std::vector<ObjectGroundTruthRow>& rows) {
  std::lock_guard<std::mutex> lock(mutex_);
  for (const auto& row : rows) index_.add(row);
}

std::vector<ObjectGroundTruthRow> ObjectGroundTruthFeed::atTime(double t, double tolerance) const {
  std::lock_guard<std::mutex> lock(mutex_);
  return index_.atTime(t, tolerance);
}

const std::vector<ObjectGroundTruthRow>& ObjectGroundTruthIndex::byFrame(std::size_t frame) const {
  const auto it = by_frame_.find(frame);
  return it == by_frame_.end() ? kNone : it->second;
}

const std::vector<ObjectGroundTruthRow>& ObjectGroundTruthIndex::atTime(double t,
                                                                        double tolerance) const {
  // The nearest listed stamp is the first one at or after t, or the one before it.
  auto best = frame_by_time_.end();
  const auto after = frame_by_time_.lower_bound(t);
  if (after != frame_by_time_.end()) best = after;
  if (after != frame_by_time_.begin()) {
    const auto before = std::prev(after);
    if (best == frame_by_time_.end() || t - before->first < best->first - t) best = before;
  }
  if (best == frame_by_time_.end() || std::abs(best->first - t) > tolerance) return kNone;
  return byFrame(best->second);
}

}  // namespace dynslam::core
