#pragma once
/// Damping of the article's modes: the damping matrix a scene's `damping:` defines, and
/// each real mode's damping ratio under it.
///
/// Damping models (DampingSpec, sim/scene/scene.hpp):
///  - modal: C = M Phi diag(2 zeta omega) Phi^T M, every mode zeta;
///  - Rayleigh: C = alpha M + beta K, zeta_k = alpha / (2 omega_k) + beta omega_k / 2;
///  - the hinges' viscous dampers: c = hinge_beta * k on every bending hinge, the damping
///    the Simbody model carries in time runs. Under gravity's geometric stiffness this C
///    is not proportional: the modes couple through it, and each mode's ratio comes from
///    the damped eigenproblem
///        (lambda^2 M + lambda C + K) x = 0,   zeta = -Re(lambda) / |lambda|,
///    solved in the basis of the real modes (Phi^T M Phi = I):
///        (lambda^2 I + lambda Phi^T C Phi + diag(omega^2)) y = 0,
///    over every mode (exact) or, on large models, over the lowest ones computed (a
///    Galerkin projection whose error the tests bound against the full solution).
///    The damped mode belonging to real mode k is the one whose y is largest in k.
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "sim/model/model.hpp"
#include "sim/modes/modal.hpp"
#include "sim/scene/scene.hpp"
#include "sim/statics/damping_matrix.hpp"
#include "sim/statics/linearize.hpp"

namespace mmv {

/// The viscous damper of each coordinate in `dofs` (N*m*s/rad): hinge_beta * k on the
/// bending hinges, 0 on joints.
Eigen::VectorXd hingeDampers(const Model& model, const std::vector<int>& dofs, double hinge_beta_s);

/// The most real modes the damped eigenproblem is solved over (2x as many states, a dense
/// nonsymmetric eigen solution: under a second at 400 on this machine).
inline constexpr int kMaxDampingBasis = 400;

struct ModalDamping {
  /// Per mode asked for, lowest first: zeta (1: overdamped; 0 for rigid or unstable
  /// modes). Fewer than asked when the basis was capped at kMaxDampingBasis: then the
  /// lowest kMaxDampingBasis / 2 only.
  std::vector<double> ratio;
  std::vector<double> natural_hz;        ///< |lambda| / (2 pi) of the damped mode (the real mode's frequency when undamped;
                                         ///< an overdamped mode of modal or Rayleigh damping: its slower real root).
  int basis_modes = 0;                   ///< real modes the damped eigenproblem was solved over.
  bool exact = false;                    ///< basis_modes is every mode of the model.
};

/// The damping ratio of the first `count` modes of `modes` (shapes over lin.dofs,
/// mass-normalised) under `damping`: modal and Rayleigh damping in closed form (each
/// mode its own oscillator); hinge dampers solved over every mode `modes` holds, at most
/// kMaxDampingBasis (see above).
/// Throws NumericalError if the damped eigen solution fails.
ModalDamping modalDamping(const Model& model, const LinearizedModel& lin, const ModalSolution& modes,
                          const DampingSpec& damping, int count);

}  // namespace mmv
