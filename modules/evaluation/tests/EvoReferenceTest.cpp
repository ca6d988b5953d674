// The evaluator against figures evo itself produced on the trajectory pairs of evo's test data
// (../shared/data/evo), and against independent computations where evo published nothing.
#include <dynslam/core/TrajectoryFile.h>
#include <dynslam/evaluation/Alignment.h>
#include <dynslam/evaluation/Ape.h>
#include <dynslam/evaluation/Association.h>
#include <dynslam/evaluation/Rpe.h>
#include <dynslam/evaluation/Statistics.h>
#include <dynslam/testing/TestEnv.h>

#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace ev = dynslam::evaluation;
namespace core = dynslam::core;

namespace {

void expectRelativelyNear(double actual, double expected, double rel_tol, const char* what) {
  EXPECT_LE(std::abs(actual - expected), rel_tol * std::abs(expected))
      << what << ": " << actual << " vs evo's " << expected;
}

void expectStatistics(const ev::ErrorStatistics& s, const ev::ErrorStatistics& evo,
                      double rel_tol) {
  expectRelativelyNear(s.rmse, evo.rmse, rel_tol, "rmse");
  expectRelativelyNear(s.mean, evo.mean, rel_tol, "mean");
  expectRelativelyNear(s.median, evo.median, rel_tol, "median");
  expectRelativelyNear(s.std, evo.std, rel_tol, "std");
  expectRelativelyNear(s.min, evo.min, rel_tol, "min");
  expectRelativelyNear(s.max, evo.max, rel_tol, "max");
  expectRelativelyNear(s.sse, evo.sse, rel_tol, "sse");
}

ev::ErrorStatistics apeStats(const ev::AssociatedTrajectories& pairs, ev::AlignmentMode mode) {
  core::Trajectory est = pairs.second;
  ev::alignTrajectory(pairs.first, est, mode, false);
  return ev::computeStatistics(ev::computeApe(pairs.first, est, ev::PoseRelation::TranslationPart));
}

/// Translation APE rmse computed without the module: Eigen's own Umeyama and plain loops.
double independentApeRmse(const ev::AssociatedTrajectories& pairs, bool with_scale) {
  const Eigen::Index n = static_cast<Eigen::Index>(pairs.first.size());
  Eigen::Matrix3Xd est(3, n), ref(3, n);
  for (Eigen::Index i = 0; i < n; ++i) {
    est.col(i) = pairs.second[static_cast<std::size_t>(i)].T_world_body.translation();
    ref.col(i) = pairs.first[static_cast<std::size_t>(i)].T_world_body.translation();
  }
  const Eigen::Matrix4d t = Eigen::umeyama(est, ref, with_scale);
  double sum = 0.0;
  for (Eigen::Index i = 0; i < n; ++i) {
    const Eigen::Vector3d aligned = t.block<3, 3>(0, 0) * est.col(i) + t.block<3, 1>(0, 3);
    sum += (aligned - ref.col(i)).squaredNorm();
  }
  return std::sqrt(sum / static_cast<double>(n));
}

/// Checks every associated pair with a method other than the module's scan: the estimate
/// (the shorter file) must have been matched to the closest reference stamp, found here by
/// binary search on the sorted reference stamps, within 0.01 s.
void expectNearestReferenceStamps(const core::Trajectory& ref_full,
                                  const ev::AssociatedTrajectories& pairs) {
  std::vector<double> stamps;
  for (const auto& p : ref_full) stamps.push_back(p.t);
  ASSERT_TRUE(std::is_sorted(stamps.begin(), stamps.end()));
  for (std::size_t k = 0; k < pairs.first.size(); ++k) {
    const double t = pairs.second[k].t;
    const auto it = std::lower_bound(stamps.begin(), stamps.end(), t);
    double best = std::numeric_limits<double>::infinity();
    if (it != stamps.end()) best = std::min(best, std::abs(*it - t));
    if (it != stamps.begin()) best = std::min(best, std::abs(*std::prev(it) - t));
    EXPECT_EQ(std::abs(pairs.first[k].t - t), best) << "pair " << k;
    EXPECT_LE(best, 0.01);
  }
}

}  // namespace

