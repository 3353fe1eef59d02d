// Modal reduction of a state-space model (sim/linear/state_space.hpp): modes of the
// state matrix, those no input-output pair sees dropped, a count or a band kept,
// the rest statically residualized.
#include <optional>
#include <algorithm>
#include <cmath>

#include "sim/core/linalg.hpp"
#include "sim/core/errors.hpp"
#include "sim/linear/state_modes.hpp"
#include "sim/core/text.hpp"
#include "sim/linear/state_space.hpp"

namespace mmv {
namespace {

using detail::ModeRef;
using detail::StateEigen;

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
  r.A = L * sm.times_state_matrix(T);
  r.B = L * sm.Bt;
  r.C = full.C * T;
  r.D = full.D;
  r.input_names = full.input_names;
  r.input_units = full.input_units;
  r.output_names = full.output_names;
  r.output_units = full.output_units;
  // Each state names its mode and the mode's |lambda| / 2 pi: a pair's real and
  // imaginary parts, a real (overdamped) root alone.
  for (std::size_t k = 0; k < kept.size(); ++k) {
    const std::string hz = strf("%.4gHz", kept[k].magnitude / (2 * M_PI));
    if (kept[k].pair) {
      r.state_names.push_back(strf("mode%zu_", k + 1) + hz + "_re");
      r.state_names.push_back(strf("mode%zu_", k + 1) + hz + "_im");
    } else {
      r.state_names.push_back(strf("root%zu_", k + 1) + hz);
    }
  }
  return r;
}

/// D += H_full(0) - H_kept(0): the discarded modes' static contribution.
void residualize(const StateSpace& full, const StateEigen& sm, StateSpace& r) {
  const std::optional<Eigen::MatrixXd> x = sm.static_solution();
  if (!x)
    throw NumericalError("static residualization needs a model without rigid-body modes (the state matrix is singular)");
  const Eigen::MatrixXd h_full = -full.C * *x + full.D;
  Eigen::MatrixXd h_kept = r.D;
  if (r.numStates() > 0) {
    const EquilibratedLu a_red(r.A);
    if (!a_red.isInvertible()) throw NumericalError("static residualization: a kept mode has a zero eigenvalue");
    h_kept = -r.C * a_red.solve(r.B) + r.D;
  }
  r.D += h_full - h_kept;
}

/// The modes the options need: only the lowest when a count is kept and no unseen mode
/// is dropped (which needs every mode's residue), else all.
StateEigen stateModes(const StateSpace& full, const ReductionOptions& o) {
  using S = ReductionOptions::Solver;
  const bool lowest_possible = o.modes > 0 && !o.drop_unseen;
  if (o.solver == S::Lowest && !lowest_possible)
    throw NumericalError("modal reduction: the lowest-modes solver needs a mode count and no dropping of unseen modes");
  if (o.solver == S::Automatic && o.proportional)
    if (std::optional<StateEigen> sm = detail::proportionalStateModes(full, o.proportional, lowest_possible ? o.modes : 0))
      return std::move(*sm);
  if (o.solver != S::Dense && lowest_possible)
    if (std::optional<StateEigen> sm = detail::lowestStateModes(full, o.modes)) return std::move(*sm);
  if (o.solver == S::Lowest) throw NumericalError("modal reduction: the lowest-modes solver does not apply to this model");
  return detail::allStateModes(full);
}

/// The reduction from the state matrix's modes (all of them, or at least those `o` keeps).
ReducedModel reduceFrom(const StateSpace& full, StateEigen sm, const ReductionOptions& o) {
  const int unseen = o.drop_unseen ? dropUnseen(sm) : 0;
  std::stable_sort(sm.modes.begin(), sm.modes.end(),
                   [](const ModeRef& a, const ModeRef& b) { return a.magnitude < b.magnitude; });
  const std::vector<ModeRef> kept = selectModes(sm.modes, o);
  ReducedModel red;
  red.model = project(full, sm, kept);
  red.kept_modes = static_cast<int>(kept.size());
  red.unseen_modes = unseen;
  for (const auto& m : kept) {
    red.kept_frequencies_hz.push_back(m.magnitude / (2 * M_PI));
    // A real root is no resonance (damping ratio 1 and above: reported as 1).
    const std::complex<double> l = sm.lambda[m.index];
    red.kept_damping.push_back(m.pair && std::abs(l) > 0 ? std::min(1.0, -l.real() / std::abs(l)) : 1.0);
  }
  red.every_mode_computed = sm.every_mode;
  if (o.residualize && red.model.numStates() < full.numStates()) {
    residualize(full, sm, red.model);
    red.residualized = true;
  }
  return red;
}

}  // namespace

ReducedModel reduceModal(const StateSpace& full, const ReductionOptions& o) { return reduceFrom(full, stateModes(full, o), o); }

void modesForTarget(const StateSpace& full, const ReductionOptions& base, const std::vector<Eigen::MatrixXcd>& full_responses,
                    const std::vector<double>& omegas, double target, int max_modes, ModelError& err) {
  MMV_DEMAND(max_modes >= 1 && target > 0);
  // Galloping from the count asked for (doubling while the error is above the target),
  // then bisection: a few small reductions, each from one solution of the state
  // matrix's lowest modes (the same modes a reduction of its own would compute), solved
  // again for more only when the search needs more: the many-mode solutions and the
  // large reduced models are the costly ones.
  ReductionOptions o = base;
  o.band_min_hz = o.band_max_hz = 0;
  StateEigen sm;
  int solved_for = 0;  // the modes sm holds: the count first tried, more only if the search goes there
  auto errorWith = [&](int modes) {
    if (modes > solved_for) {
      o.modes = solved_for = modes;  // a few more cost much more where overdamped roots crowd past them
      sm = stateModes(full, o);
    }
    o.modes = modes;
    return compareResponses(full_responses, reduceFrom(full, sm, o).model, omegas).max_relative;
  };
  ModelError::ModesNeeded& n = err.needed;
  n = {};
  n.computed = true;
  n.target = target;
  int lo = 0, hi = std::clamp(base.modes > 0 ? base.modes : 8, 1, max_modes);  // lo fails (or is none)
  double e_hi = errorWith(hi);
  while (e_hi > target) {
    if (hi == max_modes) {  // even the most modes tried do not meet it
      n.modes = hi;
      n.error = e_hi;
      return;
    }
    lo = hi;
    hi = std::min(2 * hi, max_modes);
    e_hi = errorWith(hi);
  }
  while (hi - lo > 1) {
    const int mid = (lo + hi) / 2;
    const double e = errorWith(mid);
    if (e <= target) hi = mid, e_hi = e;
    else lo = mid;
  }
  n.reached = true;
  n.modes = hi;
  n.error = e_hi;
}

}  // namespace mmv
