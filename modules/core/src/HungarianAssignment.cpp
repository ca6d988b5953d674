#include "dynslam/core/HungarianAssignment.h"

#include <limits>
#include <stdexcept>

namespace dynslam::core {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

/// Shortest augmenting paths on an n x m cost (n <= m), rows inserted one at a time. 1-based:
/// column 0 is a virtual column the row being inserted starts from.
class AugmentingPaths {
 public:
  explicit AugmentingPaths(const Eigen::MatrixXd& a)
      : a_(a),
        m_(int(a.cols())),
        u_(a.rows() + 1, 0.0),
        v_(m_ + 1, 0.0),
        rowOf_(m_ + 1, 0),
        previous_(m_ + 1, 0) {}

  /// Insert row i: grow a tree of tight edges (Dijkstra on reduced costs) until it reaches a
  /// free column, then flip the augmenting path.
  void insertRow(int i) {
    rowOf_[0] = i;
    int j0 = reachFreeColumn();
    do {
      const int j1 = previous_[j0];
      rowOf_[j0] = rowOf_[j1];
      j0 = j1;
    } while (j0 != 0);
  }

  /// The row (1-based, 0: none) assigned to column j (1-based).
  int rowOf(int j) const { return rowOf_[j]; }

 private:
  int reachFreeColumn() {
    int j0 = 0;
    std::vector<double> minReduced(m_ + 1, kInf);
    std::vector<char> inTree(m_ + 1, 0);
    do {
      inTree[j0] = 1;
      const int i0 = rowOf_[j0];
      double delta = kInf;
      int j1 = 0;
      for (int j = 1; j <= m_; ++j) {
        if (inTree[j]) continue;
        const double reduced = a_(i0 - 1, j - 1) - u_[i0] - v_[j];
        if (reduced < minReduced[j]) {
          minReduced[j] = reduced;
          previous_[j] = j0;
        }
        if (minReduced[j] < delta) {
          delta = minReduced[j];
          j1 = j;
        }
      }
      for (int j = 0; j <= m_; ++j) {
        if (inTree[j]) {
          u_[rowOf_[j]] += delta;
          v_[j] -= delta;
        } else {
          minReduced[j] -= delta;
        }
      }
      j0 = j1;
    } while (rowOf_[j0] != 0);
    return j0;
  }

  const Eigen::MatrixXd& a_;
  const int m_;
  std::vector<double> u_, v_;  // row and column potentials
  std::vector<int> rowOf_, previous_;
};

}  // namespace

std::vector<int> solveMinCostAssignment(const Eigen::MatrixXd& cost) {
  if (!cost.allFinite())
    throw std::invalid_argument("solveMinCostAssignment: the cost matrix has a non-finite entry");
  std::vector<int> rowToColumn(cost.rows(), -1);
  const bool transposed = cost.rows() > cost.cols();
  const Eigen::MatrixXd a = transposed ? Eigen::MatrixXd(cost.transpose()) : cost;
  const int n = int(a.rows()), m = int(a.cols());  // n <= m
  if (n == 0) return rowToColumn;
  AugmentingPaths paths(a);
  for (int i = 1; i <= n; ++i) paths.insertRow(i);
  for (int j = 1; j <= m; ++j) {
    if (paths.rowOf(j) == 0) continue;
    if (transposed)
      rowToColumn[j - 1] = paths.rowOf(j) - 1;
    else
      rowToColumn[paths.rowOf(j) - 1] = j - 1;
  }
  return rowToColumn;
}

std::vector<int> solveMaxGainAssignment(const Eigen::MatrixXd& gain) {
  return solveMinCostAssignment(-gain);
}

}  // namespace dynslam::core