// REFERENCE.md: evo_ape kitti KITTI_00_gt.txt KITTI_00_ORB.txt -a
TEST(EvalEvoReference, Kitti00ApeTranslationSe3) {
  DYNSLAM_REQUIRE_SHARED(gt, "data/evo/KITTI_00_gt.txt");
  DYNSLAM_REQUIRE_SHARED(orb, "data/evo/KITTI_00_ORB.txt");
  const auto pairs = ev::associateByIndex(core::readKitti(gt), core::readKitti(orb));
  ASSERT_EQ(pairs.first.size(), 4541u);
  const ev::ErrorStatistics evo{1.3034497145650266, 1.1569971285389768,  1.065624769555848,
                                0.6002822693968323, 0.06931322021483087, 3.587949120678954,
                                7715.073440292808};
  expectStatistics(apeStats(pairs, ev::AlignmentMode::Se3), evo, 1e-9);
}

// REFERENCE.md: evo_rpe kitti KITTI_00_gt.txt KITTI_00_ORB.txt --delta 10 --delta_unit m
TEST(EvalEvoReference, Kitti00RpeTranslation10mConsecutive) {
  DYNSLAM_REQUIRE_SHARED(gt, "data/evo/KITTI_00_gt.txt");
  DYNSLAM_REQUIRE_SHARED(orb, "data/evo/KITTI_00_ORB.txt");
  const auto pairs = ev::associateByIndex(core::readKitti(gt), core::readKitti(orb));
  ev::RpeOptions options;
  options.delta = 10.0;
  options.delta_unit = ev::DeltaUnit::Meters;
  const ev::RpeResult rpe = ev::computeRpe(pairs.first, pairs.second, options);
  EXPECT_EQ(rpe.pairs.size(), 353u);
  const ev::ErrorStatistics evo{0.22626134329310163, 0.16901737200653275,  0.13848432516645606,
                                0.1504238127053164,  0.025322719660754993, 1.2722090778658726,
                                18.07155100048597};
  expectStatistics(ev::computeStatistics(rpe.errors), evo, 1e-9);

  // Pairs chosen on the reference path give other figures: evo chose them on the estimate.
  options.pairs_from_reference = true;
  const ev::RpeResult from_ref = ev::computeRpe(pairs.first, pairs.second, options);
  EXPECT_EQ(from_ref.pairs.size(), 356u);
  EXPECT_GT(std::abs(ev::computeStatistics(from_ref.errors).mean - evo.mean), 1e-3);
}

// fr2_desk: evo's author posted this output of `evo_ape` with SE(3) alignment for evo's test
// pair (MichaelGrupp/evo issue #8, 6 decimals); 2174 associated pairs is also what an
// evo pull-request review reported for this pair with the default 0.01 s.
TEST(EvalEvoReference, Fr2DeskApeTranslationSe3) {
  DYNSLAM_REQUIRE_SHARED(gt_path, "data/evo/fr2_desk_groundtruth.txt");
  DYNSLAM_REQUIRE_SHARED(orb_path, "data/evo/fr2_desk_ORB.txt");
  const core::Trajectory gt = core::readTum(gt_path);
  const core::Trajectory orb = core::readTum(orb_path);
  ASSERT_EQ(gt.size(), 20957u);
  ASSERT_EQ(orb.size(), 2893u);
  const auto pairs = ev::associateByTime(gt, orb);
  EXPECT_EQ(pairs.first.size(), 2174u);
  EXPECT_EQ(pairs.max_pairs, 2893u);
  expectNearestReferenceStamps(gt, pairs);

  const ev::ErrorStatistics s = apeStats(pairs, ev::AlignmentMode::Se3);
  EXPECT_NEAR(s.max, 0.024300, 5e-7);
  EXPECT_NEAR(s.mean, 0.007492, 5e-7);
  EXPECT_NEAR(s.median, 0.007415, 5e-7);
  EXPECT_NEAR(s.min, 0.000350, 5e-7);
  EXPECT_NEAR(s.rmse, 0.008119, 5e-7);
  EXPECT_NEAR(s.sse, 0.143305, 5e-7);
  EXPECT_NEAR(s.std, 0.003129, 5e-7);
  EXPECT_NEAR(s.rmse, independentApeRmse(pairs, false), 1e-12);

  const ev::ErrorStatistics none = apeStats(pairs, ev::AlignmentMode::None);
  const ev::ErrorStatistics sim3 = apeStats(pairs, ev::AlignmentMode::Sim3);
  EXPECT_LT(s.rmse, none.rmse);
  EXPECT_LE(sim3.rmse, s.rmse);
  EXPECT_NEAR(sim3.rmse, independentApeRmse(pairs, true), 1e-12);
}

