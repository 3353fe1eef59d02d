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
///  - closed form, for models whose only forces are gravity and pin springs
///    (Model::hasOnlyGravityAndPinSprings): for planar pins j, k with j inboard of or
///    equal to k,  K_jk = k_spring,k delta_jk + g . (S_k - M_k o_k),  where o_k is pin
///    k's axis, M_k the mass outboard of it and S_k that mass's first moment (all in
///    world); K_jk = 0 when neither pin is inboard of the other. Exact, O(n * depth).
///  - central differences of f (step 1e-6 rad, truncation error ~1e-10 relative) for
///    any force model, O(n^2) force evaluations.
/// The result is symmetrised; its asymmetry before that is reported, since a
/// conservative system has a symmetric K.

#include <Eigen/Dense>

#include "sim/model.hpp"

namespace mmv {

struct LinearizedModel {
  std::vector<int> dofs;        ///< coordinate index of each row/column.
  Eigen::MatrixXd M;            ///< kg*m^2 (angle coordinates).
  Eigen::MatrixXd K;            ///< N*m/rad, symmetric.
  Eigen::MatrixXd K_elastic;    ///< N*m/rad, diagonal spring stiffness.
  Eigen::MatrixXd K_geometric;  ///< K - K_elastic.
  double asymmetry = 0;         ///< ||K_raw - K_raw^T||_max / ||K_raw||_max.
};

/// Stiffness -df/dq over `dofs` at the state `s` (not symmetrised): the closed form
/// when the model allows it, finite differences otherwise.
Eigen::MatrixXd calcStiffness(const Model& model, const SimTK::State& s, const std::vector<int>& dofs);
/// Central differences of the applied forces, for any model.
Eigen::MatrixXd calcStiffnessByDifferences(const Model& model, const SimTK::State& s, const std::vector<int>& dofs);
/// Closed form for gravity + pin springs; requires Model::hasOnlyGravityAndPinSprings().
Eigen::MatrixXd calcStiffnessClosedForm(const Model& model, const SimTK::State& s, const std::vector<int>& dofs);

/// Mass matrix restricted to `dofs` at the state `s`.
Eigen::MatrixXd calcMass(const Model& model, const SimTK::State& s, const std::vector<int>& dofs);

LinearizedModel linearize(const Model& model, const SimTK::State& equilibrium);

}  // namespace mmv
