// The diagnostics bench-tracking prints besides its scores: which tracks covered each true
// identity, how well the appearance descriptor separates people, and the gaps in the truth a
// tracker has to bridge.
#include "tracking_diagnostics.h"

#include <dynslam/tracking/Appearance.h>
#include <opencv2/core.hpp>

#include <algorithm>
#include <cstdio>
#include <map>
#include <tuple>
#include <vector>

namespace dynslam::bench {


/// --identities: per truth id, the tracks that covered it in turn ("track 5 frames 0-120, track 9
/// 121-300"), each counted frame given to the hypothesis of largest IoU >= 0.5 (a reading aid
/// for IDF1: a track that appears under two truths is a swap, a new track a fragment).
void printIdentities(const std::vector<evaluation::MotFrame>& frames) {
  std::map<int, std::vector<std::tuple<int, int, int>>> runs;  // truth -> (track, first, last)
  for (size_t i = 0; i < frames.size(); ++i)
    for (const auto& t : frames[i].truth) {
      if (!t.counted) continue;
      int best = 0;
      double bestIou = 0.5;
      for (const auto& h : frames[i].hypotheses) {
        const double iou = (t.box & h.box).area() / (t.box | h.box).area();
        if (iou >= bestIou) bestIou = iou, best = h.id;
      }
      auto& r = runs[t.id];
      if (!r.empty() && std::get<0>(r.back()) == best)
        std::get<2>(r.back()) = int(i);
      else
        r.emplace_back(best, int(i), int(i));
    }
  // Each track is given to the truth whose frames it covered most, one to one, largest first
  // (IDF1 matches ids one to one too, optimally): a person's frames on its own track, on
  // another person's (a swap) or on nobody's (a fragment) say which failure holds IDF1 down.
  std::map<std::pair<int, int>, int> covered;  // (truth, track) -> frames
  int total = 0;
  for (const auto& [truth, r] : runs)
    for (const auto& [track, first, last] : r) {
      total += last - first + 1;
      if (track != 0) covered[{truth, track}] += last - first + 1;
    }
  std::vector<std::pair<int, std::pair<int, int>>> byFrames;
  for (const auto& [pair, n] : covered) byFrames.push_back({n, pair});
  std::sort(byFrames.rbegin(), byFrames.rend());
  std::map<int, int> trackOf, truthOf;
  for (const auto& [n, pair] : byFrames)
    if (!trackOf.count(pair.first) && !truthOf.count(pair.second))
      trackOf[pair.first] = pair.second, truthOf[pair.second] = pair.first;
  int own = 0, others = 0, nobodys = 0;
  for (const auto& [pair, n] : covered)
    (trackOf[pair.first] == pair.second ? own : truthOf.count(pair.second) ? others : nobodys) += n;
  if (total > 0)
    std::printf(
        "\nidentity split  of %d counted truth frames: %.1f %% on the person's own track, %.1f %% "
        "on another person's (swaps), %.1f %% on nobody's (fragments), %.1f %% uncovered\n",
        total, 100.0 * own / total, 100.0 * others / total, 100.0 * nobodys / total,
        100.0 * (total - own - others - nobodys) / total);
  std::printf("\nidentities (truth: track[first-last] ..., track 0 = none)\n");
  for (const auto& [truth, r] : runs) {
    std::printf("  %d:", truth);
    for (const auto& [track, first, last] : r)
      if (track != 0 || last - first >= 5) std::printf(" %d[%d-%d]", track, first, last);
    std::printf("\n");
  }
}

double percentile(std::vector<double> v, double p) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  return v[std::min(v.size() - 1, size_t(p * v.size()))];
}

