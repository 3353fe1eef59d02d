#pragma once
/// Loop closures (closed trees) as constraints on the article's coordinates.
///
///   Phi_r(q) = e_r . (p_A(q) - p_B(q)) = 0   for every direction e_r a closure holds
///
/// (p_B is the ground anchor for a closure to the ground; m, world frame). The
/// Jacobian is G = dPhi/dq = e_r^T (J_A - J_B). A multiplier lambda_r is the force
/// component the closure applies to A along e_r (N); B receives the opposite. At a
/// preloaded equilibrium f(q) + G^T lambda = 0, and those forces add the stiffness
/// -d(G^T lambda)/dq (sim/statics/linearize.hpp; sim/model/point_force.hpp) to the modes, which live in the
/// null space of G.

#include <Eigen/Dense>
#include <vector>

#include "sim/model/point_force.hpp"
#include "sim/model/model.hpp"

namespace mmv {

/// Phi(q) in m, one row per held direction, closures in order.
Eigen::VectorXd calcClosureErrors(const Model& model, const SimTK::State& s);
/// G over the coordinates `cols` (m/rad for rotations).
Eigen::MatrixXd calcClosureJacobian(const Model& model, const SimTK::State& s, const std::vector<int>& cols);
/// The closure forces on the article for multipliers `lambda` (N), as point forces.
std::vector<PointForce> closureForces(const Model& model, const Eigen::VectorXd& lambda);

/// Checks, closure by closure in scene order, that each adds as many independent
/// directions of motion as it holds. Throws SceneError ("file:line:col: closures[i] ...
/// over-constrains the article ...") naming the first one that does not: a closure on
/// parts that cannot move, a duplicate, or a pin along an inextensible straight link
/// whose force would be indeterminate.
void checkClosureRank(const Model& model, const SimTK::State& s, const std::vector<int>& dofs);

/// Orthonormal basis of the null space of G (columns), by SVD with a relative rank
/// tolerance of 1e-10; the identity when G has no rows.
Eigen::MatrixXd nullSpace(const Eigen::MatrixXd& G, int n);

}  // namespace mmv
