// Marginalisation: the prior's Jacobians are right, and marginalising a state out of a small
// solved problem leaves the solution of the states that stay unchanged (issue 6).
#include "FactorJacobianCheck.h"
#include "ImuTestMotion.h"

#include <dynslam/estimator/Marginalizer.h>
#include <dynslam/estimator/factors/ImuFactor.h>

#include <ceres/ceres.h>
#include <gtest/gtest.h>

#include <random>

using namespace dynslam::estimator;
using namespace dynslam::estimator::testing;

namespace {

struct State {
  double pose[7];
  double speedBias[9];
};

State stateAt(double t) {
  const MotionState m = motionAt(t);
  State s;
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = m.q.toRotationMatrix();
  T.translation() = m.p;
  poseToBlock(T, s.pose);
  for (int k = 0; k < 3; ++k) s.speedBias[k] = m.v(k);
  for (int k = 3; k < 9; ++k) s.speedBias[k] = 0;
  return s;
}

std::shared_ptr<ImuFactor> imuBetween(double t0, double t1) {
  const double dt = 0.005;
  auto pre = std::make_shared<ImuPreintegration>(specificForce(t0), bodyRate(),
                                                 Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(),
                                                 ImuNoise{});
  for (int k = 1; k <= int(std::lround((t1 - t0) / dt)); ++k)
    pre->push(dt, specificForce(t0 + k * dt), bodyRate());
  return std::make_shared<ImuFactor>(pre);
}

/// A Gaussian prior on a pose (sigma_p metres, sigma_r radians) centred at `mean`.
std::shared_ptr<MarginalizationFactor> posePrior(const double* mean, double sigmaP,
                                                 double sigmaR) {
  Eigen::VectorXd w(6);
  w << Eigen::Vector3d::Constant(1 / sigmaP), Eigen::Vector3d::Constant(1 / sigmaR);
  return std::make_shared<MarginalizationFactor>(
      std::vector<PriorBlock>{{7, true, std::vector<double>(mean, mean + 7)}},
      Eigen::MatrixXd(w.asDiagonal()), Eigen::VectorXd::Zero(6));
}

std::shared_ptr<MarginalizationFactor> speedBiasPrior(const double* mean, double sigma) {
  return std::make_shared<MarginalizationFactor>(
      std::vector<PriorBlock>{{9, false, std::vector<double>(mean, mean + 9)}},
      Eigen::MatrixXd(Eigen::MatrixXd::Identity(9, 9) / sigma), Eigen::VectorXd::Zero(9));
}

void solve(ceres::Problem& problem) {
  ceres::Solver::Options options;
  options.linear_solver_type = ceres::DENSE_QR;
  options.max_num_iterations = 100;
  options.function_tolerance = options.gradient_tolerance = options.parameter_tolerance = 1e-15;
  ceres::Solver::Summary summary;
  ceres::Solve(options, &problem, &summary);
  ASSERT_TRUE(summary.IsSolutionUsable()) << summary.BriefReport();
}

ceres::Problem::Options notOwning() {
  ceres::Problem::Options o;
  o.cost_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
  o.loss_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
  return o;
}

}  // namespace

TEST(MarginalizationFactor, JacobiansMatchNumericDifferentiation) {
  std::mt19937 rng(5);
  std::normal_distribution<double> n(0, 1);
  State x0 = stateAt(0.7), x = stateAt(0.9);
  Eigen::MatrixXd J(12, 15);
  for (int i = 0; i < J.size(); ++i) J.data()[i] = n(rng);
  Eigen::VectorXd r0(12);
  for (int i = 0; i < 12; ++i) r0(i) = n(rng);
  const MarginalizationFactor f(
      {{7, true, std::vector<double>(x0.pose, x0.pose + 7)},
       {9, false, std::vector<double>(x0.speedBias, x0.speedBias + 9)}},
      J, r0);
  const auto mismatch =
      compareJacobians(f, {std::vector<double>(x.pose, x.pose + 7),
                           std::vector<double>(x.speedBias, x.speedBias + 9)},
                       {true, false});
  EXPECT_LT(mismatch.max_rel_error, 1e-6) << mismatch.where;

  const double* at[] = {x0.pose, x0.speedBias};
  Eigen::VectorXd r(12);
  f.Evaluate(at, r.data(), nullptr);
  EXPECT_LT((r - r0).norm(), 1e-12) << "r0 at the linearisation point";
}

namespace {

/// Three states linked by IMU factors, with priors on the first and a prior on the last that
/// disagrees with the IMU (5 cm), so the optimum has residuals.
struct ConflictingPriors {
  double times[3] = {1.0, 1.3, 1.6};
  State truth[3] = {stateAt(times[0]), stateAt(times[1]), stateAt(times[2])};
  std::shared_ptr<ImuFactor> imu01 = imuBetween(times[0], times[1]);
  std::shared_ptr<ImuFactor> imu12 = imuBetween(times[1], times[2]);
  std::shared_ptr<MarginalizationFactor> prior0 = posePrior(truth[0].pose, 0.01, 0.01);
  std::shared_ptr<MarginalizationFactor> prior0sb = speedBiasPrior(truth[0].speedBias, 0.1);
  std::shared_ptr<MarginalizationFactor> prior2;
  ceres::HuberLoss huber{1.0};
  double gravity[3] = {kTestGravity.x(), kTestGravity.y(), kTestGravity.z()};  // held

  ConflictingPriors() {
    State shifted = truth[2];
    shifted.pose[0] += 0.05;
    prior2 = posePrior(shifted.pose, 0.02, 0.05);
  }

