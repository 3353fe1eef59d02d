#pragma once
/// The damping matrix a scene's `damping:` defines over the linearized degrees of
/// freedom (LinearizedModel::dofs), the one matrix both the linear models and the time
/// runs use:
///  - modal ratio zeta: C = M Phi diag(2 zeta omega_k) Phi^T M over every mode of the
///    held article (Phi^T M Phi = I, closures through Z: Phi = Z Y with
///    (Z^T K Z) Y = (Z^T M Z) Y Omega^2), so that each mode of the equilibrium gets
///    exactly zeta (rigid and unstable modes get none);
///  - Rayleigh: C = alpha M + beta K (K with gravity's geometric stiffness, as the
///    linear models use), zeta_k = alpha / (2 omega_k) + beta omega_k / 2.
/// Hinge dampers (hinge_beta) are per-coordinate dampers the builder puts in the model
/// itself and are not part of this matrix.
/// Units: N*m*s/rad on angle coordinates (N*s/m on translations).

#include <string>

#include <Eigen/Dense>

#include "sim/scene/scene.hpp"
#include "sim/statics/linearize.hpp"

namespace mmv {

/// One line describing the damping model, with its parameters and units
/// ("hinge dampers c = 0.002 s * k", "modal, 1 % of critical in every mode").
std::string describeDamping(const DampingSpec& d);

/// True when `d` is a damping model this matrix carries (modal ratio or Rayleigh).
bool isMatrixDamping(const DampingSpec& d);

/// C over lin.dofs (symmetric, positive semi-definite for a stable equilibrium).
/// Throws NumericalError if the modes of (K, M) cannot be computed (modal ratio).
Eigen::MatrixXd calcDampingMatrix(const LinearizedModel& lin, const DampingSpec& d);

}  // namespace mmv