/// How well the appearance descriptor tells people apart: its distance between one person's
/// detections one detector frame apart, and between two people's detections in one frame.
void printAppearanceSeparation(const CachedRun& run) {
  std::vector<double> same, different;
  for (size_t i = 0; i < run.frames.size(); ++i) {
    const auto& f = run.frames[i];
    for (size_t a = 0; a < f.observations.size(); ++a) {
      if (f.observations[a].appearance.empty() || f.observation_truth[a].id < 0) continue;
      for (size_t b = a + 1; b < f.observations.size(); ++b)
        if (f.observation_truth[b].id >= 0 &&
            f.observation_truth[b].id != f.observation_truth[a].id)
          different.push_back(tracking::appearanceDistance(f.observations[a].appearance,
                                                           f.observations[b].appearance));
      if (i == 0) continue;
      const auto& p = run.frames[i - 1];
      for (size_t b = 0; b < p.observations.size(); ++b)
        if (p.observation_truth[b].id == f.observation_truth[a].id)
          same.push_back(tracking::appearanceDistance(f.observations[a].appearance,
                                                      p.observations[b].appearance));
    }
  }
  if (same.empty() || different.empty()) return;
  // Each person's mean descriptor over the run: how often a detection is nearest its own
  // person's (an upper bound on what the cue can decide alone).
  std::map<int, cv::Mat> mean;
  std::map<int, int> count;
  for (const auto& f : run.frames)
    for (size_t a = 0; a < f.observations.size(); ++a)
      if (!f.observations[a].appearance.empty() && f.observation_truth[a].id >= 0) {
        cv::Mat& m = mean[f.observation_truth[a].id];
        m = m.empty() ? f.observations[a].appearance.clone() : m + f.observations[a].appearance;
        ++count[f.observation_truth[a].id];
      }
  for (auto& [id, m] : mean) m /= double(count[id]);
  size_t nearestOwn = 0, described = 0;
  for (const auto& f : run.frames)
    for (size_t a = 0; a < f.observations.size(); ++a) {
      if (f.observations[a].appearance.empty() || f.observation_truth[a].id < 0) continue;
      double own = 1, other = 1;
      for (const auto& [id, m] : mean) {
        double& d = id == f.observation_truth[a].id ? own : other;
        d = std::min(d, tracking::appearanceDistance(m, f.observations[a].appearance));
      }
      nearestOwn += own < other;
      ++described;
    }
  std::printf(
      "appearance      distance, same person one frame apart: median %.2f, p90 %.2f, p99 %.2f; "
      "two people in one frame: p1 %.2f, p10 %.2f, median %.2f; nearest its own person's mean "
      "in %.1f %%\n",
      percentile(same, 0.5), percentile(same, 0.9), percentile(same, 0.99),
      percentile(different, 0.01), percentile(different, 0.1), percentile(different, 0.5),
      100.0 * nearestOwn / described);
}

/// Gaps: stretches of frames in which a truth id seen before and after is not counted (hidden
/// behind someone, or out of view): each one the tracker has to bridge.
void printTruthGaps(const CachedRun& run) {
  std::map<int, int> lastSeen;
  std::vector<double> gaps;
  size_t outOfView = 0;
  for (size_t i = 0; i < run.frames.size(); ++i)
    for (const auto& t : run.frames[i].truth) {
      if (!t.counted) continue;
      const auto it = lastSeen.find(t.id);
      if (it != lastSeen.end() && int(i) - it->second > 1) {
        gaps.push_back(int(i) - it->second - 1);
        // Out of view when it left the image entirely at some frame of the gap.
        bool left = false;
        for (int k = it->second + 1; k < int(i) && !left; ++k) {
          const auto& truth = run.frames[k].truth;
          left =
              std::none_of(truth.begin(), truth.end(), [&](const auto& o) { return o.id == t.id; });
        }
        outOfView += left;
      }
      lastSeen[t.id] = int(i);
    }
  std::printf(
      "truth gaps      %zu stretches in which a person is not counted between two counted "
      "frames (%zu of them out of view): median %.0f frames, p90 %.0f, max %.0f\n",
      gaps.size(), outOfView, percentile(gaps, 0.5), percentile(gaps, 0.9), percentile(gaps, 1.0));
}

}  // namespace dynslam::bench
