#include "dynslam/detection/GroundTruthDetector.h"

#include "dynslam/detection/CocoClasses.h"

#include <algorithm>
#include <random>

namespace dynslam::detection {
namespace {

cv::Size imageSize(const core::Frame& frame) {
  if (!frame.rgb.empty()) return frame.rgb.size();
  return {frame.intrinsics.width, frame.intrinsics.height};
}

/// The box with each edge moved by Gaussian noise, clipped to the image; empty when nothing of
/// it is left inside.
cv::Rect2f jittered(const cv::Rect2f& box, double sigma, std::mt19937& rng, cv::Size image) {
  float x0 = box.x, y0 = box.y, x1 = box.x + box.width, y1 = box.y + box.height;
  if (sigma > 0) {
    std::normal_distribution<float> noise(0.f, static_cast<float>(sigma));
    x0 += noise(rng), y0 += noise(rng), x1 += noise(rng), y1 += noise(rng);
  }
  x0 = std::clamp(x0, 0.f, float(image.width)), x1 = std::clamp(x1, 0.f, float(image.width));
  y0 = std::clamp(y0, 0.f, float(image.height)), y1 = std::clamp(y1, 0.f, float(image.height));
  if (x1 - x0 < 1.f || y1 - y0 < 1.f) return {};
  return {x0, y0, x1 - x0, y1 - y0};
}

/// A box on nothing in particular: a person-shaped (upright) or car-shaped (wide) box of random
/// size and place inside the image.
cv::Rect2f randomBox(const std::string& category, std::mt19937& rng, cv::Size image) {
  std::uniform_real_distribution<float> unit(0.f, 1.f);
  const float aspect = category == "car" ? 1.8f : 0.4f;  // width / height
  float h = image.height * (0.15f + 0.45f * unit(rng));
  float w = std::min(h * aspect, image.width * 0.9f);
  h = std::min(h, w / aspect);
  return {unit(rng) * (image.width - w), unit(rng) * (image.height - h), w, h};
}

}  // namespace

GroundTruthDetector::GroundTruthDetector(GroundTruthDetectorSettings settings, ClassMap class_map)
    : settings_(std::move(settings)), class_map_(std::move(class_map)) {
  const std::string prefix = core::ObjectGroundTruthFeed::kPrefix;
  if (settings_.objects.rfind(prefix, 0) == 0) {
    feed_ = core::ObjectGroundTruthFeed::named(settings_.objects.substr(prefix.size()));
    return;
  }
  auto rows = core::readObjectGroundTruth(settings_.objects);
  for (const auto& row : rows)
    if (!cocoClassId(row.category))
      throw DetectorError("'" + settings_.objects + "' lists class '" + row.category +
                          "', which is not a COCO class name the class map could look up");
  if (!rows.empty()) {
    const auto [lo, hi] = std::minmax_element(
        rows.begin(), rows.end(), [](const auto& a, const auto& b) { return a.t < b.t; });
    first_t_ = lo->t, last_t_ = hi->t;
  }
  index_ = core::ObjectGroundTruthIndex(std::move(rows));
}

std::vector<core::Detection> GroundTruthDetector::detect(const core::Frame& frame) {
  if (!feed_ && index_.frameCount() > 0 && (frame.t < first_t_ - 1.0 || frame.t > last_t_ + 1.0))
    throw DetectorError("frame " + std::to_string(frame.index) +
                        " (t = " + std::to_string(frame.t) + ") is outside the time span of '" +
                        settings_.objects + "': is it the ground truth of another sequence?");
  const cv::Size image = imageSize(frame);
  std::seed_seq seq{static_cast<std::uint32_t>(settings_.seed),
                    static_cast<std::uint32_t>(frame.index)};
  std::mt19937 rng(seq);
  std::uniform_real_distribution<double> unit(0.0, 1.0);

  std::vector<core::Detection> detections;
  const std::vector<core::ObjectGroundTruthRow> rows =
      feed_ ? feed_->atTime(frame.t, settings_.time_tolerance)
            : index_.atTime(frame.t, settings_.time_tolerance);
  for (const auto& row : rows) {
    const auto coco = cocoClassId(row.category);  // a file's classes were checked when read
    if (!coco)
      throw DetectorError("'" + settings_.objects + "' gave class '" + row.category +
                          "', which is not a COCO class name the class map could look up");
    const auto mapped = class_map_.lookup(*coco);
    // Draw for every object, reported or not, so one object's fate does not shift the noise of
    // the others when settings change.
    const bool missed = unit(rng) < settings_.miss_rate;
    const cv::Rect2f box = jittered(cv::Rect2f(row.box), settings_.jitter_px, rng, image);
    if (!mapped || missed || row.visible_fraction < settings_.min_visible_fraction ||
        row.visible_pixels == 0 || box.empty())
      continue;
    core::Detection d;
    d.box = box;
    d.category = mapped->category;
    d.model = mapped->model;
    d.score = 1.f;
    d.truth_id = row.id;
    detections.push_back(d);
  }

  std::vector<MappedClass> false_classes;  // what a false positive may be
  for (const char* name : {"person", "car"})
    if (auto mapped = class_map_.lookup(*cocoClassId(name))) false_classes.push_back(*mapped);
  std::poisson_distribution<int> false_count(std::max(0.0, settings_.false_positive_rate));
  const int n_false = settings_.false_positive_rate > 0 ? false_count(rng) : 0;
  for (int i = 0; i < n_false && !false_classes.empty(); ++i) {
    const auto& mapped = false_classes[rng() % false_classes.size()];
    core::Detection d;
    d.box = randomBox(mapped.category, rng, image);
    d.category = mapped.category;
    d.model = mapped.model;
    d.score = 1.f;
    detections.push_back(d);
  }
  return detections;
}

}  // namespace dynslam::detection
