#pragma once
// Writing and reading the simulator's object ground truth (dynslam-sim's objects.txt): one line per
// frame and object at least partly in view,
//   frame t id class moving tx ty tz qx qy qz qw box_x box_y box_w box_h visible_pixels
//   visible_fraction
// with t the frame's rawlog stamp (Unix seconds), the pose the object's rigid core in the world
// and the box amodal, in pixels, clipped to the image. Blank lines and '#' comments are skipped;
// a malformed line throws ObjectGroundTruthError "path:line: what". MRPT-free.
#include <Eigen/Geometry>
#include <opencv2/core/types.hpp>

#include <cstddef>
#include <iosfwd>
#include <map>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>
#include <vector>

namespace dynslam::core {

struct ObjectGroundTruthError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct ObjectGroundTruthRow {
  std::size_t frame = 0;  ///< 0-based frame index in the simulated sequence
  double t = 0;           ///< the frame's rawlog stamp, s
  int id = 0;             ///< instance id (its pixels in labels/NNNNNN.png)
  std::string category;   ///< "person" | "car"
  bool moving = false;    ///< false: a standing person or a parked car
  Eigen::Isometry3d T_world_object = Eigen::Isometry3d::Identity();
  cv::Rect box;                 ///< amodal, pixels, clipped to the image
  int visible_pixels = 0;       ///< pixels that show it
  double visible_fraction = 0;  ///< visible pixels / pixels it would cover unoccluded
};

/// The comment block objects.txt starts with: the column layout and what each column means.
extern const char* const kObjectGroundTruthHeader;

/// Appends `row` as one line of objects.txt, numbers at full precision (17 significant digits)
/// so readObjectGroundTruth gets the same values back; `out`'s own precision is left as it was.
void writeObjectGroundTruthRow(std::ostream& out, const ObjectGroundTruthRow& row);

/// Every row of `path` in file order. Throws ObjectGroundTruthError naming the file when it
/// cannot be read, and the file and 1-based line when a line is malformed.
std::vector<ObjectGroundTruthRow> readObjectGroundTruth(const std::string& path);

/// The rows grouped by frame, found by frame index or by stamp (the frames a pipeline sees carry
/// the rawlog stamp, which went through MRPT's 100 ns clock: hence the tolerance).
class ObjectGroundTruthIndex {
 public:
  ObjectGroundTruthIndex() = default;
  explicit ObjectGroundTruthIndex(std::vector<ObjectGroundTruthRow> rows);
  void add(ObjectGroundTruthRow row);

  /// The objects of frame `frame`; empty when the file lists none (nothing in view).
  const std::vector<ObjectGroundTruthRow>& byFrame(std::size_t frame) const;

  /// The objects of the frame whose stamp is nearest `t` within `tolerance` seconds; empty when
  /// no listed frame is that close (a frame with nothing in view has no lines at all).
  const std::vector<ObjectGroundTruthRow>& atTime(double t, double tolerance = 1e-3) const;

  std::size_t frameCount() const { return by_frame_.size(); }  ///< frames with any object

 private:
  std::map<std::size_t, std::vector<ObjectGroundTruthRow>> by_frame_;
  std::map<double, std::size_t> frame_by_time_;
  static const std::vector<ObjectGroundTruthRow> kNone;
};

/// Ground truth that arrives while a run goes on: a simulator driven in closed loop renders each
/// frame just before the system gets it, so no objects.txt exists beforehand. The program adds
/// each frame's rows before it hands over the frame; `[Detection] objects = feed:NAME` makes the
/// ground-truth detector read the feed registered under NAME instead of a file. Thread-safe; it
/// keeps every row (a closed-loop run lasts minutes).
class ObjectGroundTruthFeed {
 public:
  static constexpr const char* kPrefix = "feed:";
  /// The feed registered under `name`, made on first use; the same object for the process's life.
  static std::shared_ptr<ObjectGroundTruthFeed> named(const std::string& name);

  void add(const std::vector<ObjectGroundTruthRow>& rows);
  /// As ObjectGroundTruthIndex::atTime, a copy.
  std::vector<ObjectGroundTruthRow> atTime(double t, double tolerance = 1e-3) const;

 private:
  mutable std::mutex mutex_;
  ObjectGroundTruthIndex index_;
};

}  // namespace dynslam::core
