// The first modes of K phi = omega^2 M phi by shift-invert Lanczos (Spectra), with a
// Sturm-sequence check that none was missed (modal.hpp, solveLowestModes).
#include <Spectra/SymEigsSolver.h>

#include <algorithm>
#include <cmath>
#include <optional>

#include "sim/core/errors.hpp"
#include "sim/modes/modal.hpp"

namespace mmv {
namespace {

/// The shift-inverted pencil in standard symmetric form: with K - sigma M = L L^T
/// (Cholesky, which exists only for a shift below every eigenvalue),
///     (K - sigma M)^-1 M x = nu x   <=>   L^-1 M L^-T y = nu y,  y = L^T x,
/// nu = 1 / (omega^2 - sigma): the lowest modes are the largest nu. Each product costs
/// two triangular solves and one product with M, and Lanczos needs no M inner product.
class ShiftInverted {
 public:
  using Scalar = double;
  ShiftInverted(const Eigen::MatrixXd& K, const Eigen::MatrixXd& M) : K_(K), M_(M) {}
  Eigen::Index rows() const { return K_.rows(); }
  Eigen::Index cols() const { return K_.cols(); }
  /// False when K - sigma M is not positive definite.
  bool factor(double sigma) {
    llt_.compute(K_ - sigma * M_);
    return llt_.info() == Eigen::Success;
  }
  void perform_op(const double* x_in, double* y_out) const {
    Eigen::VectorXd x = Eigen::Map<const Eigen::VectorXd>(x_in, rows());
    llt_.matrixU().solveInPlace(x);  // L^-T y
    Eigen::Map<Eigen::VectorXd> y(y_out, rows());
    y.noalias() = M_ * x;
    llt_.matrixL().solveInPlace(y);
  }
  /// x = L^-T y for the Ritz vectors y (columns).
  Eigen::MatrixXd back(const Eigen::MatrixXd& Y) const { return llt_.matrixU().solve(Y); }

 private:
  const Eigen::MatrixXd &K_, &M_;
  Eigen::LLT<Eigen::MatrixXd> llt_;
};

/// Number of eigenvalues of (K, M) below tau: the negative pivots of K - tau M
/// (Sylvester's law of inertia), or nullopt when the factorization is unusable.
std::optional<int> countBelow(const Eigen::MatrixXd& K, const Eigen::MatrixXd& M, double tau) {
  const Eigen::LDLT<Eigen::MatrixXd> ldlt(K - tau * M);
  if (ldlt.info() != Eigen::Success) return std::nullopt;
  const Eigen::VectorXd d = ldlt.vectorD();
  const double big = d.cwiseAbs().maxCoeff();
  int negative = 0;
  for (Eigen::Index i = 0; i < d.size(); ++i) {
    if (!(std::abs(d[i]) > 1e-13 * big)) return std::nullopt;  // tau sits on an eigenvalue
    negative += d[i] < 0;
  }
  return negative;
}

/// The shift-inverted pencil of an open tree (sim/statics/tree_operator.hpp): with
/// K - sigma M = L D L^T, D = R R^T (every pivot positive only for a shift below every
/// eigenvalue),
///     R^-1 L^-1 M L^-T R^-T y = nu y,   x = L^-T R^-T y,
/// each product two O(n) sweeps of the factor and one of M.
class TreeShiftInverted {
 public:
  using Scalar = double;
  explicit TreeShiftInverted(const TreeOperator& op) : op_(op) {}
  Eigen::Index rows() const { return op_.size(); }
  Eigen::Index cols() const { return op_.size(); }
  bool factor(double sigma) {
    factor_.emplace(op_.factor(sigma));
    return factor_->invertible() && factor_->pivots().minCoeff() > 0;
  }
  void perform_op(const double* x_in, double* y_out) const {
    const Eigen::VectorXd x = Eigen::Map<const Eigen::VectorXd>(x_in, rows());
    Eigen::Map<Eigen::VectorXd>(y_out, rows()) = factor_->halfInverse(
        factor_->forward(op_.multiplyM(factor_->backward(factor_->halfInverseTransposed(x)))));
  }
  Eigen::MatrixXd back(const Eigen::MatrixXd& Y) const {
    Eigen::MatrixXd X(Y.rows(), Y.cols());
    for (Eigen::Index c = 0; c < Y.cols(); ++c)
      X.col(c) = factor_->backward(factor_->halfInverseTransposed(Eigen::VectorXd(Y.col(c))));
    return X;
  }
  /// The eigenvalues below tau: the negative pivots of K - tau M, or nullopt when a
  /// pivot vanishes to round-off of its row's scale (tau on an eigenvalue).
  std::optional<int> countBelow(double tau) const {
    const TreeFactor f = op_.factor(tau);
    if (!f.invertible()) return std::nullopt;
    const Eigen::VectorXd scale = op_.diagonalK().cwiseAbs() + std::abs(tau) * op_.diagonalM();
    for (int j = 0; j < op_.size(); ++j)
      if (!(std::abs(f.pivots()[j]) > 1e-13 * scale[j])) return std::nullopt;
    return f.negativePivots();
  }