TEST(EvalEvoReference, Fr1XyzAssociationAndApe) {
  DYNSLAM_REQUIRE_SHARED(gt_path, "data/evo/freiburg1_xyz-groundtruth.txt");
  DYNSLAM_REQUIRE_SHARED(est_path, "data/evo/freiburg1_xyz-rgbdslam.txt");
  const core::Trajectory gt = core::readTum(gt_path);
  const core::Trajectory est = core::readTum(est_path);
  ASSERT_EQ(gt.size(), 3000u);
  ASSERT_EQ(est.size(), 788u);
  const auto pairs = ev::associateByTime(gt, est);
  EXPECT_EQ(pairs.first.size(), 785u);
  expectNearestReferenceStamps(gt, pairs);

  const ev::ErrorStatistics none = apeStats(pairs, ev::AlignmentMode::None);
  const ev::ErrorStatistics se3 = apeStats(pairs, ev::AlignmentMode::Se3);
  const ev::ErrorStatistics sim3 = apeStats(pairs, ev::AlignmentMode::Sim3);
  EXPECT_LT(se3.rmse, none.rmse);
  EXPECT_LE(sim3.rmse, se3.rmse);
  EXPECT_NEAR(se3.rmse, independentApeRmse(pairs, false), 1e-12);
  EXPECT_NEAR(sim3.rmse, independentApeRmse(pairs, true), 1e-12);
  // Regression values of this implementation (RGBD-SLAM on fr1_xyz: about 1.3 cm).
  EXPECT_NEAR(se3.rmse, 0.013470088849733658, 1e-12);
  EXPECT_NEAR(sim3.rmse, 0.013389384904168177, 1e-12);
}

TEST(EvalEvoReference, V102EurocGroundTruthAgainstTumEstimate) {
  DYNSLAM_REQUIRE_SHARED(gt_path, "data/evo/V102_groundtruth.csv");
  DYNSLAM_REQUIRE_SHARED(est_path, "data/evo/V102.txt");
  const core::Trajectory gt = core::readEurocCsv(gt_path);
  const core::Trajectory est = core::readTum(est_path);
  ASSERT_EQ(gt.size(), 16702u);
  ASSERT_EQ(est.size(), 807u);
  const auto pairs = ev::associateByTime(gt, est);
  EXPECT_EQ(pairs.first.size(), 798u);
  expectNearestReferenceStamps(gt, pairs);

  const ev::ErrorStatistics none = apeStats(pairs, ev::AlignmentMode::None);
  const ev::ErrorStatistics se3 = apeStats(pairs, ev::AlignmentMode::Se3);
  const ev::ErrorStatistics sim3 = apeStats(pairs, ev::AlignmentMode::Sim3);
  EXPECT_LT(se3.rmse, none.rmse);
  EXPECT_LE(sim3.rmse, se3.rmse);
  EXPECT_NEAR(se3.rmse, independentApeRmse(pairs, false), 1e-12);
  EXPECT_NEAR(sim3.rmse, independentApeRmse(pairs, true), 1e-12);
  EXPECT_NEAR(se3.rmse, 0.09172711520685754, 1e-12);
  EXPECT_NEAR(sim3.rmse, 0.08384138804295282, 1e-12);
}
