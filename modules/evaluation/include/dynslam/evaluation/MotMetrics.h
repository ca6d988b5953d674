#pragma once
// Multi-object tracking metrics of tracker boxes against ground-truth boxes: CLEAR-MOT (MOTA,
// MOTP, ID switches, fragmentations; Bernardin and Stiefelhagen 2008) and the identity metrics
// (IDF1, IDP, IDR; Ristani et al. 2016), following py-motmetrics' rules:
//
// - A hypothesis and a truth may match when their IoU >= min_iou (0.5).
// - Per frame, first every truth keeps the hypothesis it last matched if they still may match
//   (CLEAR-MOT's continuity rule); the rest are paired by the Hungarian algorithm, most pairs
//   first, then the largest total IoU.
// - A matched truth whose previous match (in any earlier frame) was another hypothesis is an ID
//   switch; a truth that was matched, then missed, then matched again is a fragmentation.
// - MOTA = 1 - (misses + false positives + ID switches) / truth boxes; MOTP = mean IoU of
//   matches.
// - IDF1: truth ids and hypothesis ids are paired one to one for the whole sequence by the
//   Hungarian algorithm, maximising the frames in which a pair may match (IDTP);
//   IDF1 = 2 IDTP / (truth boxes + hypothesis boxes), IDP = IDTP / hypothesis boxes,
//   IDR = IDTP / truth boxes.
//
// Truths too hidden to demand (`counted` = false, e.g. a person behind another, which no
// detector can see) are "don't care", as MOT16's occluded and ambiguous boxes: they take part
// in the matching, but a hypothesis matched to one is neither a true nor a false positive and
// is left out of the identity metrics too, and missing one is no miss.
#include <opencv2/core/types.hpp>

#include <cstddef>
#include <vector>

namespace dynslam::evaluation {

struct MotTruthBox {
  int id = 0;
  cv::Rect2d box;
  bool counted = true;  ///< false: "don't care" (see above)
};

struct MotHypothesisBox {
  int id = 0;
  cv::Rect2d box;
};

struct MotFrame {
  std::vector<MotTruthBox> truth;
  std::vector<MotHypothesisBox> hypotheses;
};

struct MotOptions {
  double min_iou = 0.5;  ///< a hypothesis may match a truth with at least this IoU
};

struct MotResult {
  std::size_t frames = 0;
  std::size_t truth_boxes = 0;       ///< counted truth boxes: MOTA's and IDR's denominator
  std::size_t hypothesis_boxes = 0;  ///< hypotheses not matched to a don't-care truth
  std::size_t matches = 0;           ///< true positives
  std::size_t misses = 0;            ///< false negatives: counted truths left unmatched
  std::size_t false_positives = 0;
  std::size_t id_switches = 0;
  std::size_t fragmentations = 0;
  std::size_t ignored_hypotheses = 0;  ///< matched to a don't-care truth
  std::size_t truth_ids = 0, hypothesis_ids = 0;
  double mota = 0, motp = 0;
  std::size_t idtp = 0, idfp = 0, idfn = 0;
  double idf1 = 0, idp = 0, idr = 0;
};

/// Evaluates a whole sequence (frames in order). Throws EvaluationError when it holds no
/// counted truth box (MOTA is undefined) or min_iou is not in (0, 1].
MotResult evaluateMot(const std::vector<MotFrame>& frames, const MotOptions& options = {});

}  // namespace dynslam::evaluation
