#include "dynslam/core/HungarianAssignment.h"

#include <limits>
#include <stdexcept>

namespace dynslam::core {

std::vector<int> solveMinCostAssignment(const Eigen::MatrixXd& cost) {
  if (!cost.allFinite())
    throw std::invalid_argument("solveMinCostAssignment: the cost matrix has a non-finite entry");
  std::vector<int> rowToColumn(cost.rows(), -1);
  const bool transposed = cost.rows() > cost.cols();
  const Eigen::MatrixXd a = transposed ? Eigen::MatrixXd(cost.transpose()) : cost;
  const int n = int(a.rows()), m = int(a.cols());  // n <= m
  if (n == 0) return rowToColumn;

  // 1-based: column 0 is a virtual column the row being inserted starts from.
  constexpr double kInf = std::numeric_limits<double>::infinity();
  std::vector<double> u(n + 1, 0.0), v(m + 1, 0.0);  // row and column potentials
  std::vector<int> rowOf(m + 1, 0), previous(m + 1, 0);
  for (int i = 1; i <= n; ++i) {
    // Insert row i: grow a tree of tight edges (Dijkstra on reduced costs) until it reaches a
    // free column, then flip the augmenting path.
    rowOf[0] = i;
    int j0 = 0;
    std::vector<double> minReduced(m + 1, kInf);
    std::vector<char> inTree(m + 1, 0);
    do {
      inTree[j0] = 1;
      const int i0 = rowOf[j0];
      double delta = kInf;
      int j1 = 0;
      for (int j = 1; j <= m; ++j) {
        if (inTree[j]) continue;
        const double reduced = a(i0 - 1, j - 1) - u[i0] - v[j];
        if (reduced < minReduced[j]) {
          minReduced[j] = reduced;
          previous[j] = j0;
        }
        if (minReduced[j] < delta) {
          delta = minReduced[j];
          j1 = j;
        }
      }
      for (int j = 0; j <= m; ++j) {
        if (inTree[j]) {
          u[rowOf[j]] += delta;
          v[j] -= delta;
        } else {
          minReduced[j] -= delta;
        }
      }
      j0 = j1;
    } while (rowOf[j0] != 0);
    do {
      const int j1 = previous[j0];
      rowOf[j0] = rowOf[j1];
      j0 = j1;
    } while (j0 != 0);
  }

  for (int j = 1; j <= m; ++j) {
    if (rowOf[j] == 0) continue;
    if (transposed)
      rowToColumn[j - 1] = rowOf[j] - 1;
    else
      rowToColumn[rowOf[j] - 1] = j - 1;
  }
  return rowToColumn;
}

std::vector<int> solveMaxGainAssignment(const Eigen::MatrixXd& gain) {
  return solveMinCostAssignment(-gain);
}

}  // namespace dynslam::core
