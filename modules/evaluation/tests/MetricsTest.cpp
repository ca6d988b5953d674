// Statistics, pose relations, APE, RPE pair selection and alignment on small synthetic cases
// whose results are known in closed form (evo's own filter test cases included).
#include <dynslam/evaluation/Alignment.h>
#include <dynslam/evaluation/Ape.h>
#include <dynslam/evaluation/EvaluationError.h>
#include <dynslam/evaluation/Rpe.h>
#include <dynslam/evaluation/Statistics.h>

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace ev = dynslam::evaluation;
using dynslam::core::StampedPose;
using dynslam::core::Trajectory;

namespace {

constexpr double kPi = 3.14159265358979323846;

StampedPose poseAt(double t, const Eigen::Vector3d& p,
                   const Eigen::Matrix3d& r = Eigen::Matrix3d::Identity()) {
  StampedPose pose;
  pose.t = t;
  pose.T_world_body.linear() = r;
  pose.T_world_body.translation() = p;
  return pose;
}

Trajectory along(const std::vector<double>& z) {
  Trajectory t;
  for (std::size_t i = 0; i < z.size(); ++i) t.push_back(poseAt(double(i), {0, 0, z[i]}));
  return t;
}

/// A wiggly 3-D path with turning orientation, 100 poses.
Trajectory curvedPath() {
  Trajectory t;
  for (int i = 0; i < 100; ++i) {
    const double s = 0.1 * i;
    const Eigen::Matrix3d r =
        Eigen::AngleAxisd(0.2 * s, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    t.push_back(poseAt(s, {std::cos(s) * 5, std::sin(s) * 3, 0.3 * s}, r));
  }
  return t;
}

using Pairs = ev::IdPairs;

}  // namespace

TEST(EvalStatistics, MatchNumpyDefinitions) {
  const ev::ErrorStatistics s = ev::computeStatistics({4.0, 1.0, 3.0, 2.0});
  EXPECT_DOUBLE_EQ(s.mean, 2.5);
  EXPECT_DOUBLE_EQ(s.median, 2.5);           // mean of the two middle values
  EXPECT_DOUBLE_EQ(s.std, std::sqrt(1.25));  // population std (ddof = 0)
  EXPECT_DOUBLE_EQ(s.sse, 30.0);
  EXPECT_DOUBLE_EQ(s.rmse, std::sqrt(7.5));
  EXPECT_DOUBLE_EQ(s.min, 1.0);
  EXPECT_DOUBLE_EQ(s.max, 4.0);
  EXPECT_DOUBLE_EQ(ev::computeStatistics({5.0, 1.0, 3.0}).median, 3.0);
  EXPECT_THROW(ev::computeStatistics({}), ev::EvaluationError);
}

TEST(EvalStatistics, PairwiseSumFollowsNumpyBlocks) {
  // Below 8 values a plain left-to-right sum; 1e16 + 1 + 1 - 1e16 loses both ones there.
  const double few[] = {1e16, 1.0, 1.0, -1e16};
  EXPECT_EQ(ev::pairwiseSum(few, 4), 0.0);
  // From 8 values on, 8 lanes summed as ((r0 + r1) + (r2 + r3)) + ((r4 + r5) + (r6 + r7)), the
  // 9th value added last: (1e16 + 1) rounds to 1e16, the other six ones survive -> 6 (a plain
  // left-to-right sum would give 0).
  const double lanes[] = {1e16, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, -1e16};
  EXPECT_EQ(ev::pairwiseSum(lanes, 9), 6.0);
  std::vector<double> many(1000);
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  long double exact = 0.0L;
  for (double& v : many) exact += (v = u(rng));
  EXPECT_NEAR(ev::pairwiseSum(many.data(), many.size()), static_cast<double>(exact), 1e-12);
}

TEST(EvalPoseRelations, ClosedFormValues) {
  const double angle = 0.3;
  Eigen::Matrix4d e = Eigen::Matrix4d::Identity();
  e.block<3, 3>(0, 0) = Eigen::AngleAxisd(angle, Eigen::Vector3d(1, 2, 2) / 3.0).toRotationMatrix();
  e.block<3, 1>(0, 3) = Eigen::Vector3d(3, 4, 12);                 // norm 13
  const double rot_part = 2.0 * std::sqrt(1.0 - std::cos(angle));  // |R - I|_F
  EXPECT_NEAR(ev::poseError(e, ev::PoseRelation::TranslationPart), 13.0, 1e-12);
  EXPECT_NEAR(ev::poseError(e, ev::PoseRelation::RotationPart), rot_part, 1e-12);
  EXPECT_NEAR(ev::poseError(e, ev::PoseRelation::FullTransformation),
              std::sqrt(rot_part * rot_part + 169.0), 1e-12);
  EXPECT_NEAR(ev::poseError(e, ev::PoseRelation::AngleRad), angle, 1e-12);
  EXPECT_NEAR(ev::poseError(e, ev::PoseRelation::AngleDeg), angle * 180.0 / kPi, 1e-10);
  EXPECT_EQ(ev::parsePoseRelation("trans_part"), ev::PoseRelation::TranslationPart);
  EXPECT_EQ(ev::parsePoseRelation("angle_deg"), ev::PoseRelation::AngleDeg);
  EXPECT_THROW(ev::parsePoseRelation("translation"), std::invalid_argument);
}

TEST(EvalPoseRelations, RotationAngleOverTheWholeRange) {
  std::mt19937 rng(2);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (double angle : {0.0, 1e-9, 0.5, 1.5, 3.0, kPi - 1e-7, kPi}) {
    const Eigen::Vector3d axis = Eigen::Vector3d(u(rng), u(rng), u(rng)).normalized();
    const Eigen::Matrix3d r = Eigen::AngleAxisd(angle, axis).toRotationMatrix();
    EXPECT_NEAR(ev::rotationAngle(r), angle, 1e-7) << angle;
  }
}

TEST(EvalApe, TranslationAndRotationErrors) {
  const Trajectory ref = curvedPath();
  Trajectory est = ref;
  // Shift every estimated pose by 0.5 m along its own x axis and turn it by 0.1 rad.
  for (auto& p : est) {
    p.T_world_body = p.T_world_body * Eigen::Translation3d(0.5, 0, 0) *
                     Eigen::AngleAxisd(0.1, Eigen::Vector3d::UnitY());
  }
  for (double e : ev::computeApe(ref, est, ev::PoseRelation::TranslationPart))
    EXPECT_NEAR(e, 0.5, 1e-12);
  for (double e : ev::computeApe(ref, est, ev::PoseRelation::AngleRad)) EXPECT_NEAR(e, 0.1, 1e-12);
  EXPECT_THROW(ev::computeApe(ref, Trajectory(ref.begin(), ref.end() - 1),
                              ev::PoseRelation::TranslationPart),
               ev::EvaluationError);
}

TEST(EvalRpePairs, ByIndex) {
  EXPECT_EQ(ev::filterPairsByIndex(7, 2, false), (Pairs{{0, 2}, {2, 4}, {4, 6}}));
  EXPECT_EQ(ev::filterPairsByIndex(6, 2, false), (Pairs{{0, 2}, {2, 4}}));
  EXPECT_EQ(ev::filterPairsByIndex(5, 2, true), (Pairs{{0, 2}, {1, 3}, {2, 4}}));
  EXPECT_TRUE(ev::filterPairsByIndex(2, 2, false).empty());
}

TEST(EvalRpePairs, ByPathAllPairsLikeEvoFilterTests) {
  // evo test_filters.py: POSES_1..3, z positions.
  const Trajectory poses_1 = along({0, 0.5, 0, 1});
  EXPECT_EQ(ev::filterPairsByPath(poses_1, 1.0, 0.0, true), (Pairs{{0, 2}, {2, 3}}));
  EXPECT_TRUE(ev::filterPairsByPath(poses_1, 2.5, 0.0, true).empty());
  EXPECT_EQ(ev::filterPairsByPath(along({0, 0.5, 0.99, 1.0}), 1.0, 0.001, true), (Pairs{{0, 3}}));
  const Trajectory poses_3 = along({0.0, 0.9, 0.99, 0.999, 0.9999, 0.99999, 0.999999, 0.9999999});
  EXPECT_EQ(ev::filterPairsByPath(poses_3, 1.0, 0.2, true), (Pairs{{0, 7}}));
}

TEST(EvalRpePairs, ByPathToleranceEdge) {
  // Path lengths from pose 0: 1, 2, 3 (binary exact); delta 2.5 lies between 2 and 3, the
  // first of the equally close ones (2) is the candidate; accepted only with tol >= 0.5.
  const Trajectory t = along({0, 1, 2, 3});
  EXPECT_EQ(ev::filterPairsByPath(t, 2.5, 0.5, true), (Pairs{{0, 2}, {1, 3}}));
  EXPECT_TRUE(ev::filterPairsByPath(t, 2.5, 0.4999, true).empty());
}

TEST(EvalRpePairs, ByPathConsecutiveStartsWhereThePathFirstReachesDelta) {
  // Released evo opens the first pair at the first pose with path >= delta (pose 2 here),
  // not at pose 0; this is the rule that reproduces evo's KITTI_00 reference figures.
  EXPECT_EQ(ev::filterPairsByPath(along({0, 1, 2, 3, 4}), 2.0, 0.0, false), (Pairs{{2, 4}}));
  EXPECT_EQ(ev::filterPairsByPath(along({0, 1, 2, 3, 4, 5, 6}), 2.0, 0.0, false),
            (Pairs{{2, 4}, {4, 6}}));
  // The running sum restarts at each mark: 0.75 + 0.75 reaches 1.5 at pose 2 and pose 4.
  EXPECT_EQ(ev::filterPairsByPath(along({0, 0.75, 1.5, 2.25, 3.0}), 1.5, 0.0, false),
            (Pairs{{2, 4}}));
}

TEST(EvalRpe, InvariantToAGlobalTransformAndDetectsScale) {
  const Trajectory ref = curvedPath();
  Trajectory est = ref;
  const Eigen::Isometry3d g = Eigen::Translation3d(10, -4, 2) *
                              Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 1, 0).normalized());
  for (auto& p : est) p.T_world_body = g * p.T_world_body;
  ev::RpeOptions options;
  options.delta = 5;
  const ev::RpeResult same = ev::computeRpe(ref, est, options);
  EXPECT_EQ(same.pairs.size(), 19u);  // (0,5) ... (90,95)
  for (double e : same.errors) EXPECT_NEAR(e, 0.0, 1e-12);

  // Scaling every position by 1.1 makes each relative translation 10 % too long.
  Trajectory scaled = ref;
  for (auto& p : scaled) p.T_world_body.translation() *= 1.1;
  options.delta = 1;
  options.all_pairs = true;
  const ev::RpeResult r = ev::computeRpe(ref, scaled, options);
  ASSERT_EQ(r.pairs.size(), 99u);
  for (std::size_t k = 0; k < r.pairs.size(); ++k) {
    const auto [i, j] = r.pairs[k];
    const double step =
        (ref[j].T_world_body.translation() - ref[i].T_world_body.translation()).norm();
    EXPECT_NEAR(r.errors[k], 0.1 * step, 1e-12);
  }
  options.delta = 1.5;
  options.all_pairs = false;
  EXPECT_THROW(ev::computeRpe(ref, est, options), ev::EvaluationError);  // frames need integers
  options.delta = 1000;
  options.delta_unit = ev::DeltaUnit::Meters;
  EXPECT_THROW(ev::computeRpe(ref, est, options), ev::EvaluationError);  // no pair found
}