  /// All three states solved with every factor.
  void solveAll(State (&x)[3]) {
    ceres::Problem problem(notOwning());
    for (auto& s : x) {
      problem.AddParameterBlock(s.pose, 7, new PoseManifold);
      problem.AddParameterBlock(s.speedBias, 9);
    }
    problem.AddResidualBlock(prior0.get(), nullptr, x[0].pose);
    problem.AddResidualBlock(prior0sb.get(), nullptr, x[0].speedBias);
    problem.AddResidualBlock(imu01.get(), nullptr, x[0].pose, x[0].speedBias, x[1].pose,
                             x[1].speedBias, gravity);
    problem.AddResidualBlock(imu12.get(), nullptr, x[1].pose, x[1].speedBias, x[2].pose,
                             x[2].speedBias, gravity);
    problem.SetParameterBlockConstant(gravity);
    problem.AddResidualBlock(prior2.get(), &huber, x[2].pose);
    solve(problem);
  }

  /// State 0 marginalised at x's values; states 1 and 2 then solved with the prior it left.
  void solveWithoutTheFirst(State (&x)[3]) {
    Marginalizer marginalizer;
    for (auto& s : x) marginalizer.setPoseBlock(s.pose);
    marginalizer.setConstantBlock(gravity);
    marginalizer.addFactor(prior0, nullptr, {x[0].pose});
    marginalizer.addFactor(prior0sb, nullptr, {x[0].speedBias});
    marginalizer.addFactor(imu01, nullptr,
                           {x[0].pose, x[0].speedBias, x[1].pose, x[1].speedBias, gravity});
    const auto prior = marginalizer.marginalize({x[0].pose, x[0].speedBias});
    ASSERT_TRUE(prior.factor);
    ASSERT_EQ(prior.blocks.size(), 2u);
    EXPECT_EQ(prior.blocks[0], x[1].pose);
    for (int k = 1; k < 3; ++k) x[k].pose[2] -= 0.02;  // a perturbed start
    ceres::Problem problem(notOwning());
    for (int k = 1; k < 3; ++k) {
      problem.AddParameterBlock(x[k].pose, 7, new PoseManifold);
      problem.AddParameterBlock(x[k].speedBias, 9);
    }
    problem.AddResidualBlock(prior.factor.get(), nullptr, prior.blocks);
    problem.AddResidualBlock(imu12.get(), nullptr, x[1].pose, x[1].speedBias, x[2].pose,
                             x[2].speedBias, gravity);
    problem.SetParameterBlockConstant(gravity);
    problem.AddResidualBlock(prior2.get(), &huber, x[2].pose);
    solve(problem);
  }
};

}  // namespace

TEST(Marginalizer, MarginalisingTheOldestStateKeepsTheSolution) {
  ConflictingPriors graph;
  State full[3] = {graph.truth[0], graph.truth[1], graph.truth[2]};
  for (auto& s : full) s.pose[1] += 0.03;  // start away from the optimum
  graph.solveAll(full);
  const double pull = (Eigen::Map<Eigen::Vector3d>(full[2].pose) -
                       Eigen::Map<Eigen::Vector3d>(graph.truth[2].pose)).norm();
  EXPECT_GT(pull, 0.005) << "the conflicting prior moved the optimum";

  State kept[3] = {full[0], full[1], full[2]};
  graph.solveWithoutTheFirst(kept);
  for (int k = 1; k < 3; ++k) {
    for (int i = 0; i < 7; ++i)
      EXPECT_NEAR(kept[k].pose[i], full[k].pose[i], 1e-6) << k << "," << i;
    for (int i = 0; i < 9; ++i)
      EXPECT_NEAR(kept[k].speedBias[i], full[k].speedBias[i], 1e-5) << k << "," << i;
  }
}

namespace {

/// A Gaussian factor |J (x - x0)|^2 on scalar blocks, x0 = 0.
std::shared_ptr<MarginalizationFactor> scalarFactor(const Eigen::RowVectorXd& J) {
  std::vector<PriorBlock> blocks(J.size(), PriorBlock{1, false, {0.0}});
  return std::make_shared<MarginalizationFactor>(blocks, Eigen::MatrixXd(J),
                                                 Eigen::VectorXd::Zero(1));
}

}  // namespace

// States of very different stiffness leave the window together: a bias held by a random walk
// over 33 ms carries ~1e12 of information, a velocity seen twice ~1e-2. A weak leaving state that
// is tied to a staying one must take that tie with it; an eigenvalue floor relative to the
// stiffest state treated it as fixed and left its tie in the prior, 100 times overconfident here.
TEST(Marginalizer, AWeakLeavingStateNextToAStiffOneTakesItsTieAlong) {
  double stiff = 0, weak = 0, staying = 0;
  Eigen::RowVectorXd j1(1), j2(2), j3(1);
  j1 << 1e6;        // the stiff leaving state, on its own
  j2 << 0.1, -0.1;  // the weak leaving state, tied to the staying one
  j3 << 0.01;       // what else is known of the staying one
  Marginalizer marginalizer;
  marginalizer.addFactor(scalarFactor(j1), nullptr, {&stiff});
  marginalizer.addFactor(scalarFactor(j2), nullptr, {&weak, &staying});
  marginalizer.addFactor(scalarFactor(j3), nullptr, {&staying});
  const auto prior = marginalizer.marginalize({&stiff, &weak});
  ASSERT_TRUE(prior.factor);
  ASSERT_EQ(prior.blocks.size(), 1u);
  const int rows = prior.factor->num_residuals();
  Eigen::VectorXd r(rows), J(rows);
  const double* at[] = {&staying};
  double* jacobians[] = {J.data()};
  ASSERT_TRUE(prior.factor->Evaluate(at, r.data(), jacobians));
  // The weak state is free once it leaves, so the tie says nothing: information 0.01^2 remains.
  EXPECT_NEAR(J.squaredNorm(), 1e-4, 1e-8);
}
