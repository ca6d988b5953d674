#include "dynslam/detection/ClassMap.h"

#include "dynslam/detection/CocoClasses.h"

#include <charconv>
#include <sstream>
#include <vector>

namespace dynslam::detection {
namespace {

std::vector<std::string> splitOn(const std::string& text, const std::string& separators) {
  std::vector<std::string> parts;
  std::size_t i = 0;
  while (i <= text.size()) {
    const std::size_t end = text.find_first_of(separators, i);
    const std::string part = text.substr(i, end == std::string::npos ? std::string::npos : end - i);
    if (!part.empty() || separators == ":") parts.push_back(part);
    if (end == std::string::npos) break;
    i = end + 1;
  }
  return parts;
}

int parseCocoClass(const std::string& field, const std::string& entry) {
  if (const auto id = cocoClassId(field)) return *id;
  int id = -1;
  const auto [ptr, ec] = std::from_chars(field.data(), field.data() + field.size(), id);
  if (!field.empty() && ec == std::errc() && ptr == field.data() + field.size() && id >= 0 &&
      id < kCocoClassCount)
    return id;
  throw ClassMapError("class map entry '" + entry + "': '" + field +
                      "' is neither a COCO class name (person, car, bus, truck, bicycle, "
                      "motorcycle, ...; '_' for blanks) nor an id 0..79");
}

}  // namespace

ClassMap::ClassMap() {
  map_[0] = {"person", core::MotionModel::NonRigid};
  map_[2] = {"car", core::MotionModel::Rigid};
}

ClassMap ClassMap::parse(const std::string& spec) {
  ClassMap result;
  result.map_.clear();
  for (const auto& entry : splitOn(spec, " \t,")) {
    const auto fields = splitOn(entry, ":");
    if (fields.size() != 3)
      throw ClassMapError("class map entry '" + entry +
                          "': expected coco_class:category:motion, e.g. bus:car:rigid");
    const int id = parseCocoClass(fields[0], entry);
    const std::string& category = fields[1];
    if (category != "person" && category != "car" && category != "other")
      throw ClassMapError("class map entry '" + entry + "': category '" + category +
                          "' is not person, car or other");
    core::MotionModel model;
    if (fields[2] == "rigid")
      model = core::MotionModel::Rigid;
    else if (fields[2] == "non_rigid")
      model = core::MotionModel::NonRigid;
    else
      throw ClassMapError("class map entry '" + entry + "': motion '" + fields[2] +
                          "' is not rigid or non_rigid");
    if (result.map_.count(id))
      throw ClassMapError("class map entry '" + entry + "': COCO class '" + cocoClassName(id) +
                          "' is mapped twice");
    result.map_[id] = {category, model};
  }
  if (result.map_.empty())
    throw ClassMapError("the class map '" + spec +
                        "' has no entries: every detection would be dropped");
  return result;
}

std::optional<MappedClass> ClassMap::lookup(int coco_id) const {
  const auto it = map_.find(coco_id);
  if (it == map_.end()) return std::nullopt;
  return it->second;
}

void ClassMap::set(int coco_id, MappedClass mapped) { map_[coco_id] = std::move(mapped); }

std::string ClassMap::toString() const {
  std::ostringstream out;
  for (const auto& [id, mapped] : map_) {
    if (out.tellp() > 0) out << ' ';
    out << cocoClassName(id) << ':' << mapped.category << ':'
        << (mapped.model == core::MotionModel::Rigid ? "rigid" : "non_rigid");
  }
  return out.str();
}

}  // namespace dynslam::detection
