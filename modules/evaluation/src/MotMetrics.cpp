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

/// Accumulates the counts of evaluateMot frame by frame.
class MotAccumulator {
 public:
  explicit MotAccumulator(double min_iou) : minIou_(min_iou) {}

  void add(const MotFrame& f) {
    const auto matches = matchFrame(f, minIou_, history_);
    Marks marks{std::vector<char>(f.truth.size(), 0), std::vector<char>(f.hypotheses.size(), 0),
                std::vector<char>(f.hypotheses.size(), 0)};
    countMatches(f, matches, marks);
    countTruth(f, marks);
    countHypotheses(f, marks);
    countIdentityPairs(f, marks);
  }

  MotResult result(size_t frames) {
    r_.frames = frames;
    if (r_.truth_boxes == 0)
      throw EvaluationError("evaluateMot: no counted ground-truth box, MOTA is undefined");
    r_.mota = 1.0 - double(r_.misses + r_.false_positives + r_.id_switches) / r_.truth_boxes;
    r_.motp = r_.matches ? iouSum_ / r_.matches : 0.0;
    r_.truth_ids = truthIndex_.size();
    r_.hypothesis_ids = hypIndex_.size();
    Eigen::MatrixXd overlap = Eigen::MatrixXd::Zero(r_.truth_ids, r_.hypothesis_ids);
    for (const auto& [ids, count] : pairFrames_)
      overlap(truthIndex_.at(ids.first), hypIndex_.at(ids.second)) = double(count);
    const std::vector<int> assigned = core::solveMaxGainAssignment(overlap);
    for (size_t t = 0; t < assigned.size(); ++t)
      if (assigned[t] >= 0) r_.idtp += size_t(overlap(t, assigned[t]));
    r_.idfn = r_.truth_boxes - r_.idtp;
    r_.idfp = r_.hypothesis_boxes - r_.idtp;
    r_.idf1 = 2.0 * r_.idtp / double(r_.truth_boxes + r_.hypothesis_boxes);
    r_.idp = r_.hypothesis_boxes ? double(r_.idtp) / r_.hypothesis_boxes : 0.0;
    r_.idr = double(r_.idtp) / r_.truth_boxes;
    return r_;
  }

 private:
  /// Per box of one frame: matched (truth, hypothesis), ignored (a hypothesis matched to a
  /// truth box that does not count).
  struct Marks {
    std::vector<char> truthMatched, hypMatched, hypIgnored;
  };

  void countMatches(const MotFrame& f, const std::vector<std::pair<int, int>>& matches, Marks& m) {
    for (const auto& [t, h] : matches) {
      const MotTruthBox& truth = f.truth[t];
      TruthHistory& th = history_[truth.id];
      th.last_hypothesis = f.hypotheses[h].id;
      m.truthMatched[t] = m.hypMatched[h] = 1;
      if (!truth.counted) {
        m.hypIgnored[h] = 1;
        ++r_.ignored_hypotheses;
        continue;
      }
      ++r_.matches;
      iouSum_ += iou(truth.box, f.hypotheses[h].box);
      if (th.last_counted_hypothesis >= 0 && th.last_counted_hypothesis != f.hypotheses[h].id)
        ++r_.id_switches;
      th.last_counted_hypothesis = f.hypotheses[h].id;
      if (th.interrupted) ++r_.fragmentations;
      th.tracked = true;
      th.interrupted = false;
    }
  }

  void countTruth(const MotFrame& f, const Marks& m) {
    for (size_t t = 0; t < f.truth.size(); ++t) {
      if (!f.truth[t].counted) continue;
      ++r_.truth_boxes;
      truthIndex_.emplace(f.truth[t].id, int(truthIndex_.size()));
      if (!m.truthMatched[t]) {
        ++r_.misses;
        TruthHistory& th = history_[f.truth[t].id];
        if (th.tracked) th.interrupted = true;
      }
    }
  }

  void countHypotheses(const MotFrame& f, const Marks& m) {
    for (size_t h = 0; h < f.hypotheses.size(); ++h) {
      if (m.hypIgnored[h]) continue;
      ++r_.hypothesis_boxes;
      hypIndex_.emplace(f.hypotheses[h].id, int(hypIndex_.size()));
      if (!m.hypMatched[h]) ++r_.false_positives;
    }
  }

  /// Identity: every (counted truth, kept hypothesis) pair that may match in this frame.
  void countIdentityPairs(const MotFrame& f, const Marks& m) {
    for (const auto& t : f.truth) {
      if (!t.counted) continue;
      for (size_t h = 0; h < f.hypotheses.size(); ++h)
        if (!m.hypIgnored[h] && iou(t.box, f.hypotheses[h].box) >= minIou_)
          ++pairFrames_[{t.id, f.hypotheses[h].id}];
    }
  }

  const double minIou_;
  MotResult r_;
  std::map<int, TruthHistory> history_;
  std::map<int, int> truthIndex_, hypIndex_;          // id -> row/column of the identity matrix
  std::map<std::pair<int, int>, size_t> pairFrames_;  // (truth id, hyp id) -> frames they match
  double iouSum_ = 0;
};

}  // namespace

MotResult evaluateMot(const std::vector<MotFrame>& frames, const MotOptions& options) {
  if (!(options.min_iou > 0 && options.min_iou <= 1))
    throw EvaluationError("evaluateMot: min_iou must be in (0, 1]");
  MotAccumulator accumulator(options.min_iou);
  for (const MotFrame& f : frames) accumulator.add(f);
  return accumulator.result(frames.size());
}

}  // namespace dynslam::evaluation
