#pragma once
/// The mass matrix M and the tangent stiffness K of an open tree about a state, as
/// O(n) operators that are never formed (n degrees of freedom): products, and the
/// factorization K - sigma M = L D L^T in O(n) time and memory. What the modes of a fine
/// mesh need (1024 segments per link: 4096 DOF, whose dense M and K alone would take
/// 270 MB and whose Cholesky factor O(n^3) time).
///
/// Structure. Every degree of freedom j has a world-frame spatial axis S_j = (w; v_O)
/// (the velocity its unit rate gives the bodies it moves, v at the world origin), a
/// parent (the nearest degree of freedom inboard of it) and a spring k_j. Each body b
/// is moved by the degrees of freedom on its path to ground, so with per-body 6 x 6
/// matrices c_b
///     A_jk = k_j delta_jk + S_j^T C_k S_k   for j inboard of or equal to k,
///     C_k  = sum of c_b over the bodies outboard of or at k (its subtree),
/// and A_kj = A_jk. The mass matrix is of this form with c_b the body's spatial
/// inertia about the world origin (symmetric). So is the closed-form stiffness of
/// sim/statics/linearize.hpp (gravity and dead loads, for j inboard of k: a constant
/// force f at p contributes K_jk = S_j^T X S_k with X = [[(p.f) I - p f^T, [f x]],
/// [0, 0]], which is what a_j . (a_k x (p - o_k)) x f works out to), with the joints'
/// springs on the diagonal. Translations of a mobilizer count as inboard of its
/// rotations (they move the rotation axis), rotations in their q order (a gimbal's
/// later axes turn with its earlier ones).
///
/// The spatial hinges' rotation springs add the Hessian of their energy less diag(k)
/// among the three angles of one gimbal (sim/model/rotation_spring.hpp).
///
/// Factorization. Eliminating the mobilizers leaves first is the articulated-body
/// recursion with general 6 x 6 "inertias" and a block per mobilizer i (its m_i <= 3
/// degrees of freedom, axes S_i 6 x m_i): IA_i = c_i + sum over children
/// (IA_c - U_c D_c^-1 U_c^T), U_i = IA_i S_i, pivot block D_i = S_i^T IA_i S_i (taken from
/// its upper triangle, the inboard row first) + springs and their coupling. The pivot
/// blocks' eigenvalues have the inertia of K - sigma M (Sylvester), so they count the
/// eigenvalues below sigma (a Sturm check in O(n)).
///
/// Applies to open trees whose only forces are gravity, dead loads, the coordinates'
/// linear springs and the hinges' rotation springs (no closures), with at most three
/// coordinates on a mobilizer (the node blocks' size; a free body's six are not): appliesTo.
#include <Eigen/Dense>
#include <vector>

#include "sim/model/model.hpp"

namespace mmv {

using Matrix6d = Eigen::Matrix<double, 6, 6>;
using Vector6d = Eigen::Matrix<double, 6, 1>;
/// A mobilizer's axes (6 x m), a block over its m <= 3 degrees of freedom, a vector of them.
inline constexpr int kMaxNodeDofs = 3;  ///< a mobilizer's coordinates the node blocks hold.
using NodeAxes = Eigen::Matrix<double, 6, Eigen::Dynamic, 0, 6, kMaxNodeDofs>;
using NodeBlock = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxNodeDofs, kMaxNodeDofs>;
using NodeVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 3, 1>;

class TreeFactor;

/// An entry of a stiffness matrix over a list of degrees of freedom.
struct StiffnessEntry {
  int row = 0, column = 0;
  double value = 0;
};
/// The rotation springs' stiffness beyond diag(k) between the angles of each gimbal
/// (the Hessian of their energy less its unbent value; sim/model/rotation_spring.hpp) at
/// state `s`, over `dofs` (held angles left out, zero entries omitted).
std::vector<StiffnessEntry> rotationSpringCoupling(const Model& model, const SimTK::State& s, const std::vector<int>& dofs);

class TreeOperator {
 public:
  /// Whether the model's M and K have the structure above: no closures, closed-form
  /// forces (Model::hasClosedFormForces) and at most kMaxNodeDofs coordinates a mobilizer.
  static bool appliesTo(const Model& model);

  /// At state `s` over the coordinates `dofs` (held ones
  /// excluded; the model's getDofs()). Requires appliesTo(model).
  TreeOperator(const Model& model, const SimTK::State& s, const std::vector<int>& dofs);

