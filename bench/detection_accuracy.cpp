#include "detection_accuracy.h"

#include <dynslam/core/ObjectGroundTruth.h>
#include <dynslam/tracking/DepthIoU.h>

#include <algorithm>
#include <tuple>

namespace dynslam::bench {

std::map<std::size_t, std::vector<TruePerson>> readTruePeople(const std::string& objects_txt,
                                                              double min_visible) {
  std::map<std::size_t, std::vector<TruePerson>> people;
  for (const auto& row : core::readObjectGroundTruth(objects_txt))
    if (row.category == "person")
      people[row.frame].push_back({row.box, row.visible_fraction >= min_visible});
  return people;
}

DetectionScore scoreDetector(detection::Detector& detector, const std::vector<core::Frame>& frames,
                             const std::map<std::size_t, std::vector<TruePerson>>& truth) {
  DetectionScore score;
  for (const auto& frame : frames) {
    std::vector<cv::Rect> boxes;
    for (const auto& d : detector.detect(frame))
      if (d.category == "person") boxes.push_back(cv::Rect(d.box));
    const auto it = truth.find(frame.index);
    const std::vector<TruePerson> none;
    const auto& people = it == truth.end() ? none : it->second;
    std::vector<std::tuple<double, size_t, size_t>> pairs;  // (-iou, detection, person)
    for (size_t d = 0; d < boxes.size(); ++d)
      for (size_t p = 0; p < people.size(); ++p)
        if (const double v = tracking::boxIoU(cv::Rect2f(boxes[d]), cv::Rect2f(people[p].box));
            v >= 0.5)
          pairs.emplace_back(-v, d, p);
    std::sort(pairs.begin(), pairs.end());
    std::vector<bool> detectionUsed(boxes.size()), personUsed(people.size());
    for (const auto& [negIou, d, p] : pairs) {
      if (detectionUsed[d] || personUsed[p]) continue;
      detectionUsed[d] = personUsed[p] = true;
      score.found += people[p].counted;
    }
    for (size_t p = 0; p < people.size(); ++p) score.missed += people[p].counted && !personUsed[p];
    score.false_positives += size_t(std::count(detectionUsed.begin(), detectionUsed.end(), false));
  }
  return score;
}

}  // namespace dynslam::bench