 private:
  const TreeOperator& op_;
  std::optional<TreeFactor> factor_;
};

/// Dense pencils count through countBelow(K, M, tau); the tree's through its pivots.
class DensePencil : public ShiftInverted {
 public:
  DensePencil(const Eigen::MatrixXd& K, const Eigen::MatrixXd& M) : ShiftInverted(K, M), K_(K), M_(M) {}
  std::optional<int> countBelow(double tau) const { return mmv::countBelow(K_, M_, tau); }

 private:
  const Eigen::MatrixXd &K_, &M_;
};

/// Shift-invert Lanczos on `op` (modal.hpp, solveLowestModes): a shift below every
/// eigenvalue found from `stiff` (the largest |K_ii / M_ii|), the `count` lowest modes
/// with x^T M x = 1 in the pencil's coordinates, and the Sturm check.
template <class Pencil>
std::optional<ModalSolution> lanczos(Pencil& op, double stiff, int count, const Eigen::VectorXd* start) {
  const Eigen::Index n = op.rows();
  if (!(stiff > 0)) return std::nullopt;
  // A small negative shift first (rigid-body modes sit at zero), then four times lower
  // until every pivot is positive.
  double sigma = -1e-9 * stiff;
  while (!op.factor(sigma)) {
    sigma *= 4;
    if (-sigma > 10 * stiff) return std::nullopt;
  }
  const int wanted = static_cast<int>(std::min<Eigen::Index>(n - 1, count + 1));  // one more to place the Sturm shift
  const Eigen::Index ncv = std::min<Eigen::Index>(n, std::max(2 * wanted + 1, wanted + 24));
  Spectra::SymEigsSolver<Pencil> eigs(op, wanted, ncv);
  if (start) {
    MMV_DEMAND(start->size() == n);
    eigs.init(start->data());
  } else {
    eigs.init();
  }
  eigs.compute(Spectra::SortRule::LargestAlge, 1000, 1e-12);
  if (eigs.info() != Spectra::CompInfo::Successful) return std::nullopt;
  const Eigen::VectorXd nu = eigs.eigenvalues();  // descending: the lowest modes first
  if (!(nu.minCoeff() > 0)) return std::nullopt;
  const Eigen::MatrixXd X = op.back(eigs.eigenvectors());  // x^T M x = nu for a unit y
  ModalSolution sol;
  sol.omega2.resize(count);
  sol.shapes.resize(n, count);
  for (int i = 0; i < count; ++i) {
    sol.omega2[i] = sigma + 1.0 / nu[i];
    sol.shapes.col(i) = X.col(i) / std::sqrt(nu[i]);
  }
  // Sturm check: exactly `count` eigenvalues lie below a point between the last mode
  // kept and the next one, so Lanczos missed none (e.g. one of a repeated pair).
  const double next = sigma + 1.0 / nu[count], last = sol.omega2[count - 1];
  if (!(next > last)) return std::nullopt;
  const std::optional<int> below = op.countBelow(0.5 * (last + next));
  if (!below || *below != count) return std::nullopt;
  return sol;
}

}  // namespace

std::optional<ModalSolution> solveLowestModes(const Eigen::MatrixXd& M, const Eigen::MatrixXd& K, int count,
                                              const Eigen::VectorXd* start) {
  const Eigen::Index n = M.rows();
  MMV_DEMAND(M.cols() == n && K.rows() == n && K.cols() == n && count > 0 && count < n);
  for (Eigen::Index i = 0; i < n; ++i)
    if (!(M(i, i) > 0)) return std::nullopt;  // the dense solver names the problem
  // Balanced as the dense solver is: unit mass diagonal.
  const Eigen::VectorXd d = M.diagonal().cwiseSqrt().cwiseInverse();
  const Eigen::MatrixXd Ms = d.asDiagonal() * M * d.asDiagonal();
  const Eigen::MatrixXd Ks = d.asDiagonal() * K * d.asDiagonal();
  DensePencil op(Ks, Ms);
  std::optional<ModalSolution> sol = lanczos(op, Ks.diagonal().cwiseAbs().maxCoeff(), count, start);
  if (sol) sol->shapes = d.asDiagonal() * sol->shapes;
  return sol;
}

std::optional<ModalSolution> solveLowestModes(const TreeOperator& tree, int count, const Eigen::VectorXd* start) {
  const int n = tree.size();
  MMV_DEMAND(count > 0 && count < n);
  const Eigen::VectorXd m = tree.diagonalM();
  if (!(m.minCoeff() > 0)) return std::nullopt;  // the dense solver names the problem
  TreeShiftInverted op(tree);
  return lanczos(op, tree.diagonalK().cwiseQuotient(m).cwiseAbs().maxCoeff(), count, start);
}

}  // namespace mmv
