#include <dynslam/core/HungarianAssignment.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>

using namespace dynslam::core;

namespace {

double totalCost(const Eigen::MatrixXd& cost, const std::vector<int>& assignment) {
  double total = 0;
  for (size_t r = 0; r < assignment.size(); ++r)
    if (assignment[r] >= 0) total += cost(r, assignment[r]);
  return total;
}

/// The least total cost over every injective assignment of the smaller side (brute force).
double bruteForceMinimum(const Eigen::MatrixXd& cost) {
  const bool transposed = cost.rows() > cost.cols();
  const Eigen::MatrixXd a = transposed ? Eigen::MatrixXd(cost.transpose()) : cost;
  std::vector<int> columns(a.cols());
  std::iota(columns.begin(), columns.end(), 0);
  double best = std::numeric_limits<double>::infinity();
  do {  // the first a.rows() entries of each permutation pick the columns
    double total = 0;
    for (int r = 0; r < a.rows(); ++r) total += a(r, columns[r]);
    best = std::min(best, total);
  } while (std::next_permutation(columns.begin(), columns.end()));
  return best;
}

void expectValid(const std::vector<int>& assignment, const Eigen::MatrixXd& cost) {
  ASSERT_EQ(assignment.size(), size_t(cost.rows()));
  std::vector<int> used;
  for (int c : assignment)
    if (c >= 0) {
      EXPECT_LT(c, cost.cols());
      used.push_back(c);
    }
  EXPECT_EQ(used.size(), size_t(std::min(cost.rows(), cost.cols())));
  std::sort(used.begin(), used.end());
  EXPECT_TRUE(std::adjacent_find(used.begin(), used.end()) == used.end()) << "a column twice";
}

}  // namespace

TEST(TrackingHungarian, KnownSquareMatrix) {
  // Unique optimum 0->1 (1), 1->0 (2), 2->2 (2): total 5; every other permutation costs 6 or more.
  Eigen::MatrixXd cost(3, 3);
  cost << 4, 1, 3,  //
      2, 0, 5,      //
      3, 2, 2;
  const auto a = solveMinCostAssignment(cost);
  expectValid(a, cost);
  EXPECT_EQ(a, (std::vector<int>{1, 0, 2}));
  EXPECT_DOUBLE_EQ(totalCost(cost, a), 5);
}

TEST(TrackingHungarian, GreedyIsNotOptimal) {
  // Greedy takes the 1 at (0, 0) and is left with 100; the optimum pays 2 + 2.
  Eigen::MatrixXd cost(2, 2);
  cost << 1, 2,  //
      2, 100;
  EXPECT_EQ(solveMinCostAssignment(cost), (std::vector<int>{1, 0}));
}

TEST(TrackingHungarian, RectangularMatrices) {
  Eigen::MatrixXd wide(2, 4);  // more columns: every row gets one
  wide << 9, 9, 1, 9,          //
      9, 2, 1.5, 9;
  EXPECT_EQ(solveMinCostAssignment(wide), (std::vector<int>{2, 1}));
  const Eigen::MatrixXd tall = wide.transpose();  // more rows: two are left over
  EXPECT_EQ(solveMinCostAssignment(tall), (std::vector<int>{-1, 1, 0, -1}));
  EXPECT_TRUE(solveMinCostAssignment(Eigen::MatrixXd(0, 3)).empty());
  EXPECT_EQ(solveMinCostAssignment(Eigen::MatrixXd(2, 0)), (std::vector<int>{-1, -1}));
}

TEST(TrackingHungarian, MaximisesGain) {
  Eigen::MatrixXd gain(2, 3);
  gain << 0.9, 0.8, 0,  //
      0.85, 0, 0;
  // Max total: 0.8 + 0.85 beats 0.9 + 0.
  EXPECT_EQ(solveMaxGainAssignment(gain), (std::vector<int>{1, 0}));
}

TEST(TrackingHungarian, MatchesBruteForceOnRandomMatrices) {
  std::mt19937 rng(3);
  std::uniform_int_distribution<int> size(1, 6);
  std::uniform_real_distribution<double> value(-5, 5);
  std::uniform_int_distribution<int> small(0, 3);  // many ties
  for (int trial = 0; trial < 300; ++trial) {
    Eigen::MatrixXd cost(size(rng), size(rng));
    for (int r = 0; r < cost.rows(); ++r)
      for (int c = 0; c < cost.cols(); ++c)
        cost(r, c) = trial % 2 ? value(rng) : double(small(rng));
    const auto a = solveMinCostAssignment(cost);
    expectValid(a, cost);
    EXPECT_NEAR(totalCost(cost, a), bruteForceMinimum(cost), 1e-9) << "trial " << trial << "\n"
                                                                   << cost;
  }
}

TEST(TrackingHungarian, RejectsNonFiniteCosts) {
  Eigen::MatrixXd cost = Eigen::MatrixXd::Zero(2, 2);
  cost(1, 0) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(solveMinCostAssignment(cost), std::invalid_argument);
}
