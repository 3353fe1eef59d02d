// Modal reduction of a state-space model (sim/linear/state_space.hpp): modes of the
// state matrix, those no input-output pair sees dropped, a count or a band kept,
// the rest statically residualized.
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

#include "sim/core/linalg.hpp"
#include "sim/core/errors.hpp"
#include "sim/linear/state_space.hpp"

namespace mmv {
namespace {

using cd = std::complex<double>;

/// One mode of the state matrix: a real eigenvalue or a complex pair (the member with Im > 0).
struct ModeRef {
  int index;
  bool pair;
  double magnitude;
  Eigen::MatrixXd residue;  ///< |C_o v| |w B_i| / |lambda| per output-input pair.
};

/// The eigen solution of E^-1 A with its left eigenvectors.
struct StateEigen {
  Eigen::MatrixXd At, Bt;  ///< E^-1 A, E^-1 B.
  Eigen::VectorXcd lambda;
  Eigen::MatrixXcd V, W;   ///< right (columns), left (rows), W V = I.
  std::vector<ModeRef> modes;
  Eigen::MatrixXd pair_max;  ///< the largest modal residue of each output-input pair.
};

StateEigen stateModes(const StateSpace& full) {
  StateEigen sm;
  const Eigen::PartialPivLU<Eigen::MatrixXd> Elu(full.E);
  sm.At = Elu.solve(full.A);
  sm.Bt = Elu.solve(full.B);
  Eigen::EigenSolver<Eigen::MatrixXd> es(sm.At);
  if (es.info() != Eigen::Success) throw NumericalError("modal reduction: eigen solution of the state matrix failed");
  sm.lambda = es.eigenvalues();
  sm.V = es.eigenvectors();
  sm.W = sm.V.inverse();
  sm.pair_max = Eigen::MatrixXd::Zero(full.C.rows(), full.B.cols());
  for (int i = 0; i < full.numStates(); ++i) {
    const cd l = sm.lambda[i];
    if (l.imag() < -1e-12 * std::abs(l)) continue;
    const Eigen::VectorXd cv = (full.C.cast<cd>() * sm.V.col(i)).cwiseAbs();
    const Eigen::RowVectorXd wb = (sm.W.row(i) * sm.Bt.cast<cd>()).cwiseAbs();
    const Eigen::MatrixXd res = cv * wb / std::max(std::abs(l), 1e-300);
    sm.pair_max = sm.pair_max.cwiseMax(res);
    sm.modes.push_back({i, l.imag() > 1e-12 * std::abs(l), std::abs(l), res});
  }
  return sm;
}

/// Drops the modes no pair sees; returns how many.
int dropUnseen(StateEigen& sm) {
  if (!sm.pair_max.size()) return 0;
  // A mode is seen when some pair gets at least 1e-9 of that pair's largest modal
  // contribution (pairs that are zero by symmetry are measured against 1e-12 of the
  // model's largest, so their round-off sees nothing).
  const Eigen::MatrixXd floor = (1e-9 * sm.pair_max).cwiseMax(1e-12 * sm.pair_max.maxCoeff());
  std::vector<ModeRef> seen;
  int unseen = 0;
  for (const auto& m : sm.modes) ((m.residue - floor).maxCoeff() >= 0 ? seen.push_back(m) : void(++unseen));
  sm.modes.swap(seen);
  return unseen;
}

/// The modes kept: the lowest `o.modes` oscillatory ones (real roots within their
/// reach), or those in the band.
std::vector<ModeRef> selectModes(const std::vector<ModeRef>& modes, const ReductionOptions& o) {
  std::vector<ModeRef> kept;
  if (o.modes > 0) {
    // Count oscillatory modes (complex pairs); real roots (overdamped modes, relaxation)
    // are kept when they lie within the range of the kept pairs.
    double reach = 0;
    int counted = 0;
    for (const auto& m : modes)
      if (m.pair && counted < o.modes) {
        reach = m.magnitude;
        ++counted;
      }
    counted = 0;
    for (const auto& m : modes)
      if (m.pair ? counted++ < o.modes : m.magnitude <= reach) kept.push_back(m);
  } else {
    for (const auto& m : modes) {
      const double f = m.magnitude / (2 * M_PI);
      if (f >= o.band_min_hz && f <= o.band_max_hz) kept.push_back(m);
    }
  }
  return kept;
}

/// The reduced model on the real and imaginary parts of the kept modes.
StateSpace project(const StateSpace& full, const StateEigen& sm, const std::vector<ModeRef>& kept) {
  std::vector<Eigen::VectorXd> right, left;
  for (const auto& m : kept) {
    right.push_back(sm.V.col(m.index).real());
    left.push_back(sm.W.row(m.index).real().transpose());
    if (m.pair) {
      right.push_back(sm.V.col(m.index).imag());
      left.push_back(sm.W.row(m.index).imag().transpose());
    }
  }
  const int nr = static_cast<int>(right.size());
  Eigen::MatrixXd T(full.numStates(), nr), L(nr, full.numStates());
  for (int k = 0; k < nr; ++k) {
    T.col(k) = right[k];
    L.row(k) = left[k].transpose();
  }
  StateSpace r;
  r.E = L * T;
  r.A = L * sm.At * T;
  r.B = L * sm.Bt;
  r.C = full.C * T;
  r.D = full.D;
  r.input_names = full.input_names;
  r.input_units = full.input_units;
  r.output_names = full.output_names;
  r.output_units = full.output_units;
  for (int k = 0; k < nr; ++k) r.state_names.push_back("modal" + std::to_string(k + 1));
  return r;
}

/// D += H_full(0) - H_kept(0): the discarded modes' static contribution.
void residualize(const StateSpace& full, StateSpace& r) {
  const EquilibratedLu a_full(full.A);
  if (!a_full.isInvertible())
    throw NumericalError("static residualization needs a model without rigid-body modes (the state matrix is singular)");
  const Eigen::MatrixXd h_full = -full.C * a_full.solve(full.B) + full.D;
  Eigen::MatrixXd h_kept = r.D;
  if (r.numStates() > 0) {
    const EquilibratedLu a_red(r.A);
    if (!a_red.isInvertible()) throw NumericalError("static residualization: a kept mode has a zero eigenvalue");
    h_kept = -r.C * a_red.solve(r.B) + r.D;
  }
  r.D += h_full - h_kept;
}

}  // namespace

ReducedModel reduceModal(const StateSpace& full, const ReductionOptions& o) {
  StateEigen sm = stateModes(full);
  const int unseen = o.drop_unseen ? dropUnseen(sm) : 0;
  std::stable_sort(sm.modes.begin(), sm.modes.end(),
                   [](const ModeRef& a, const ModeRef& b) { return a.magnitude < b.magnitude; });
  const std::vector<ModeRef> kept = selectModes(sm.modes, o);
  ReducedModel red;
  red.model = project(full, sm, kept);
  red.kept_modes = static_cast<int>(kept.size());
  red.discarded_modes = static_cast<int>(sm.modes.size() - kept.size()) + unseen;
  red.unseen_modes = unseen;
  for (const auto& m : kept) red.kept_frequencies_hz.push_back(m.magnitude / (2 * M_PI));
  if (o.residualize && red.discarded_modes > 0) {
    residualize(full, red.model);
    red.residualized = true;
  }
  return red;
}

}  // namespace mmv
