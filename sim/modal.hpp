#pragma once
/// Undamped normal modes of a linearized model:
///
///     K phi = omega^2 M phi,   M = M^T > 0 (checked by Cholesky),  K = K^T,
///
/// solved as a symmetric-definite generalized eigenproblem (Eigen's
/// GeneralizedSelfAdjointEigenSolver: Cholesky of M, then a symmetric QR iteration).
/// Shapes are mass-normalised, phi^T M phi = 1. A negative omega^2 means the
/// equilibrium is unstable in that shape (e.g. an upright link past buckling); it is
/// reported as unstable, never as a NaN frequency.

#include <Eigen/Dense>
#include <vector>

#include "sim/linearize.hpp"

namespace mmv {

struct ModalSolution {
  Eigen::VectorXd omega2;  ///< rad^2/s^2, ascending.
  Eigen::MatrixXd shapes;  ///< columns, mass-normalised, over LinearizedModel::dofs.
  double max_residual = 0;         ///< max_i ||K v_i - w_i^2 M v_i|| / (||K v_i|| + |w_i^2| ||M v_i||).
  double orthogonality_error = 0;  ///< ||V^T M V - I||_max.

  /// Frequency in Hz of mode i, or a negative number -sqrt(-omega2)/(2 pi) flagged by
  /// isStable(i) == false for an unstable shape.
  double frequencyHz(int i) const;
  bool isStable(int i) const { return omega2[i] >= 0; }
};

/// Throws NumericalError (sim/statics.hpp) if M is not positive definite or the
/// eigen solver fails.
ModalSolution solveModes(const Eigen::MatrixXd& M, const Eigen::MatrixXd& K);

}  // namespace mmv
