#pragma once
// The 80 COCO class names in the order YOLO-family detectors number them (person = 0, car = 2),
// so the ini can name classes instead of giving bare ids.
#include <optional>
#include <string>

namespace dynslam::detection {

constexpr int kCocoClassCount = 80;

/// The name of COCO class `id` ("person", "car", ...); throws std::out_of_range outside 0..79.
const std::string& cocoClassName(int id);

/// The id of a COCO class name, or nullopt when it is not one.
std::optional<int> cocoClassId(const std::string& name);

}  // namespace dynslam::detection
