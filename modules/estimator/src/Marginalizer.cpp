#include "dynslam/estimator/Marginalizer.h"

#include "dynslam/estimator/StateBlocks.h"

#include <Eigen/Eigenvalues>

#include <map>
#include <stdexcept>

namespace dynslam::estimator {
namespace {

using RowMajor = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

/// Ceres' robust-loss correction (Triggs et al.): scales the residual and Jacobian so that the
/// Gauss-Newton model of rho(|r|^2) is |J' dx + r'|^2.
void applyLoss(const ceres::LossFunction& loss, Eigen::VectorXd& r, Eigen::MatrixXd& J) {
  const double sq = r.squaredNorm();
  double rho[3];
  loss.Evaluate(sq, rho);
  const double sqrtRho1 = std::sqrt(rho[1]);
  double residualScale = sqrtRho1, alphaSq = 0;
  if (sq > 0 && rho[2] > 0) {
    const double D = 1.0 + 2.0 * sq * rho[2] / rho[1];
    const double alpha = 1.0 - std::sqrt(D);
    residualScale = sqrtRho1 / (1.0 - alpha);
    alphaSq = alpha / sq;
  }
  J = sqrtRho1 * (J - alphaSq * r * (r.transpose() * J));
  r *= residualScale;
}

/// The pseudo-inverse of a symmetric matrix: eigenvalues below eps (relative to the largest, at
/// least 1) are taken as zero.
Eigen::MatrixXd pseudoInverse(const Eigen::MatrixXd& A, double eps) {
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(0.5 * (A + A.transpose()));
  const double floor = eps * std::max(1.0, es.eigenvalues().cwiseAbs().maxCoeff());
  const Eigen::VectorXd inv =
      (es.eigenvalues().array() > floor).select(es.eigenvalues().cwiseInverse(), 0.0);
  return Eigen::MatrixXd(es.eigenvectors() * inv.asDiagonal() * es.eigenvectors().transpose());
}

/// The staying blocks' information once the leaving ones are eliminated, in Jacobi-scaled
/// coordinates (x_scaled = D^1/2 x): A dx^2 + 2 b dx.
struct SchurComplement {
  Eigen::MatrixXd A;
  Eigen::VectorXd b;
  Eigen::VectorXd scale;  ///< D^-1/2 over all m + n columns
};

/// H and g over the m leaving columns, then the n staying ones.
SchurComplement eliminateLeaving(Eigen::MatrixXd H, Eigen::VectorXd g, int m, int n, double eps) {
  // Jacobi scaling: the states' units differ by many orders of magnitude (a bias random walk
  // between keyframes 33 ms apart carries ~1e11 of information, a position ~1e4), so the
  // eigenvalue floors below are taken on D^-1/2 H D^-1/2, whose diagonal is one. A floor
  // relative to the largest eigenvalue of H itself dropped every direction weaker than a
  // hundred-millionth of the stiffest, e.g. the gyro bias as the window's rotations fix it.
  const Eigen::VectorXd diagonal = H.diagonal();
  SchurComplement s;
  s.scale = (diagonal.array() > 0).select(diagonal.array().rsqrt(), 1.0).matrix();
  H = s.scale.asDiagonal() * H * s.scale.asDiagonal();
  g = s.scale.asDiagonal() * g;
  // Schur complement of the leaving block, with a pseudo-inverse (its information can be
  // rank-deficient, e.g. an unobserved yaw).
  const Eigen::MatrixXd Hmm_inv =
      m > 0 ? pseudoInverse(H.topLeftCorner(m, m), eps) : Eigen::MatrixXd();
  s.A = H.bottomRightCorner(n, n);
  s.b = g.tail(n);
  if (m > 0) {
    s.A -= H.bottomLeftCorner(n, m) * Hmm_inv * H.topRightCorner(m, n);
    s.b -= H.bottomLeftCorner(n, m) * Hmm_inv * g.head(m);
  }
  return s;
}

/// A = V S V^T (scaled) -> J = S^1/2 V^T D^1/2, r0 = S^-1/2 V^T b, so that
/// |J dx + r0|^2 = dx^T A dx + 2 b^T dx + c in the states' own units.
void squareRootOf(const SchurComplement& s, int n, double eps, Eigen::MatrixXd& J,
                  Eigen::VectorXd& r0) {
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(0.5 * (s.A + s.A.transpose()));
  const double floor = eps * std::max(1.0, es.eigenvalues().cwiseAbs().maxCoeff());
  const Eigen::VectorXd S = (es.eigenvalues().array() > floor).select(es.eigenvalues(), 0.0);
  const Eigen::VectorXd Sinv =
      (es.eigenvalues().array() > floor).select(es.eigenvalues().cwiseInverse(), 0.0);
  J = S.cwiseSqrt().asDiagonal() * es.eigenvectors().transpose() *
      s.scale.tail(n).cwiseInverse().asDiagonal();
  r0 = Sinv.cwiseSqrt().asDiagonal() * es.eigenvectors().transpose() * s.b;
}

}  // namespace

void Marginalizer::addFactor(std::shared_ptr<const ceres::CostFunction> cost,
                             const ceres::LossFunction* loss, std::vector<double*> blocks) {
  if (int(blocks.size()) != int(cost->parameter_block_sizes().size()))
    throw std::invalid_argument("Marginalizer::addFactor: block count does not match the factor");
  factors_.push_back({std::move(cost), loss, std::move(blocks)});
}

/// The columns of the normal equations: the leaving blocks first, then the staying ones, each
/// in order of first appearance among the factors.
struct Marginalizer::Layout {
  struct Column {
    int ambient = 0, tangent = 0, offset = 0;
    bool pose = false;
  };
  std::map<const double*, Column> columns;
  std::vector<double*> order[2];  // [0] leaving, [1] staying
  int m = 0, n = 0;               // tangent sizes of the leaving and the staying blocks
};

Marginalizer::Layout Marginalizer::layout(const std::set<const double*>& leaving) const {
  Layout l;
  for (const auto& f : factors_)
    for (size_t k = 0; k < f.blocks.size(); ++k) {
      double* b = f.blocks[k];
      if (l.columns.count(b) || constants_.count(b)) continue;
      Layout::Column c;
      c.ambient = f.cost->parameter_block_sizes()[k];
      c.pose = poses_.count(b) > 0;
      c.tangent = c.pose ? kPoseTangentSize : c.ambient;
      l.columns[b] = c;
      l.order[leaving.count(b) ? 0 : 1].push_back(b);
    }
  for (int side = 0; side < 2; ++side)
    for (double* b : l.order[side]) {
      l.columns[b].offset = l.m + l.n;
      (side == 0 ? l.m : l.n) += l.columns[b].tangent;
    }
  return l;
}

void Marginalizer::accumulate(const Layout& l, Eigen::MatrixXd& H, Eigen::VectorXd& g) const {
  // H = sum J^T J and g = sum J^T r, accumulated block by block: each factor's Jacobian spans
  // only its own blocks (a few columns of the m + n), and a dense product over all the columns
  // made this the estimator's largest cost (docs/notes/estimator.md, 2026-11-28 (sums)).
  H = Eigen::MatrixXd::Zero(l.m + l.n, l.m + l.n);
  g = Eigen::VectorXd::Zero(l.m + l.n);
  struct Span {
    size_t block = 0;                       // index among the factor's blocks
    int column = 0, width = 0, offset = 0;  // in the factor's compact Jacobian; in H
  };
  std::vector<Span> spans;
  for (const auto& f : factors_) {
    const int rows = f.cost->num_residuals();
    Eigen::VectorXd r(rows);
    std::vector<RowMajor> jac;
    std::vector<double*> jacPtr;
    for (size_t k = 0; k < f.blocks.size(); ++k)
      jac.emplace_back(rows, f.cost->parameter_block_sizes()[k]);
    for (auto& j : jac) jacPtr.push_back(j.data());
    if (!f.cost->Evaluate(f.blocks.data(), r.data(), jacPtr.data()))
      throw std::runtime_error("Marginalizer: a factor failed to evaluate");
    spans.clear();
    int width = 0;
    for (size_t k = 0; k < f.blocks.size(); ++k) {
      if (constants_.count(f.blocks[k])) continue;
      const Layout::Column& c = l.columns.at(f.blocks[k]);
      spans.push_back({k, width, c.tangent, c.offset});
      width += c.tangent;
    }
    Eigen::MatrixXd J(rows, width);  // the tangent parts of the factor's own blocks
    for (const Span& a : spans) J.middleCols(a.column, a.width) = jac[a.block].leftCols(a.width);
    if (f.loss) applyLoss(*f.loss, r, J);
    for (const Span& a : spans) {
      const auto Ja = J.middleCols(a.column, a.width);
      g.segment(a.offset, a.width).noalias() += Ja.transpose() * r;
      for (const Span& b : spans)
        H.block(a.offset, b.offset, a.width, b.width).noalias() +=
            Ja.transpose() * J.middleCols(b.column, b.width);
    }
  }
}

Marginalizer::Prior Marginalizer::marginalize(const std::set<const double*>& leaving,
                                              double eps) const {
  const Layout l = layout(leaving);
  Eigen::MatrixXd H;
  Eigen::VectorXd g;
  accumulate(l, H, g);
  Prior prior;
  if (l.n == 0) return prior;
  const SchurComplement schur = eliminateLeaving(std::move(H), std::move(g), l.m, l.n, eps);
  Eigen::MatrixXd J;
  Eigen::VectorXd r0;
  squareRootOf(schur, l.n, eps, J, r0);
  std::vector<PriorBlock> blocks;
  for (double* block : l.order[1]) {
    const Layout::Column& c = l.columns.at(block);
    blocks.push_back({c.ambient, c.pose, std::vector<double>(block, block + c.ambient)});
    prior.blocks.push_back(block);
  }
  prior.factor = std::make_shared<MarginalizationFactor>(std::move(blocks), J, r0);
  return prior;
}

}  // namespace dynslam::estimator