  int size() const { return static_cast<int>(axis_.size()); }
  Eigen::VectorXd multiplyM(const Eigen::VectorXd& x) const;
  Eigen::VectorXd multiplyK(const Eigen::VectorXd& x) const;
  Eigen::MatrixXd multiplyM(const Eigen::MatrixXd& X) const;
  Eigen::MatrixXd multiplyK(const Eigen::MatrixXd& X) const;
  Eigen::VectorXd diagonalM() const;
  Eigen::VectorXd diagonalK() const;
  /// The springs' diagonal stiffness k_j (K's elastic part), N*m/rad or N/m.
  const Eigen::VectorXd& springs() const { return spring_; }
  /// M and K formed (O(n * depth) time, O(n^2) memory): tests and the dense fallback.
  Eigen::MatrixXd denseM() const;
  Eigen::MatrixXd denseK() const;
  /// K - sigma M = L D L^T.
  TreeFactor factor(double sigma) const;

 private:
  friend class TreeFactor;
  /// y = A x for A of the form above with per-dof matrices `own` (their subtree sums
  /// `composite`) and diagonal `diag`.
  Eigen::VectorXd apply(const std::vector<Matrix6d>& own, const std::vector<Matrix6d>& composite,
                        const Eigen::VectorXd* diag, const Eigen::VectorXd& x) const;
  Eigen::MatrixXd dense(const std::vector<Matrix6d>& composite, const Eigen::VectorXd* diag) const;
  /// spring_blocks_ from the springs and coupling_; node_of: each dof's node.
  void buildSpringBlocks(const std::vector<int>& node_of);

  /// A mobilizer's degrees of freedom, inboard first, and its parent mobilizer's index.
  struct Node {
    std::vector<int> dofs;
    int parent = -1;
  };
  std::vector<Node> nodes_;        ///< every parent before its children.
  std::vector<NodeBlock> spring_blocks_;  ///< per node: the springs and their coupling (K's part without sigma).
  std::vector<StiffnessEntry> coupling_;  ///< rotationSpringCoupling.
  std::vector<Vector6d> axis_;     ///< S_j.
  std::vector<int> parent_;        ///< index of the parent dof, -1 at ground.
  std::vector<int> order_;         ///< dof indices, every parent before its children.
  Eigen::VectorXd spring_;
  std::vector<Matrix6d> mass_, stiff_;                    ///< c_j: the bodies attached at j.
  std::vector<Matrix6d> mass_composite_, stiff_composite_;  ///< C_j.
};

/// The factorization K - sigma M = L D L^T of a TreeOperator (which must outlive it).
class TreeFactor {
 public:
  /// The eigenvalues of the pivot blocks D_i, at their mobilizer's degrees of freedom
  /// (for a pin, its pivot).
  const Eigen::VectorXd& pivots() const { return pivot_; }
  /// Whether every pivot is non-zero (the matrix is invertible).
  bool invertible() const { return invertible_; }
  int negativePivots() const;
  /// (K - sigma M)^-1 r. Requires invertible().
  Eigen::VectorXd solve(const Eigen::VectorXd& r) const;
  /// L^-1 r and L^-T w (unit block-triangular factors).
  Eigen::VectorXd forward(const Eigen::VectorXd& r) const;
  Eigen::VectorXd backward(const Eigen::VectorXd& w) const;
  /// With D = R R^T (R_i = V_i Lambda_i^1/2 from each block's eigen decomposition; every
  /// pivot positive): R^-1 z and R^-T y.
  Eigen::VectorXd halfInverse(const Eigen::VectorXd& z) const;
  Eigen::VectorXd halfInverseTransposed(const Eigen::VectorXd& y) const;

 private:
  friend class TreeOperator;
  explicit TreeFactor(const TreeOperator& op) : op_(&op) {}
  NodeVector gather(const Eigen::VectorXd& v, std::size_t node) const;
  void scatter(const NodeVector& s, std::size_t node, Eigen::VectorXd& v) const;
  const TreeOperator* op_;
  std::vector<NodeAxes> u_;         ///< U_i = IA_i S_i.
  std::vector<NodeAxes> g_;         ///< U_i D_i^-1 (both sweeps use it).
  std::vector<NodeBlock> inverse_;  ///< D_i^-1.
  std::vector<NodeBlock> vectors_;  ///< V_i: D_i = V_i Lambda_i V_i^T.
  std::vector<NodeVector> values_;  ///< Lambda_i.
  Eigen::VectorXd pivot_;
  bool invertible_ = true;
};

}  // namespace mmv
