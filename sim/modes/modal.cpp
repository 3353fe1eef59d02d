#include "sim/modes/modal.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>

#include <tbb/parallel_invoke.h>

#include "sim/core/errors.hpp"
#include "sim/core/symmetric_eigen.hpp"

namespace mmv {

double ModalSolution::frequencyHz(int i) const {
  if (isRigidBody(i)) return 0.0;
  const double w2 = omega2[i];
  return (w2 >= 0 ? std::sqrt(w2) : -std::sqrt(-w2)) / (2.0 * M_PI);
}

namespace {

/// Keeps the shapes after the first k (refined) M-orthogonal to them and mass-normalised:
/// r <- r - Xk a with a = (M Xk)^T r, products with the k refined columns, then each
/// column's M-norm from one product M R (a product with M per column cost more than the
/// refinement).
void keepRestOrthogonal(const Eigen::MatrixXd& M, ModalSolution& sol, Eigen::Index k) {
  const Eigen::MatrixXd Xk = sol.shapes.leftCols(k);
  auto rest = sol.shapes.rightCols(sol.shapes.cols() - k);
  const Eigen::MatrixXd a = (M * Xk).transpose() * rest;
  rest.noalias() -= Xk * a;
  const Eigen::MatrixXd MR = M * rest;
  for (Eigen::Index j = 0; j < rest.cols(); ++j) rest.col(j) /= std::sqrt(rest.col(j).dot(MR.col(j)));
}

/// The dense solver's eigenvalues carry an absolute error of about eps * max|omega^2|:
/// on a fine mesh (omega^2 spanning 1e8 and more) that is a visible relative error in
/// the lowest modes, the ones users read (a 0.6457 Hz pendulum mode printed as 0.6462 Hz
/// at 512 segments). When that error could exceed 1e-9 of a low mode, the lowest modes
/// are refined by two steps of shifted subspace iteration, X <- (K - s M)^-1 M X, each
/// followed by a Rayleigh-Ritz solution on span(X): the eigenvalues then come from
/// Rayleigh quotients, accurate to round-off relative to the mode itself. The shift s
/// lies below every eigenvalue, so K - s M is positive definite (unstable and rigid
/// modes included). A model of 36 DOF or fewer takes its lowest third from shift-invert
/// Lanczos instead (a subspace of every mode would change nothing).
void refineLowestModes(const Eigen::MatrixXd& M, const Eigen::MatrixXd& K, ModalSolution& sol) {
  const Eigen::Index n = sol.omega2.size();
  const double big = sol.omega2.cwiseAbs().maxCoeff();
  Eigen::Index k = std::min<Eigen::Index>(n, 24);
  const Eigen::Index p = std::min<Eigen::Index>(n, k + 12);
  double low = 0;  // the smallest |omega^2| worth resolving among the first k (rigid ~0 excluded)
  for (Eigen::Index i = 0; i < k; ++i)
    if (std::abs(sol.omega2[i]) > 1e-12 * big) low = low > 0 ? std::min(low, std::abs(sol.omega2[i])) : std::abs(sol.omega2[i]);
  if (low == 0 || 2.2e-16 * big <= 1e-9 * low) return;
  if (p == n) {
    // A small model (36 DOF or fewer): a subspace of every mode would change nothing, and
    // Rayleigh-Ritz on it keeps the dense error. Its lowest third by shift-invert Lanczos
    // instead (solveLowestModes, accurate relative to each mode): the two-link demo at 16
    // segments (33 DOF, a free elbow beside stiff hinges) had its first mode 4e-9 off.
    k = n / 3;
    const std::optional<ModalSolution> lanczos = k > 0 ? solveLowestModes(M, K, static_cast<int>(k)) : std::nullopt;
    if (!lanczos) return;  // keep the dense solution
    sol.omega2.head(k) = lanczos->omega2.head(k);
    sol.shapes.leftCols(k) = lanczos->shapes.leftCols(k);
    keepRestOrthogonal(M, sol, k);
    return;
  }
  const double shift = sol.omega2[0] - 0.5 * (std::abs(sol.omega2[0]) + std::abs(sol.omega2[k - 1])) - 1e-6 * low;
  const Eigen::LDLT<Eigen::MatrixXd> A(K - shift * M);
  if (A.info() != Eigen::Success || !(A.vectorD().minCoeff() > 0)) return;  // keep the dense solution
  Eigen::MatrixXd X = sol.shapes.leftCols(p);
  Eigen::VectorXd lam;
  for (int it = 0; it < 2; ++it) {
    const Eigen::MatrixXd Y = A.solve(M * X);
    const Eigen::MatrixXd Kr = Y.transpose() * K * Y, Mr = Y.transpose() * M * Y;
    Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> rr(0.5 * (Kr + Kr.transpose()), 0.5 * (Mr + Mr.transpose()),
                                                                 Eigen::ComputeEigenvectors | Eigen::Ax_lBx);
    if (rr.info() != Eigen::Success) return;
    lam = rr.eigenvalues();
    X = Y * rr.eigenvectors();  // M-orthonormal
  }
  sol.omega2.head(k) = lam.head(k);
  sol.shapes.leftCols(k) = X.leftCols(k);
  keepRestOrthogonal(M, sol, k);
}

}  // namespace

namespace {

/// All modes by the dense solver, balanced first: with D = diag(M)^(-1/2), solve
/// (D K D) psi = w^2 (D M D) psi and phi = D psi. The scaled mass matrix has a unit
/// diagonal, which keeps the Cholesky factor well conditioned when heavy torquers sit
/// next to gram-scale rods. With D M D = L L^T the problem is the symmetric
/// L^-1 (D K D) L^-T y = w^2 y, psi = L^-T y (as Eigen's generalized solver forms it),
/// solved by symmetricEigen (MRRR on the tridiagonal form).
ModalSolution solveAllModes(const Eigen::MatrixXd& M, const Eigen::MatrixXd& K) {
  const Eigen::Index n = M.rows();
  const Eigen::VectorXd d = M.diagonal().cwiseSqrt().cwiseInverse();
  const Eigen::MatrixXd Ms = d.asDiagonal() * M * d.asDiagonal();
  const Eigen::MatrixXd Ks = d.asDiagonal() * K * d.asDiagonal();
  Eigen::MatrixXd S = Ks.selfadjointView<Eigen::Lower>();  // exactly symmetric (D K D is not, by an ulp)
  const Eigen::LLT<Eigen::MatrixXd> llt(Ms);
  if (llt.info() != Eigen::Success) {
    throw NumericalError("mass matrix is not positive definite (a degree of freedom without inertia?)");
  }
  llt.matrixL().solveInPlace<Eigen::OnTheLeft>(S);
  llt.matrixU().solveInPlace<Eigen::OnTheRight>(S);
  SymmetricEigen es = symmetricEigen(S);
  llt.matrixU().solveInPlace(es.vectors);
  ModalSolution sol;
  sol.omega2 = std::move(es.values);
  sol.shapes = d.asDiagonal() * es.vectors;
  MMV_DEMAND(sol.shapes.cols() == n);
  refineLowestModes(M, K, sol);
  return sol;
}

/// Signs: the largest component positive, for reproducible output.
void fixSigns(ModalSolution& sol) {
  for (Eigen::Index i = 0; i < sol.omega2.size(); ++i) {
    Eigen::Index imax;
    sol.shapes.col(i).cwiseAbs().maxCoeff(&imax);
    if (sol.shapes(imax, i) < 0) sol.shapes.col(i) *= -1.0;
  }
}

/// The checks of the modes returned, from KV = K V and MV = M V: residuals, and
/// M-orthogonality from V^T (M V) (its lower triangle: the matrix is symmetric).
void checkModes(const Eigen::MatrixXd& KV, const Eigen::MatrixXd& MV, ModalSolution& sol) {
  const Eigen::MatrixXd& V = sol.shapes;
  const Eigen::Index k = sol.omega2.size();
  for (Eigen::Index i = 0; i < k; ++i) {
    const double denom = KV.col(i).norm() + std::abs(sol.omega2[i]) * MV.col(i).norm();
    const double r = denom > 0 ? (KV.col(i) - sol.omega2[i] * MV.col(i)).norm() / denom : 0.0;
    sol.residuals.push_back(r);
    sol.max_residual = std::max(sol.max_residual, r);
  }
  Eigen::MatrixXd ortho = Eigen::MatrixXd::Zero(k, k);
  ortho.triangularView<Eigen::Lower>() = V.transpose() * MV;
  ortho.diagonal().array() -= 1.0;
  sol.orthogonality_error = k ? ortho.cwiseAbs().maxCoeff() : 0.0;
  if (!sol.omega2.allFinite() || !sol.shapes.allFinite()) throw NumericalError("eigen solution has non-finite values");
}

/// The same from dense M and K; MV is kept. The two products on two cores when there
/// are many modes (all 256 of a 64-segment article: 2 x 34 Mflop; below about 200,
/// waking the other core costs more than it saves).
void checkModes(const Eigen::MatrixXd& M, const Eigen::MatrixXd& K, ModalSolution& sol, Eigen::MatrixXd& MV) {
  const Eigen::MatrixXd& V = sol.shapes;
  Eigen::MatrixXd KV;
  if (V.cols() >= 192) {
    tbb::parallel_invoke([&] { KV.noalias() = K * V; }, [&] { MV.noalias() = M * V; });
  } else {
    KV.noalias() = K * V;
    MV.noalias() = M * V;
  }
  checkModes(KV, MV, sol);
}

}  // namespace

ModalSolution solveModes(const Eigen::MatrixXd& M, const Eigen::MatrixXd& K, int count, Eigen::MatrixXd* mass_shapes) {
  const Eigen::Index n = M.rows();
  MMV_DEMAND(M.cols() == n && K.rows() == n && K.cols() == n && count >= 0);
  if (!M.allFinite() || !K.allFinite()) throw NumericalError("mass or stiffness matrix has non-finite entries");
  if (n == 0) return {};
  for (Eigen::Index i = 0; i < n; ++i)
    if (!(M(i, i) > 0)) {
      throw NumericalError("mass matrix is not positive definite (degree of freedom " + std::to_string(i) +
                           " has no inertia)");
    }
  std::optional<ModalSolution> sol;
  if (count > 0 && n >= kPartialModesMinDofs && 3 * count <= n) sol = solveLowestModes(M, K, count);
  if (!sol) sol = solveAllModes(M, K);
  fixSigns(*sol);
  Eigen::MatrixXd MV;
  checkModes(M, K, *sol, MV);
  if (mass_shapes) *mass_shapes = std::move(MV);
  return std::move(*sol);
}

ModalSolution solveModes(const TreeOperator& op, int count) {
  const int n = op.size();
  MMV_DEMAND(count >= 0);
  std::optional<ModalSolution> sol;
  if (count > 0 && n >= kPartialModesMinDofs && 3 * count <= n) sol = solveLowestModes(op, count);
  if (!sol) return solveModes(op.denseM(), op.denseK(), count);  // small, or unproven: the dense solver
  fixSigns(*sol);
  checkModes(op.multiplyK(sol->shapes), op.multiplyM(sol->shapes), *sol);
  return std::move(*sol);
}

ModalSolution solveModes(const Eigen::MatrixXd& M, const Eigen::MatrixXd& K, const Eigen::MatrixXd& Z, int count) {
  MMV_DEMAND(Z.rows() == M.rows());
  if (Z.cols() == Z.rows() && Z.isIdentity(0.0)) return solveModes(M, K, count);  // an open tree: no products
  const Eigen::MatrixXd Mz = Z.transpose() * M * Z, Kz = Z.transpose() * K * Z;
  ModalSolution sol = solveModes(0.5 * (Mz + Mz.transpose()), 0.5 * (Kz + Kz.transpose()), count);
  sol.shapes = Z * sol.shapes;
  return sol;
}

int ModalSolution::rigidBodyCount() const { return static_cast<int>(std::count(rigid.begin(), rigid.end(), 1)); }

Eigen::MatrixXd unstrainedCoordinates(const std::vector<bool>& strained) {
  const Eigen::Index n = static_cast<Eigen::Index>(strained.size());
  Eigen::MatrixXd U = Eigen::MatrixXd::Zero(n, n - std::count(strained.begin(), strained.end(), true));
  Eigen::Index c = 0;
  for (Eigen::Index i = 0; i < n; ++i)
    if (!strained[i]) U(i, c++) = 1.0;
  return U;
}

Eigen::MatrixXd unstrainedMotions(const Eigen::MatrixXd& Z, const std::vector<bool>& strained) {
  std::vector<Eigen::Index> rows;
  for (std::size_t i = 0; i < strained.size(); ++i)
    if (strained[i]) rows.push_back(static_cast<Eigen::Index>(i));
  const Eigen::Index nz = Z.cols();
  if (rows.empty()) return Z;
  if (Z.cols() == Z.rows() && Z.isIdentity(0.0)) return unstrainedCoordinates(strained);  // an open tree
  Eigen::MatrixXd H(rows.size(), nz);
  for (std::size_t k = 0; k < rows.size(); ++k) H.row(k) = Z.row(rows[k]);
  // Null space of H by a complete orthogonal decomposition of H^T's column space.
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(H, Eigen::ComputeFullV);
  const Eigen::VectorXd sv = svd.singularValues();
  const double tol = 1e-10 * (sv.size() ? std::max(sv[0], 1.0) : 1.0);
  Eigen::Index rank = 0;
  while (rank < sv.size() && sv[rank] > tol) ++rank;
  return Z * svd.matrixV().rightCols(nz - rank);
}

void markRigidBodyModes(ModalSolution& sol, const Eigen::MatrixXd& M, const Eigen::MatrixXd& K, const Eigen::MatrixXd& U,
                        double omega2_scale) {
  if (U.cols() == 0 || sol.omega2.size() == 0) {
    sol.rigid.assign(sol.omega2.size(), 0);
    return;
  }
  markRigidBodyModesOn(sol, U.transpose() * K * U, U.transpose() * M * U, omega2_scale);
}

void markRigidBodyModesOn(ModalSolution& sol, const Eigen::MatrixXd& Ku, const Eigen::MatrixXd& Mu, double omega2_scale) {
  const Eigen::Index n = sol.omega2.size();
  sol.rigid.assign(n, 0);
  if (Ku.cols() == 0 || n == 0) return;
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> es(0.5 * (Ku + Ku.transpose()), 0.5 * (Mu + Mu.transpose()),
                                                                Eigen::EigenvaluesOnly | Eigen::Ax_lBx);
  if (es.info() != Eigen::Success) throw NumericalError("rigid-body mode count: eigen solution failed");
  const Eigen::VectorXd lam = es.eigenvalues();
  const double tol = 1e-8 * std::max(omega2_scale, lam.cwiseAbs().maxCoeff()) + 1e-14;
  int r = 0;
  for (Eigen::Index i = 0; i < lam.size(); ++i) r += std::abs(lam[i]) <= tol;
  std::vector<Eigen::Index> order(n);
  for (Eigen::Index i = 0; i < n; ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(),
                   [&](Eigen::Index a, Eigen::Index b) { return std::abs(sol.omega2[a]) < std::abs(sol.omega2[b]); });
  for (int k = 0; k < r && k < n; ++k) sol.rigid[order[k]] = 1;
}

}  // namespace mmv
