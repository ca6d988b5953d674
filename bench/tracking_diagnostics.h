#pragma once
// What bench-tracking prints besides CLEAR-MOT and IDF1, as reading aids for its scores.
#include "tracking_sim_input.h"

#include <dynslam/evaluation/MotMetrics.h>

#include <vector>

namespace dynslam::bench {

/// The value below which a share p of v lies (0 when v is empty).
double percentile(std::vector<double> v, double p);

/// --identities: per truth id, the tracks that covered it in turn, and the split of the counted
/// truth frames into own track, another person's (swaps), nobody's (fragments) and uncovered.
void printIdentities(const std::vector<evaluation::MotFrame>& frames);

/// The appearance descriptor's distances within one person and between two people.
void printAppearanceSeparation(const CachedRun& run);

/// The stretches in which a person seen before and after is not counted.
void printTruthGaps(const CachedRun& run);

}  // namespace dynslam::bench
