#pragma once
/// Undamped normal modes of a linearized model:
///
///     K phi = omega^2 M phi,   M = M^T > 0 (checked by Cholesky),  K = K^T,
///
/// solved as a symmetric-definite generalized eigenproblem (Eigen's
/// GeneralizedSelfAdjointEigenSolver: Cholesky of M, then a symmetric QR iteration).
/// Shapes are mass-normalised, phi^T M phi = 1. A mode with |omega^2| <= 1e-12 of the
/// largest |omega^2| is a rigid-body (mechanism) mode: zero frequency up to round-off,
/// e.g. a free joint with no gravity. A negative omega^2 beyond that means the
/// equilibrium is unstable in that shape (e.g. an upright link past buckling); it is
/// reported as unstable, never as a NaN frequency.

#include <Eigen/Dense>
#include <cmath>
#include <vector>



namespace mmv {

struct ModalSolution {
  Eigen::VectorXd omega2;  ///< rad^2/s^2, ascending.
  Eigen::MatrixXd shapes;  ///< columns, mass-normalised, over LinearizedModel::dofs.
  double max_residual = 0;         ///< max_i ||K v_i - w_i^2 M v_i|| / (||K v_i|| + |w_i^2| ||M v_i||).
  double orthogonality_error = 0;  ///< ||V^T M V - I||_max.

  double rigid_body_threshold = 0;  ///< rad^2/s^2, 1e-12 * max |omega^2|.

  /// Frequency in Hz of mode i: 0 for a rigid-body mode, or a negative number
  /// -sqrt(-omega2)/(2 pi) flagged by isStable(i) == false for an unstable shape.
  double frequencyHz(int i) const;
  bool isRigidBody(int i) const { return std::abs(omega2[i]) <= rigid_body_threshold; }
  bool isStable(int i) const { return omega2[i] >= 0 || isRigidBody(i); }
};

/// Throws NumericalError (sim/statics/statics.hpp) if M is not positive definite or the
/// eigen solver fails.
ModalSolution solveModes(const Eigen::MatrixXd& M, const Eigen::MatrixXd& K);

/// Modes constrained to the columns of Z (a closed loop's admissible motions):
/// (Z^T K Z) psi = omega^2 (Z^T M Z) psi, phi = Z psi. Residuals and orthogonality are
/// those of the reduced problem; shapes stay mass-normalised (phi^T M phi = 1).
ModalSolution solveModes(const Eigen::MatrixXd& M, const Eigen::MatrixXd& K, const Eigen::MatrixXd& Z);

}  // namespace mmv
