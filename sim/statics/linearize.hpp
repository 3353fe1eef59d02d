#pragma once
/// Linearization of the held article about a static equilibrium q*:
///
///     M dq'' + K dq = 0,   M = M(q*) (Simbody's mass matrix),  K = -df/dq (q*)
///
/// over the degrees of freedom (held joints removed). f(q) are the applied generalized
/// forces at zero speed (gravity + springs), so K = K_elastic + K_geometric where
/// K_elastic is the springs' diagonal stiffness and K_geometric the gravity stiffness
/// at the deflected state (positive when gravity stabilises, e.g. a hanging link).
/// K has two independent evaluations:
///  - closed form, for models whose only forces are gravity, dead point loads and
///    springs (Model::hasClosedFormForces): a constant world force F at a
///    point p has the stiffness  K_jk = F . (p - o_k)  for rotations j, k that both move
///    p with j inboard of or equal to k (o_k: k's axis), and 0 for translations. Summed
///    over gravity (F = m g at each mass centre) and loads, per coordinate k:
///        K_jk = k_spring,k delta_jk + G_k,  G_k = sum_{F outboard of k} F . (p - o_k).
///    Exact, O(n * depth). Constraint forces at a preloaded closed loop enter the same
///    way (extra point forces, sim/statics/closures.hpp). In the spatial model (axes a_k
///    other than z) the same derivation gives, with d^2 p / dq_j dq_k = a_j x (a_k x (p - o_k)),
///        K_jk = (a_j . a_k) G_k - a_j . V_k,  V_k = sum_{F outboard of k} (F . a_k) (p - o_k),
///    where a gimbal's later rotations count as outboard of its earlier ones.
///  - central differences of f (step 1e-6 rad, truncation error ~1e-10 relative) for
///    any force model, O(n^2) force evaluations.
/// The result is symmetrised; its asymmetry before that is reported, since a
/// conservative system has a symmetric K.

#include <Eigen/Dense>
#include <memory>

#include "sim/model/model.hpp"
#include "sim/model/point_force.hpp"
#include "sim/statics/tree_operator.hpp"

namespace mmv {

struct LinearizedModel {
  std::vector<int> dofs;        ///< coordinate index of each row/column.
  Eigen::MatrixXd M;            ///< kg*m^2 (angle coordinates).
  Eigen::MatrixXd K;            ///< N*m/rad, symmetric, closure preload included.
  Eigen::MatrixXd K_elastic;    ///< N*m/rad, diagonal spring stiffness.
  Eigen::MatrixXd K_geometric;  ///< K - K_elastic: gravity, loads and closure forces.
  Eigen::MatrixXd G;            ///< closure Jacobian (rows x dofs), empty for an open tree.
  Eigen::MatrixXd Z;            ///< orthonormal null-space basis of G (identity when open).
  double asymmetry = 0;         ///< ||K_raw - K_raw^T||_max / ||K_raw||_max.
  /// Set by linearizeOperators on a large open tree: M and K as O(n) operators
  /// (sim/statics/tree_operator.hpp). The matrices above are then empty (0 x 0): read
  /// M and K through massTimes, stiffnessTimes and springDiagonal (or fill them with
  /// addDenseMatrices).
  std::shared_ptr<const TreeOperator> tree;
};

/// The dense matrices (M, K, its parts, G and Z) of a model linearizeOperators kept as
/// operators, from the operators (O(n^2)); the operators stay. Nothing if it has them.
void addDenseMatrices(LinearizedModel& lin);

/// M V, K V and K's elastic (spring) diagonal, whichever form `lin` holds.
Eigen::MatrixXd massTimes(const LinearizedModel& lin, const Eigen::MatrixXd& V);
Eigen::MatrixXd stiffnessTimes(const LinearizedModel& lin, const Eigen::MatrixXd& V);
Eigen::VectorXd springDiagonal(const LinearizedModel& lin);

/// From this many DOF on, linearizeOperators keeps an open tree's M and K as operators.
inline constexpr int kTreeOperatorMinDofs = 96;

/// Stiffness -df/dq over `dofs` at the state `s` (not symmetrised): the closed form
/// when the model allows it, finite differences otherwise.
Eigen::MatrixXd calcStiffness(const Model& model, const SimTK::State& s, const std::vector<int>& dofs);
/// Central differences of the applied forces, for any model.
Eigen::MatrixXd calcStiffnessByDifferences(const Model& model, const SimTK::State& s, const std::vector<int>& dofs);
/// Closed form for gravity + loads + springs (+ `extra` point forces); requires
/// Model::hasClosedFormForces().
Eigen::MatrixXd calcStiffnessClosedForm(const Model& model, const SimTK::State& s, const std::vector<int>& dofs,
                                        const std::vector<PointForce>& extra = {});
/// The stiffness -d(J^T F)/dq of point forces alone (no springs, no gravity), over `dofs`.
Eigen::MatrixXd calcPointForceStiffness(const Model& model, const SimTK::State& s, const std::vector<int>& dofs,
                                        const std::vector<PointForce>& forces);

/// Mass matrix restricted to `dofs` at the state `s`.
Eigen::MatrixXd calcMass(const Model& model, const SimTK::State& s, const std::vector<int>& dofs);

/// `closure_multipliers`: the closure forces at the equilibrium (EquilibriumResult),
/// empty for an open tree.
LinearizedModel linearize(const Model& model, const SimTK::State& equilibrium,
                          const Eigen::VectorXd& closure_multipliers = Eigen::VectorXd());

/// linearize(), except that an open tree (TreeOperator::appliesTo) of at least
/// kTreeOperatorMinDofs DOF gets the operators alone (`tree`), in O(n) time and memory:
/// for callers that read M and K only through massTimes, stiffnessTimes and
/// springDiagonal (the modes of fine meshes).
LinearizedModel linearizeOperators(const Model& model, const SimTK::State& equilibrium,
                                   const Eigen::VectorXd& closure_multipliers = Eigen::VectorXd());

}  // namespace mmv
