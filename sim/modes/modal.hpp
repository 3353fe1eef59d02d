#pragma once
/// Undamped normal modes of a linearized model:
///
///     K phi = omega^2 M phi,   M = M^T > 0 (checked by Cholesky),  K = K^T,
///
/// solved as a symmetric-definite generalized eigenproblem (Cholesky of M, then every
/// eigenpair of the symmetric L^-1 K L^-T by sim/core/symmetric_eigen.hpp), or for the
/// lowest modes of a large model by shift-invert Lanczos.
/// Shapes are mass-normalised, phi^T M phi = 1. A negative omega^2 means the
/// equilibrium is unstable in that shape (e.g. an upright link past buckling); it is
/// reported as unstable, never as a NaN frequency.
///
/// Rigid-body (mechanism) modes come from the model's structure, never from a ratio to
/// the stiffest mode (which grows as N^4 with the mesh and would swallow real modes on
/// fine meshes): markRigidBodyModes counts the motions that strain no spring and on
/// which the remaining (geometric) stiffness vanishes, and flags that many modes with
/// the smallest |omega^2|. Without it no mode is rigid.
#include <Eigen/Dense>
#include <cmath>
#include <optional>
#include <vector>
#include "sim/core/mode_number.hpp"
#include "sim/statics/tree_operator.hpp"



namespace mmv {

struct ModalSolution {
  Eigen::VectorXd omega2;  ///< rad^2/s^2, ascending.
  Eigen::MatrixXd shapes;  ///< columns, mass-normalised, over LinearizedModel::dofs.
  double max_residual = 0;         ///< max_i ||K v_i - w_i^2 M v_i|| / (||K v_i|| + |w_i^2| ||M v_i||).
  double orthogonality_error = 0;  ///< ||V^T M V - I||_max.

  std::vector<double> residuals;   ///< per mode, as max_residual.
  std::vector<char> rigid;         ///< per mode: a rigid-body mode (markRigidBodyModes).

  /// Frequency in Hz of mode i: 0 for a rigid-body mode, or a negative number
  /// -sqrt(-omega2)/(2 pi) flagged by isStable(i) == false for an unstable shape.
  double frequencyHz(int i) const;
  bool isRigidBody(int i) const { return i < static_cast<int>(rigid.size()) && rigid[i]; }
  int rigidBodyCount() const;
  bool isStable(int i) const { return omega2[i] >= 0 || isRigidBody(i); }
};

/// count = 0: every mode, by the dense solver. count > 0: at least the `count` lowest
/// modes (omega^2 ascending, unstable ones first); from kPartialModesMinDofs DOF on
/// (and count <= n / 3) only those, by shift-invert Lanczos (solveLowestModes), which
/// falls back to the dense solver whenever it cannot prove its answer complete.
/// Residuals and orthogonality are computed for the modes returned; `mass_shapes`, if
/// given, receives M * shapes as those checks formed it (the modal damping matrix's
/// factor, not formed twice).
/// Throws NumericalError (sim/statics/statics.hpp) if M is not positive definite or the
/// eigen solver fails.
ModalSolution solveModes(const Eigen::MatrixXd& M, const Eigen::MatrixXd& K, int count = 0,
                         Eigen::MatrixXd* mass_shapes = nullptr);

/// Below this many DOF the dense solver is cheap enough (a few ms) to return every mode.
inline constexpr int kPartialModesMinDofs = 96;

/// The `count` lowest modes (0 < count < n) by shift-invert Lanczos in M's inner
/// product (Spectra's SymGEigsShiftSolver): K - sigma M is factored once by Cholesky
/// with a shift sigma below every eigenvalue (the factor proves that, so the modes
/// nearest sigma are the lowest ones, unstable and rigid-body modes included), then
/// each Lanczos step costs two triangular solves and a product with M. A Sturm-sequence
/// check (the inertia of K - tau M, tau between the last mode returned and the next)
/// proves that none was missed, e.g. one of a repeated pair. Shapes are mass-normalised,
/// unsigned and unchecked (solveModes does that). nullopt when the shift, the iteration
/// or the check fails: the caller then solves densely. `start`: Lanczos' first vector
/// (in the balanced, factored coordinates; default Spectra's random one), for tests
/// that make it miss a mode on purpose.
std::optional<ModalSolution> solveLowestModes(const Eigen::MatrixXd& M, const Eigen::MatrixXd& K, int count,
                                              const Eigen::VectorXd* start = nullptr);

/// The same from an open tree's O(n) operators (sim/statics/tree_operator.hpp): the
/// lowest `count` modes by shift-invert Lanczos on the tree's O(n) factorization, with
/// the Sturm count from its pivots; O(n) memory. Small models, count = 0 and unproven
/// partial solutions go to the dense solver on the formed matrices.
ModalSolution solveModes(const TreeOperator& op, int count);
std::optional<ModalSolution> solveLowestModes(const TreeOperator& op, int count, const Eigen::VectorXd* start = nullptr);

/// Modes constrained to the columns of Z (a closed loop's admissible motions):
/// (Z^T K Z) psi = omega^2 (Z^T M Z) psi, phi = Z psi. Residuals and orthogonality are
/// those of the reduced problem; shapes stay mass-normalised (phi^T M phi = 1).
/// An identity Z (an open tree) costs nothing.
ModalSolution solveModes(const Eigen::MatrixXd& M, const Eigen::MatrixXd& K, const Eigen::MatrixXd& Z, int count = 0);

/// The admissible motions q = Z eta that leave every coordinate with `strained[i]`
/// unchanged (columns over q, orthonormal): the candidates for rigid-body modes.
Eigen::MatrixXd unstrainedMotions(const Eigen::MatrixXd& Z, const std::vector<bool>& strained);
/// The same on an open tree (Z the identity, not formed): the coordinates with
/// `strained[i]` false, one column each.
Eigen::MatrixXd unstrainedCoordinates(const std::vector<bool>& strained);

/// Flags the rigid-body modes of `sol` (shapes over q): r = the number of independent
/// motions in span(U) (U from unstrainedMotions) on which K vanishes, measured by the
/// eigenvalues of (U^T K U, U^T M U) against 1e-8 of `omega2_scale` (rad^2/s^2, a
/// mesh-independent scale of the geometric stiffness such as |g| / L) or of the largest
/// such eigenvalue; then the r modes with the smallest |omega^2| are rigid.
void markRigidBodyModes(ModalSolution& sol, const Eigen::MatrixXd& M, const Eigen::MatrixXd& K, const Eigen::MatrixXd& U,
                        double omega2_scale);
/// The same from Ku = U^T K U and Mu = U^T M U.
void markRigidBodyModesOn(ModalSolution& sol, const Eigen::MatrixXd& Ku, const Eigen::MatrixXd& Mu, double omega2_scale);

}  // namespace mmv
