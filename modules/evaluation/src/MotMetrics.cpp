#include "dynslam/evaluation/MotMetrics.h"

#include "dynslam/evaluation/EvaluationError.h"

#include <dynslam/core/HungarianAssignment.h>

#include <map>

namespace dynslam::evaluation {
namespace {

double iou(const cv::Rect2d& a, const cv::Rect2d& b) {
  const double intersection = (a & b).area();
  const double unionArea = a.area() + b.area() - intersection;
  return unionArea > 0 ? intersection / unionArea : 0.0;
}

/// Per truth, the state CLEAR-MOT carries from frame to frame.
struct TruthHistory {
  int last_hypothesis = -1;                   // last match in any frame (continuity rule)
  int last_counted_hypothesis = -1;           // last match while counted (ID switches)
  bool tracked = false, interrupted = false;  // fragmentations
};

/// This frame's matches as (truth index, hypothesis index).
std::vector<std::pair<int, int>> matchFrame(const MotFrame& f, double minIou,
                                            const std::map<int, TruthHistory>& history) {
  const size_t nt = f.truth.size(), nh = f.hypotheses.size();
  std::vector<std::pair<int, int>> matches;
  std::vector<char> truthUsed(nt, 0), hypUsed(nh, 0);
  // Continuity: keep last frame's pairs that still overlap enough.
  for (size_t t = 0; t < nt; ++t) {
    const auto it = history.find(f.truth[t].id);
    if (it == history.end() || it->second.last_hypothesis < 0) continue;
    for (size_t h = 0; h < nh; ++h)
      if (!hypUsed[h] && f.hypotheses[h].id == it->second.last_hypothesis &&
          iou(f.truth[t].box, f.hypotheses[h].box) >= minIou) {
        matches.emplace_back(int(t), int(h));
        truthUsed[t] = hypUsed[h] = 1;
        break;
      }
  }
  // The rest: most pairs, then least total (1 - IoU). A pair below min_iou costs more than
  // any set of valid pairs, so it is only taken when nothing valid is left, and then dropped.
  std::vector<int> rows, cols;
  for (size_t t = 0; t < nt; ++t)
    if (!truthUsed[t]) rows.push_back(int(t));
  for (size_t h = 0; h < nh; ++h)
    if (!hypUsed[h]) cols.push_back(int(h));
  if (rows.empty() || cols.empty()) return matches;
  const double invalid = 1.0 + double(std::min(rows.size(), cols.size()));
  Eigen::MatrixXd cost(rows.size(), cols.size());
  for (size_t r = 0; r < rows.size(); ++r)
    for (size_t c = 0; c < cols.size(); ++c) {
      const double o = iou(f.truth[rows[r]].box, f.hypotheses[cols[c]].box);
      cost(r, c) = o >= minIou ? 1.0 - o : invalid;
    }
  const std::vector<int> assigned = core::solveMinCostAssignment(cost);
  for (size_t r = 0; r < rows.size(); ++r)
    if (assigned[r] >= 0 && cost(r, assigned[r]) < invalid)
      matches.emplace_back(rows[r], cols[assigned[r]]);
  return matches;
}

}  // namespace

MotResult evaluateMot(const std::vector<MotFrame>& frames, const MotOptions& options) {
  if (!(options.min_iou > 0 && options.min_iou <= 1))
    throw EvaluationError("evaluateMot: min_iou must be in (0, 1]");
  MotResult r;
  r.frames = frames.size();
  std::map<int, TruthHistory> history;
  std::map<int, int> truthIndex, hypIndex;           // id -> row/column of the identity matrix
  std::map<std::pair<int, int>, size_t> pairFrames;  // (truth id, hyp id) -> frames they match
  double iouSum = 0;

  for (const MotFrame& f : frames) {
    const auto matches = matchFrame(f, options.min_iou, history);
    std::vector<char> truthMatched(f.truth.size(), 0), hypIgnored(f.hypotheses.size(), 0);
    std::vector<char> hypMatched(f.hypotheses.size(), 0);
    for (const auto& [t, h] : matches) {
      const MotTruthBox& truth = f.truth[t];
      TruthHistory& th = history[truth.id];
      th.last_hypothesis = f.hypotheses[h].id;
      truthMatched[t] = hypMatched[h] = 1;
      if (!truth.counted) {
        hypIgnored[h] = 1;
        ++r.ignored_hypotheses;
        continue;
      }
      ++r.matches;
      iouSum += iou(truth.box, f.hypotheses[h].box);
      if (th.last_counted_hypothesis >= 0 && th.last_counted_hypothesis != f.hypotheses[h].id)
        ++r.id_switches;
      th.last_counted_hypothesis = f.hypotheses[h].id;
      if (th.interrupted) ++r.fragmentations;
      th.tracked = true;
      th.interrupted = false;
    }
    for (size_t t = 0; t < f.truth.size(); ++t) {
      if (!f.truth[t].counted) continue;
      ++r.truth_boxes;
      truthIndex.emplace(f.truth[t].id, int(truthIndex.size()));
      if (!truthMatched[t]) {
        ++r.misses;
        TruthHistory& th = history[f.truth[t].id];
        if (th.tracked) th.interrupted = true;
      }
    }
    for (size_t h = 0; h < f.hypotheses.size(); ++h) {
      if (hypIgnored[h]) continue;
      ++r.hypothesis_boxes;
      hypIndex.emplace(f.hypotheses[h].id, int(hypIndex.size()));
      if (!hypMatched[h]) ++r.false_positives;
    }
    // Identity: every (counted truth, kept hypothesis) pair that may match in this frame.
    for (const auto& t : f.truth) {
      if (!t.counted) continue;
      for (size_t h = 0; h < f.hypotheses.size(); ++h)
        if (!hypIgnored[h] && iou(t.box, f.hypotheses[h].box) >= options.min_iou)
          ++pairFrames[{t.id, f.hypotheses[h].id}];
    }
  }
  if (r.truth_boxes == 0)
    throw EvaluationError("evaluateMot: no counted ground-truth box, MOTA is undefined");

  r.mota = 1.0 - double(r.misses + r.false_positives + r.id_switches) / r.truth_boxes;
  r.motp = r.matches ? iouSum / r.matches : 0.0;
  r.truth_ids = truthIndex.size();
  r.hypothesis_ids = hypIndex.size();
  Eigen::MatrixXd overlap = Eigen::MatrixXd::Zero(r.truth_ids, r.hypothesis_ids);
  for (const auto& [ids, count] : pairFrames)
    overlap(truthIndex.at(ids.first), hypIndex.at(ids.second)) = double(count);
  const std::vector<int> assigned = core::solveMaxGainAssignment(overlap);
  for (size_t t = 0; t < assigned.size(); ++t)
    if (assigned[t] >= 0) r.idtp += size_t(overlap(t, assigned[t]));
  r.idfn = r.truth_boxes - r.idtp;
  r.idfp = r.hypothesis_boxes - r.idtp;
  r.idf1 = 2.0 * r.idtp / double(r.truth_boxes + r.hypothesis_boxes);
  r.idp = r.hypothesis_boxes ? double(r.idtp) / r.hypothesis_boxes : 0.0;
  r.idr = double(r.idtp) / r.truth_boxes;
  return r;
}

}  // namespace dynslam::evaluation
