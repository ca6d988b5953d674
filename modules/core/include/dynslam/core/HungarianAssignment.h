#pragma once
// Optimal one-to-one assignment (Kuhn-Munkres, the "Hungarian" algorithm), for the tracker's
// association (method.md section 2) and the MOT metrics' matching.
//
// Written by hand (~50 lines): neither OpenCV nor MRPT has a public one. OpenCV's Kuhn-Munkres
// lives inside opencv_contrib's tracking_by_matching and shape modules, not in their API;
// MRPT's mrpt::slam::data_association offers nearest-neighbour and JCBB gating of landmarks,
// not a linear assignment; cv::EMD solves transportation problems but with a fixed iteration
// cap and float flows, a poor fit for an exact, integral assignment. This is the O(n^2 m)
// shortest-augmenting-path form with row and column potentials (Kuhn 1955, Munkres 1957, as
// given by Jonker and Volgenant), for an n x m matrix with n <= m (else on its transpose).
#include <Eigen/Core>

#include <vector>

namespace dynslam::core {

/// The assignment of rows to columns with the least total cost among those that pair
/// min(rows, cols) of them. Returns, per row, its column or -1 (a row left over when there are
/// more rows than columns). Throws std::invalid_argument for a non-finite cost.
std::vector<int> solveMinCostAssignment(const Eigen::MatrixXd& cost);

/// The same with the largest total gain (the costs negated).
std::vector<int> solveMaxGainAssignment(const Eigen::MatrixXd& gain);

}  // namespace dynslam::core
