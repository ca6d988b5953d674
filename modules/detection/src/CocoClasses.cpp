#include "dynslam/detection/CocoClasses.h"

#include <array>
#include <stdexcept>

namespace dynslam::detection {
namespace {

// Multi-word names use '_' so that an ini list can be split on blanks.
const std::array<std::string, kCocoClassCount> kNames = {
    "person",        "bicycle",      "car",
    "motorcycle",    "airplane",     "bus",
    "train",         "truck",        "boat",
    "traffic_light", "fire_hydrant", "stop_sign",
    "parking_meter", "bench",        "bird",
    "cat",           "dog",          "horse",
    "sheep",         "cow",          "elephant",
    "bear",          "zebra",        "giraffe",
    "backpack",      "umbrella",     "handbag",
    "tie",           "suitcase",     "frisbee",
    "skis",          "snowboard",    "sports_ball",
    "kite",          "baseball_bat", "baseball_glove",
    "skateboard",    "surfboard",    "tennis_racket",
    "bottle",        "wine_glass",   "cup",
    "fork",          "knife",        "spoon",
    "bowl",          "banana",       "apple",
    "sandwich",      "orange",       "broccoli",
    "carrot",        "hot_dog",      "pizza",
    "donut",         "cake",         "chair",
    "couch",         "potted_plant", "bed",
    "dining_table",  "toilet",       "tv",
    "laptop",        "mouse",        "remote",
    "keyboard",      "cell_phone",   "microwave",
    "oven",          "toaster",      "sink",
    "refrigerator",  "book",         "clock",
    "vase",          "scissors",     "teddy_bear",
    "hair_drier",    "toothbrush"};

}  // namespace

const std::string& cocoClassName(int id) {
  if (id < 0 || id >= kCocoClassCount)
    throw std::out_of_range("COCO class id " + std::to_string(id) + " is not in 0..79");
  return kNames[static_cast<std::size_t>(id)];
}

std::optional<int> cocoClassId(const std::string& name) {
  for (int i = 0; i < kCocoClassCount; ++i)
    if (kNames[static_cast<std::size_t>(i)] == name) return i;
  return std::nullopt;
}

}  // namespace dynslam::detection