TEST(EvalRpe, PairsComeFromTheEstimateUnlessAskedForTheReference) {
  const Trajectory ref = along({0, 1, 2, 3, 4, 5, 6});
  const Trajectory est = along({0, 2, 4, 6, 8, 10, 12});  // twice as fast
  ev::RpeOptions options;
  options.delta = 2;
  options.delta_unit = ev::DeltaUnit::Meters;
  const ev::RpeResult from_est = ev::computeRpe(ref, est, options);
  EXPECT_EQ(from_est.pairs, (Pairs{{1, 2}, {2, 3}, {3, 4}, {4, 5}, {5, 6}}));
  for (double e : from_est.errors) EXPECT_NEAR(e, 1.0, 1e-12);  // 2 m estimated vs 1 m true
  options.pairs_from_reference = true;
  const ev::RpeResult from_ref = ev::computeRpe(ref, est, options);
  EXPECT_EQ(from_ref.pairs, (Pairs{{2, 4}, {4, 6}}));
  for (double e : from_ref.errors) EXPECT_NEAR(e, 2.0, 1e-12);  // 4 m estimated vs 2 m true
}

TEST(EvalAlignment, Se3Sim3AndOrigin) {
  const Trajectory ref = curvedPath();
  Trajectory moved = ref;
  ev::SimilarityTransform known;
  known.rotation =
      Eigen::AngleAxisd(-0.4, Eigen::Vector3d(0.2, 1, 0.1).normalized()).toRotationMatrix();
  known.translation = Eigen::Vector3d(3, 2, 1);
  known.scale = 0.8;
  ev::applySimilarity(known, moved);

  Trajectory est = moved;
  const ev::AlignmentResult sim3 = ev::alignTrajectory(ref, est, ev::AlignmentMode::Sim3, false);
  EXPECT_NEAR(sim3.umeyama.scale, 1.0 / 0.8, 1e-12);
  for (double e : ev::computeApe(ref, est, ev::PoseRelation::FullTransformation))
    EXPECT_NEAR(e, 0.0, 1e-9);

  // SE(3) cannot undo the scale: error stays, but below the unaligned one.
  Trajectory est_se3 = moved;
  ev::alignTrajectory(ref, est_se3, ev::AlignmentMode::Se3, false);
  const auto rmse = [&](const Trajectory& e) {
    return ev::computeStatistics(ev::computeApe(ref, e, ev::PoseRelation::TranslationPart)).rmse;
  };
  EXPECT_GT(rmse(est_se3), 1e-3);
  EXPECT_LT(rmse(est_se3), rmse(moved));

  // Origin alignment puts the first estimated pose exactly on the first reference pose.
  Trajectory est_origin = moved;
  const ev::AlignmentResult origin =
      ev::alignTrajectory(ref, est_origin, ev::AlignmentMode::None, true);
  EXPECT_TRUE(origin.origin_aligned);
  EXPECT_NEAR((est_origin.front().T_world_body.matrix() - ref.front().T_world_body.matrix()).norm(),
              0.0, 1e-12);
  EXPECT_EQ(ev::parseAlignmentMode("sim3"), ev::AlignmentMode::Sim3);
  EXPECT_THROW(ev::parseAlignmentMode("se2"), std::invalid_argument);
}
