#include "sim/modes/modal.hpp"

#include <cmath>
#include <sstream>

#include "sim/core/errors.hpp"

namespace mmv {

double ModalSolution::frequencyHz(int i) const {
  if (isRigidBody(i)) return 0.0;
  const double w2 = omega2[i];
  return (w2 >= 0 ? std::sqrt(w2) : -std::sqrt(-w2)) / (2.0 * M_PI);
}

ModalSolution solveModes(const Eigen::MatrixXd& M, const Eigen::MatrixXd& K) {
  const Eigen::Index n = M.rows();
  if (M.cols() != n || K.rows() != n || K.cols() != n) throw std::invalid_argument("solveModes: M and K must be square and of one size");
  if (!M.allFinite() || !K.allFinite()) throw NumericalError("mass or stiffness matrix has non-finite entries");
  ModalSolution sol;
  if (n == 0) return sol;
  // Balance first: with D = diag(M)^(-1/2), solve (D K D) psi = w^2 (D M D) psi and
  // phi = D psi. The scaled mass matrix has a unit diagonal, which keeps the Cholesky
  // factor well conditioned when heavy torquers sit next to gram-scale rods.
  for (Eigen::Index i = 0; i < n; ++i)
    if (!(M(i, i) > 0)) {
      throw NumericalError("mass matrix is not positive definite (degree of freedom " + std::to_string(i) +
                           " has no inertia)");
    }
  const Eigen::VectorXd d = M.diagonal().cwiseSqrt().cwiseInverse();
  const Eigen::MatrixXd Ms = d.asDiagonal() * M * d.asDiagonal();
  const Eigen::MatrixXd Ks = d.asDiagonal() * K * d.asDiagonal();
  Eigen::LLT<Eigen::MatrixXd> llt(Ms);
  if (llt.info() != Eigen::Success) {
    throw NumericalError("mass matrix is not positive definite (a degree of freedom without inertia?)");
  }
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> es(Ks, Ms, Eigen::ComputeEigenvectors | Eigen::Ax_lBx);
  if (es.info() != Eigen::Success) throw NumericalError("generalized eigen solver did not converge");
  sol.omega2 = es.eigenvalues();
  sol.shapes = d.asDiagonal() * es.eigenvectors();
  sol.rigid_body_threshold = 1e-12 * sol.omega2.cwiseAbs().maxCoeff();
  // Fix the sign of each shape: largest component positive (reproducible output).
  for (Eigen::Index i = 0; i < n; ++i) {
    Eigen::Index imax;
    sol.shapes.col(i).cwiseAbs().maxCoeff(&imax);
    if (sol.shapes(imax, i) < 0) sol.shapes.col(i) *= -1.0;
  }
  for (Eigen::Index i = 0; i < n; ++i) {
    const Eigen::VectorXd kv = K * sol.shapes.col(i), mv = M * sol.shapes.col(i);
    const double denom = kv.norm() + std::abs(sol.omega2[i]) * mv.norm();
    const double r = denom > 0 ? (kv - sol.omega2[i] * mv).norm() / denom : 0.0;
    sol.max_residual = std::max(sol.max_residual, r);
  }
  const Eigen::MatrixXd ortho = sol.shapes.transpose() * M * sol.shapes - Eigen::MatrixXd::Identity(n, n);
  sol.orthogonality_error = ortho.cwiseAbs().maxCoeff();
  if (!sol.omega2.allFinite() || !sol.shapes.allFinite()) throw NumericalError("eigen solution has non-finite values");
  return sol;
}

ModalSolution solveModes(const Eigen::MatrixXd& M, const Eigen::MatrixXd& K, const Eigen::MatrixXd& Z) {
  if (Z.rows() != M.rows()) throw std::invalid_argument("solveModes: Z must have one row per coordinate");
  const Eigen::MatrixXd Mz = Z.transpose() * M * Z, Kz = Z.transpose() * K * Z;
  ModalSolution sol = solveModes(0.5 * (Mz + Mz.transpose()), 0.5 * (Kz + Kz.transpose()));
  sol.shapes = Z * sol.shapes;
  return sol;
}

}  // namespace mmv
