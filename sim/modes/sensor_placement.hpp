#pragma once
/// Sensor placement: which candidate sensors tell the target modes apart best.
///
/// Each candidate measures one direction at one place; its row of Phi (m x k) is the
/// target modes' translations along that direction there (mass-normalised shapes).
/// Candidates are grouped in blocks that are kept or removed together: a uniaxial
/// sensor is a block of one row, a triaxial block is its axes at one station.
///
///  - Effective Independence (Kammer 1991, "Sensor placement for on-orbit modal
///    identification and correlation of large space structures"): with the Fisher
///    information Q = Phi^T Phi and the projector E = Phi Q^-1 Phi^T, delete, one
///    block at a time, the block B whose removal costs the least information,
///    det(Q - Phi_B^T Phi_B) = det(Q) det(I - E_BB); for a single row that is the row
///    with the smallest E_ii, Kammer's rule. Stops at the count asked for.
///  - Modal kinetic energy: rank blocks by sum_rows m_r sum_k Phi_rk^2 (m_r the row's
///    tributary mass, kg) and keep the largest.
///  - Driving-point residue: rank by sum_rows sum_k Phi_rk^2 / omega_k and keep the
///    largest (where a force at the sensor would excite the target modes most).
///
/// The set is judged by det(Q) and cond(Q) of the rows kept, and by the AutoMAC of the
/// target modes as the kept rows see them, MAC_ij = (phi_i . phi_j)^2 /
/// ((phi_i . phi_i)(phi_j . phi_j)): off-diagonal terms near 1 are modes the set cannot
/// tell apart. Plain Eigen; no model here (sim/modes/place_sensors.hpp builds Phi).

#include <Eigen/Dense>

#include <string>
#include <vector>

namespace mmv {

enum class PlacementMethod { EffectiveIndependence, ModalKineticEnergy, DrivingPointResidue };

/// "efi", "mke", "dpr"; false for another name.
bool parsePlacementMethod(const std::string& name, PlacementMethod& method);
const char* placementMethodName(PlacementMethod m);

struct PlacementProblem {
  Eigen::MatrixXd phi;               ///< rows: candidate directions, columns: target modes (m per unit modal coordinate).
  std::vector<int> block;            ///< per row: its block (0..blocks-1); rows of a block are kept or removed together.
  Eigen::VectorXd row_mass;          ///< per row, kg (modal kinetic energy ranking).
  /// Minimum separation: per block its world position (m); two kept blocks closer than
  /// `min_separation` (and apart: one station's directions may share it) are not kept
  /// together. Empty or 0: no constraint.
  std::vector<Eigen::Vector3d> block_at;
  double min_separation = 0;
  /// Per block: 1 for a sensor fixed in advance (the scene's own): always kept, counted
  /// in `count`; two fixed blocks may be closer than the separation. Empty: none.
  std::vector<char> fixed_block;
  bool fixed(int block) const { return static_cast<std::size_t>(block) < fixed_block.size() && fixed_block[static_cast<std::size_t>(block)]; }
  Eigen::VectorXd omega;             ///< per target mode, rad/s (> 0; driving-point residue ranking).
};

struct PlacementResult {
  std::vector<int> kept_blocks;      ///< in block order.
  std::vector<int> deletion_order;   ///< blocks removed, first to last (EfI; empty for rankings).
  Eigen::VectorXd block_score;       ///< per kept block: its EfI (sum of E_ii over its rows, at the end) or ranking value.
  double fisher_determinant = 0;     ///< det(Q) of the kept rows.
  double fisher_condition = 0;       ///< cond(Q) (infinity when singular).
  Eigen::MatrixXd automac;           ///< k x k.
  double max_offdiagonal_mac = 0;
};

/// Chooses `count` blocks (1 <= count <= blocks, and no fewer than the fixed ones; at
/// least one row per target mode for EfI so Q is invertible), every fixed block among them. Throws NumericalError when the candidates cannot see every
/// target mode (Q singular from the start).
PlacementResult placeSensors(const PlacementProblem& p, PlacementMethod method, int count);

/// The AutoMAC of the columns of `phi` (k x k).
Eigen::MatrixXd autoMac(const Eigen::MatrixXd& phi);

/// The rows of `p.phi` that belong to `blocks`.
Eigen::MatrixXd rowsOfBlocks(const PlacementProblem& p, const std::vector<int>& blocks);

}  // namespace mmv
