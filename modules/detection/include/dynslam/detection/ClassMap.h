#pragma once
// Which detector classes the system keeps, under which category and motion model (method.md
// section 1: person non-rigid, car rigid by default; other COCO classes may be mapped too). A
// class mapped to nothing is dropped by every detector.
//
// The ini form (DetectionStage key `class_map`) is a list of entries separated by blanks or
// commas, each "coco_class:category:motion":
//   class_map = person:person:non_rigid car:car:rigid bus:car:rigid truck:car:rigid
// coco_class is a COCO name (CocoClasses.h, '_' for blanks) or id 0..79; category is person, car
// or other (the classes the segmenter and tracker know); motion is rigid or non_rigid.
#include <dynslam/core/Perception.h>

#include <map>
#include <optional>
#include <stdexcept>
#include <string>

namespace dynslam::detection {

struct ClassMapError : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

struct MappedClass {
  std::string category;  ///< "person" | "car" | "other"
  core::MotionModel model = core::MotionModel::NonRigid;
};

class ClassMap {
 public:
  /// The default map: person -> person, non-rigid; car -> car, rigid.
  ClassMap();

  /// Parses the ini form above; throws ClassMapError naming the bad entry (and what was valid).
  static ClassMap parse(const std::string& spec);

  /// What COCO class `coco_id` becomes, or nullopt when it is dropped.
  std::optional<MappedClass> lookup(int coco_id) const;

  /// Sets what `coco_id` becomes (replacing an earlier mapping).
  void set(int coco_id, MappedClass mapped);

  /// The ini form of this map (parse(toString()) gives the same map).
  std::string toString() const;

  bool empty() const { return map_.empty(); }

 private:
  std::map<int, MappedClass> map_;
};

}  // namespace dynslam::detection
