#pragma once
// The modes of a first-order model's state matrix E^-1 A with their left eigenvectors,
// for the modal reduction (reduction.cpp): every mode by Eigen's dense solver, or only
// the lowest ones by shift-invert Arnoldi (Spectra) when the model is the first-order
// form of a second-order one (secondOrderModel) with symmetric M, C and K, which is
// how the article's models are built. The partial solution costs O(n^2) per Krylov step
// after one factorization of K, where the dense one costs O((2n)^3).
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "sim/linear/state_space.hpp"

namespace mmv::detail {

/// One mode of the state matrix: a real eigenvalue or a complex pair (the member with Im > 0).
struct ModeRef {
  int index;  ///< column of StateEigen::V, row of StateEigen::W
  bool pair;
  double magnitude;
  Eigen::MatrixXd residue;  ///< |C_o v| |w B_i| / |lambda| per output-input pair.
};

struct StateEigen {
  Eigen::VectorXcd lambda;
  Eigen::MatrixXcd V, W;      ///< right (columns), left (rows), W V = I over the modes computed.
  std::vector<ModeRef> modes;  ///< one per real root or complex pair.
  Eigen::MatrixXd pair_max;    ///< the largest modal residue of each output-input pair.
  Eigen::MatrixXd Bt;          ///< E^-1 B.
  std::function<Eigen::MatrixXd(const Eigen::MatrixXd&)> times_state_matrix;  ///< X -> E^-1 A X.
  /// A^-1 B (the static response), or nullopt when A is singular.
  std::function<std::optional<Eigen::MatrixXd>()> static_solution;
  bool every_mode = true;  ///< false: only the lowest modes were computed.
};

/// Every mode (Eigen's real Schur form and the inverse of the eigenvector matrix).
/// Throws NumericalError when the eigen solution fails.
StateEigen allStateModes(const StateSpace& full);

/// The modes of smallest magnitude, enough to hold the lowest `pairs` complex pairs and
/// every real root no larger than the last of them, computed by shift-invert Arnoldi on
/// (E^-1 A)^-1 and checked: residuals of the quadratic eigenproblem, biorthogonality,
/// and a second Arnoldi run on the deflated operator that must find no mode below the
/// ones kept (a repeated eigenvalue, which one Krylov space holds only once, is caught
/// there). nullopt when the model is not of second-order form with symmetric matrices,
/// K is singular, or any check fails (`declined` then says which): the caller then uses
/// allStateModes. `start`: the first Arnoldi run's start vector (default Spectra's
/// random one), for tests.
std::optional<StateEigen> lowestStateModes(const StateSpace& full, int pairs, std::string* declined = nullptr,
                                           const Eigen::VectorXd* start = nullptr);

/// The modes of smallest magnitude as lowestStateModes chooses them (or every mode when
/// `pairs` is 0), in closed form from the model's proportional modes (ReductionOptions::
/// proportional): no eigen solution. nullopt (`declined` says why) when the model is not
/// of second-order form with symmetric matrices, a mode is rigid, unstable or critically
/// damped (a defective eigenvalue), or the modes do not solve its M, C and K to 1e-9.
std::optional<StateEigen> proportionalStateModes(const StateSpace& full, std::shared_ptr<const ProportionalModes> modes,
                                                 int pairs, std::string* declined = nullptr);

/// Eigenvectors scaled to a canonical phase and size (a fixed real weighting of their
/// components is 1), so every solver gives the same reduced-model basis; returns what
/// each column was divided by.
Eigen::VectorXcd normalizeEigenvectors(Eigen::MatrixXcd& V);

/// The modes' residues and each pair's largest (fills modes and pair_max).
void collectModes(const StateSpace& full, StateEigen& sm, const std::vector<int>& indices);

}  // namespace mmv::detail
