#include "detection_accuracy.h"

#include <dynslam/core/ObjectGroundTruth.h>
#include <dynslam/tracking/DepthIoU.h>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cstdio>
#include <set>
#include <tuple>

namespace dynslam::bench {

std::vector<std::pair<size_t, size_t>> matchBoxes(const std::vector<cv::Rect>& detected,
                                                  const std::vector<cv::Rect>& truth,
                                                  double min_iou) {
  std::vector<std::tuple<double, size_t, size_t>> pairs;  // (-iou, detection, truth)
  for (size_t d = 0; d < detected.size(); ++d)
    for (size_t t = 0; t < truth.size(); ++t)
      if (const double v = tracking::boxIoU(cv::Rect2f(detected[d]), cv::Rect2f(truth[t]));
          v >= min_iou)
        pairs.emplace_back(-v, d, t);
  std::sort(pairs.begin(), pairs.end());
  std::vector<bool> detectedUsed(detected.size()), truthUsed(truth.size());
  std::vector<std::pair<size_t, size_t>> matches;
  for (const auto& [negIou, d, t] : pairs) {
    if (detectedUsed[d] || truthUsed[t]) continue;
    detectedUsed[d] = truthUsed[t] = true;
    matches.emplace_back(d, t);
  }
  return matches;
}

std::vector<int> matchDetections(const std::vector<core::Detection>& detections,
                                 const std::vector<TrueBox>& truth, double min_iou) {
  std::vector<int> matched(detections.size(), -1);
  std::set<std::string> categories;
  for (const auto& d : detections) categories.insert(d.category);
  for (const auto& category : categories) {
    std::vector<size_t> dk, tk;
    std::vector<cv::Rect> boxes, trueBoxes;
    for (size_t k = 0; k < detections.size(); ++k)
      if (detections[k].category == category)
        dk.push_back(k), boxes.push_back(cv::Rect(detections[k].box));
    for (size_t k = 0; k < truth.size(); ++k)
      if (truth[k].category == category) tk.push_back(k), trueBoxes.push_back(truth[k].box);
    for (const auto& [d, t] : matchBoxes(boxes, trueBoxes, min_iou)) matched[dk[d]] = int(tk[t]);
  }
  return matched;
}

std::map<std::size_t, std::vector<TruePerson>> readTruePeople(const std::string& objects_txt,
                                                              double min_visible) {
  std::map<std::size_t, std::vector<TruePerson>> people;
  for (const auto& row : core::readObjectGroundTruth(objects_txt))
    if (row.category == "person")
      people[row.frame].push_back({row.box, row.visible_fraction >= min_visible});
  return people;
}

namespace {

/// The frame with its true people (green: must be found, grey: less visible) and the detections
/// (blue: matched, red: false positive), as DIR/detections_NNNNNN.png.
void drawScoredFrame(const std::string& dir, const core::Frame& frame,
                     const std::vector<TruePerson>& people, const std::vector<cv::Rect>& boxes,
                     const std::vector<bool>& detectionUsed) {
  cv::Mat image = frame.rgb.clone();
  for (const auto& p : people)
    cv::rectangle(image, p.box, p.counted ? cv::Scalar(0, 200, 0) : cv::Scalar(150, 150, 150), 2);
  for (size_t d = 0; d < boxes.size(); ++d)
    cv::rectangle(image, boxes[d],
                  detectionUsed[d] ? cv::Scalar(255, 120, 0) : cv::Scalar(0, 0, 255), 1);
  char name[32];
  std::snprintf(name, sizeof name, "/detections_%06zu.png", frame.index);
  if (!cv::imwrite(dir + name, image)) throw std::runtime_error("cannot write " + dir + name);
}

}  // namespace

DetectionScore scoreDetector(detection::Detector& detector, const std::vector<core::Frame>& frames,
                             const std::map<std::size_t, std::vector<TruePerson>>& truth,
                             const std::string& draw_dir) {
  DetectionScore score;
  for (const auto& frame : frames) {
    std::vector<cv::Rect> boxes;
    for (const auto& d : detector.detect(frame))
      if (d.category == "person") boxes.push_back(cv::Rect(d.box));
    const auto it = truth.find(frame.index);
    const std::vector<TruePerson> none;
    const auto& people = it == truth.end() ? none : it->second;
    std::vector<cv::Rect> trueBoxes;
    for (const auto& p : people) trueBoxes.push_back(p.box);
    std::vector<bool> detectionUsed(boxes.size()), personUsed(people.size());
    for (const auto& [d, p] : matchBoxes(boxes, trueBoxes)) {
      detectionUsed[d] = personUsed[p] = true;
      score.found += people[p].counted;
    }
    for (size_t p = 0; p < people.size(); ++p) score.missed += people[p].counted && !personUsed[p];
    score.false_positives += size_t(std::count(detectionUsed.begin(), detectionUsed.end(), false));
    if (!draw_dir.empty()) drawScoredFrame(draw_dir, frame, people, boxes, detectionUsed);
  }
  return score;
}

}  // namespace dynslam::bench
