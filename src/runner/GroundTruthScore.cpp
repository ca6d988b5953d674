#include "GroundTruthScore.h"

#include <dynslam/core/TrajectoryFile.h>
#include <dynslam/evaluation/Alignment.h>
#include <dynslam/evaluation/Ape.h>
#include <dynslam/evaluation/Association.h>
#include <dynslam/evaluation/Statistics.h>

namespace dynslam::runner {

namespace ev = dynslam::evaluation;

core::Trajectory readGroundTruth(const std::string& path) { return core::readTum(path); }

ApeScore scoreAgainstGroundTruth(const core::Trajectory& ground_truth,
                                 const core::Trajectory& estimate) {
  ev::AssociatedTrajectories pairs = ev::associateByTime(ground_truth, estimate);
  ev::alignTrajectory(pairs.first, pairs.second, ev::AlignmentMode::Se3, false);
  const auto errors = ev::computeApe(pairs.first, pairs.second, ev::PoseRelation::TranslationPart);
  const ev::ErrorStatistics s = ev::computeStatistics(errors);
  ApeScore score;
  score.pairs = pairs.first.size();
  score.max_pairs = pairs.max_pairs;
  score.rmse = s.rmse;
  score.mean = s.mean;
  score.median = s.median;
  score.std = s.std;
  score.min = s.min;
  score.max = s.max;
  score.sse = s.sse;
  return score;
}

}  // namespace dynslam::runner
