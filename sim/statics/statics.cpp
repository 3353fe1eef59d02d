#include "sim/statics/statics.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <optional>
#include <sstream>

#include "sim/core/linalg.hpp"
#include "sim/core/text.hpp"
#include "sim/statics/closures.hpp"
#include "sim/statics/linearize.hpp"

namespace mmv {
namespace {

/// The largest moment gravity could exert about any joint axis (an article joint or a
/// floating base's, not a link's own hinges) in this configuration,
/// max_k sum_{i outboard of k} m_i |g| |p_i - o_k|, or about any pin when the model has
/// no joint: a load scale that does not vanish when the article happens to be balanced
/// (e.g. an upright straight rod). Joints only, so that its cost is O(bodies) on a fine
/// mesh (a few joints on each body's path, against thousands of hinges).
double gravityMomentScale(const Model& model, const SimTK::State& s) {
  const auto& matter = model.getMatter();
  const double g = model.getGravity().norm();
  const auto& coords = model.getCoordinates();
  const bool any_joint = std::any_of(coords.begin(), coords.end(), [](const Coordinate& c) { return c.kind == CoordinateKind::Joint; });
  // Per mobilized body, its counted coordinates and the nearest inboard body with any.
  std::vector<std::vector<int>> counted(matter.getNumBodies());
  for (std::size_t k = 0; k < coords.size(); ++k)
    if (!any_joint || coords[k].kind == CoordinateKind::Joint) counted[coords[k].mobod].push_back(static_cast<int>(k));
  std::vector<int> inboard(matter.getNumBodies(), 0);  // 0: ground
  for (SimTK::MobilizedBodyIndex ix(1); ix < matter.getNumBodies(); ++ix) {
    const int p = matter.getMobilizedBody(ix).getParentMobilizedBody().getMobilizedBodyIndex();
    inboard[ix] = counted[p].empty() ? inboard[p] : p;
  }
  std::vector<double> scale(coords.size(), 0.0);
  std::vector<SimTK::Vec3> origin(coords.size());
  for (std::size_t k = 0; k < coords.size(); ++k) origin[k] = matter.getMobilizedBody(coords[k].mobod).getBodyOriginLocation(s);
  for (const auto& body : model.getBodies()) {
    const SimTK::MobilizedBody& mb = matter.getMobilizedBody(body.mobod);
    const SimTK::Vec3 c = mb.findStationLocationInGround(s, mb.getBodyMassCenterStation(s));
    const double weight = mb.getBodyMass(s) * g;
    for (int ix = counted[body.mobod].empty() ? inboard[body.mobod] : static_cast<int>(body.mobod); ix != 0; ix = inboard[ix])
      for (int k : counted[ix]) scale[k] += weight * (c - origin[k]).norm();
  }
  return scale.empty() ? 0.0 : *std::max_element(scale.begin(), scale.end());
}

}  // namespace

namespace {

/// Newton's method on the KKT system (statics.hpp) from (q, lambda) in state s
/// (whose gravity scale is set), with a backtracking line search.
class Newton {
 public:
  Newton(const Model& model, SimTK::State s, const EquilibriumOptions& options, double force_scale, double size)
      : model_(model), s_(std::move(s)), options_(options), dofs_(model.getDofs()),
        n_(static_cast<int>(dofs_.size())), m_(model.getNumClosureRows()), size_(size) {
    r_.force_scale = force_scale;
    tol_ = options.force_tolerance * force_scale;
    tol_closure_ = 1e-12 * size;  // closures must close to 1e-12 of the article's size
  }

  EquilibriumResult solve(Eigen::VectorXd q, Eigen::VectorXd lambda);

 private:
  /// Residuals at (q, lambda): force part over the DOFs, closure part.
  struct Residual {
    Eigen::VectorXd f_all, force, closure;
    double merit = 0;
    bool converged = false;
  };
  Residual evaluate(const Eigen::VectorXd& qv, const Eigen::VectorXd& lv);
  EquilibriumResult finish(bool ok, const std::string& why, const Residual& res);
  /// The Newton step (dq over the DOFs; dlambda), or empty when the tangent is singular.
  std::optional<Eigen::VectorXd> step(const Residual& res);
  /// The first step length 1, 1/2, ... that reduces the merit sufficiently; false if none.
  bool lineSearch(const Eigen::VectorXd& dx, Residual& res);
  /// No step can reduce `res` further because it is round-off: each DOF's residual within
  /// what rounding its coordinate makes of its own stiffness (64 eps K_ii max(1, |q_i|):
  /// a servo of 1e10 N*m/rad turns the last bit of a 0.5 rad angle into 1e-6 N*m), the
  /// closures within their tolerance. Checked only where Newton stalls.
  bool atRoundOff(const Residual& res) const;

  const Model& model_;
  SimTK::State s_;
  const EquilibriumOptions& options_;
  const std::vector<int>& dofs_;
  const int n_, m_;
  const double size_;
  double tol_ = 0, tol_closure_ = 0;
  Eigen::VectorXd q_, lambda_;
  Eigen::VectorXd k_diag_;  ///< the last step's stiffness diagonal over the DOFs (atRoundOff)
  EquilibriumResult r_;
};

Newton::Residual Newton::evaluate(const Eigen::VectorXd& qv, const Eigen::VectorXd& lv) {
  Residual res;
  model_.setQ(s_, qv);
  res.f_all = model_.calcAppliedForces(s_);
  res.force.resize(n_);
  for (int i = 0; i < n_; ++i) res.force[i] = res.f_all[dofs_[i]];
  if (m_ > 0) {
    res.force += calcClosureJacobian(model_, s_, dofs_).transpose() * lv;
    res.closure = calcClosureErrors(model_, s_);
  } else {
    res.closure.resize(0);
  }
  // Converged when both parts are within tolerance; the line search uses the sum of
  // squares of both parts, each relative to its physical scale (force scale, size).
  const double fr = n_ ? res.force.cwiseAbs().maxCoeff() / tol_ : 0.0;
  const double cr = m_ ? res.closure.cwiseAbs().maxCoeff() / tol_closure_ : 0.0;
  res.converged = std::max(fr, cr) <= 1.0;
  res.merit = (n_ ? (res.force / r_.force_scale).squaredNorm() : 0.0) + (m_ ? (res.closure / size_).squaredNorm() : 0.0);
  return res;
}

EquilibriumResult Newton::finish(bool ok, const std::string& why, const Residual& res) {
  model_.setQ(s_, q_);
  model_.getSystem().realize(s_, SimTK::Stage::Position);
  r_.generalized_force = res.f_all;
  if (m_ > 0) {
    // Closure forces on every coordinate (held joints included) for the torques.
    std::vector<int> all(model_.getNumCoordinates());
    for (int i = 0; i < model_.getNumCoordinates(); ++i) all[i] = i;
    r_.generalized_force += calcClosureJacobian(model_, s_, all).transpose() * lambda_;
  }
  r_.converged = ok;
  r_.failure = why;
  r_.residual = n_ ? res.force.cwiseAbs().maxCoeff() : 0.0;
  r_.closure_error = m_ ? res.closure.cwiseAbs().maxCoeff() : 0.0;
  r_.closure_multipliers = lambda_;
  r_.q = q_;
  r_.state = s_;
  return r_;
}

std::optional<Eigen::VectorXd> Newton::step(const Residual& res) {
  model_.setQ(s_, q_);
  model_.getSystem().realize(s_, SimTK::Stage::Position);
  const double k_min = 1e-12 * r_.force_scale;
  if (TreeOperator::appliesTo(model_) && n_ >= kTreeOperatorMinDofs) {
    // A large open tree: K's O(n) factorization (sim/statics/tree_operator.hpp) in place
    // of the dense Cholesky below, under the same tests (positive definite, every
    // Jacobi-scaled pivot at least 1e-12); else the dense path judges the step.
    const TreeOperator op(model_, s_, dofs_);
    const TreeFactor f = op.factor(0.0);
    const Eigen::VectorXd diag = op.diagonalK();
    k_diag_ = diag;
    if (f.invertible() && diag.minCoeff() > k_min && f.pivots().cwiseQuotient(diag).minCoeff() >= 1e-12)
      return f.solve(res.force);
  }
  const Eigen::MatrixXd K = calcStiffness(model_, s_, dofs_);
  k_diag_ = K.diagonal();
  // Singular relative to the problem's loads, not to K's own largest entry: a 1x1 K of
  // 1e-17 N*m/rad is singular next to a 100 N*m load although it is its own largest
  // pivot, while hinges of 4e13 and 2.6 N*m/rad in one chain (a link of E = 1e20 Pa
  // beside a slender rod) are a well-posed problem whose raw pivots span 13 decades.
  // So each row is first scaled to unit size (equilibration), and a row whose
  // stiffness is below 1e-12 of the load scale per radian has nothing to hold it.
  if (m_ == 0 && model_.hasClosedFormForces() && K.diagonal().minCoeff() > k_min) {
    // An open tree near a stable equilibrium: K (symmetric in closed form) is positive
    // definite; its Jacobi-scaled Cholesky factor costs half an LU. Anything else goes to the LU.
    const Eigen::VectorXd d = K.diagonal().cwiseSqrt().cwiseInverse();
    const Eigen::LLT<Eigen::MatrixXd> llt(d.asDiagonal() * K * d.asDiagonal());
    if (llt.info() == Eigen::Success && llt.rcond() >= 1e-12)
      return Eigen::VectorXd(d.asDiagonal() * llt.solve(d.asDiagonal() * res.force));
  }
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(n_ + m_, n_ + m_);
  A.topLeftCorner(n_, n_) = -K;
  if (m_ > 0) {
    const Eigen::MatrixXd G = calcClosureJacobian(model_, s_, dofs_);
    A.topLeftCorner(n_, n_) -= calcPointForceStiffness(model_, s_, dofs_, closureForces(model_, lambda_));
    A.topRightCorner(n_, m_) = G.transpose();
    A.bottomLeftCorner(m_, n_) = G;
  }
  Eigen::VectorXd rhs(n_ + m_);
  rhs << -res.force, -res.closure;
  const Eigen::VectorXd row_max = A.cwiseAbs().rowwise().maxCoeff();
  if (!(row_max.head(n_).minCoeff() > k_min) || (m_ > 0 && !(row_max.tail(m_).minCoeff() > 0))) return std::nullopt;
  const Eigen::VectorXd r = row_max.cwiseInverse();
  Eigen::PartialPivLU<Eigen::MatrixXd> lu(r.asDiagonal() * A);
  const double pivot = lu.matrixLU().diagonal().head(n_).cwiseAbs().minCoeff();
  if (!(pivot >= 1e-12) || !(lu.rcond() >= 1e-15)) return std::nullopt;
  return Eigen::VectorXd(lu.solve(r.asDiagonal() * rhs));
}

bool Newton::atRoundOff(const Residual& res) const {
  if (k_diag_.size() != n_) return false;
  if (m_ > 0 && !(res.closure.cwiseAbs().maxCoeff() <= tol_closure_)) return false;
  const double eps = std::numeric_limits<double>::epsilon();
  for (int i = 0; i < n_; ++i) {
    const double floor = 64 * eps * std::abs(k_diag_[i]) * std::max(1.0, std::abs(q_[dofs_[i]]));
    if (!(std::abs(res.force[i]) <= std::max(tol_, floor))) return false;
  }
  return true;
}

bool Newton::lineSearch(const Eigen::VectorXd& dx, Residual& res) {
  double alpha = 1.0;
  for (int ls = 0; ls < 40; ++ls, alpha *= 0.5) {
    Eigen::VectorXd q_try = q_;
    for (int i = 0; i < n_; ++i) q_try[dofs_[i]] += alpha * dx[i];
    const Eigen::VectorXd l_try = lambda_ + alpha * dx.tail(m_);
    Residual trial = evaluate(q_try, l_try);
    if (std::isfinite(trial.merit) && (trial.merit <= (1.0 - 1e-4 * alpha) * res.merit || trial.converged)) {
      q_ = q_try;
      lambda_ = l_try;
      res = trial;
      return true;
    }
  }
  return false;
}

EquilibriumResult Newton::solve(Eigen::VectorXd q, Eigen::VectorXd lambda) {
  q_ = std::move(q);
  lambda_ = std::move(lambda);
  Residual res = evaluate(q_, lambda_);
  for (r_.iterations = 0; r_.iterations < options_.max_iterations; ++r_.iterations) {
    if (!std::isfinite(res.merit)) return finish(false, "non-finite generalized force", res);
    if (res.converged || n_ == 0) return finish(true, "", res);
    const std::optional<Eigen::VectorXd> dx = step(res);
    if (!dx) {
      std::ostringstream os;
      os << "tangent stiffness is singular at iteration " << r_.iterations
         << " (a free joint with nothing to restore it, or a mechanism)";
      return finish(false, os.str(), res);
    }
    if (!lineSearch(*dx, res)) {
      if (atRoundOff(res)) return finish(true, "", res);  // very stiff joints: nothing left but rounding
      std::ostringstream os;
      os << "line search failed at iteration " << r_.iterations << " (residual " << res.force.cwiseAbs().maxCoeff()
         << " N*m)";
      return finish(false, os.str(), res);
    }
  }
  if (res.converged || atRoundOff(res)) return finish(true, "", res);
  std::ostringstream os;
  os << "did not converge in " << options_.max_iterations << " Newton iterations (residual "
     << (n_ ? res.force.cwiseAbs().maxCoeff() : 0.0) << " N*m, tolerance " << tol_ << " N*m";
  if (m_ > 0) os << "; closure error " << res.closure.cwiseAbs().maxCoeff() << " m";
  os << ")";
  return finish(false, os.str(), res);
}

EquilibriumResult newton(const Model& model, SimTK::State s, Eigen::VectorXd q, Eigen::VectorXd lambda,
                         const EquilibriumOptions& options, double force_scale, double size) {
  return Newton(model, std::move(s), options, force_scale, size).solve(std::move(q), std::move(lambda));
}

}  // namespace

namespace {

/// Why gravity's ramp stalled, in the terms of this model: a free joint that gravity
/// turns with nothing to hold it (no equilibrium near its scene angle), else a limit or
/// bifurcation point of the path (buckling or snap-through; with closures, typically a
/// closure compressing a slender link).
std::string stalledContinuationCause(const Model& model, SimTK::State s, const Eigen::VectorXd& q0) {
  model.setGravityScale(s, 1.0);
  model.setQ(s, q0);
  model.getSystem().realize(s, SimTK::Stage::Position);
  const Eigen::VectorXd f = model.calcAppliedForces(s);
  const auto& coords = model.getCoordinates();
  double scale = 0;
  for (int i = 0; i < static_cast<int>(coords.size()); ++i) scale = std::max(scale, std::abs(f[i]));
  std::string free;
  for (int i = 0; i < static_cast<int>(coords.size()); ++i) {
    const Coordinate& c = coords[i];
    if (c.kind != CoordinateKind::Joint || c.held || c.stiffness > 0 || !(std::abs(f[i]) > 1e-6 * scale)) continue;
    free += (free.empty() ? "" : ", ") + strf("'%s' (%.3g N*m at its scene angle %.1f deg)", c.name.c_str(), f[i],
                                              c.reference * 180 / M_PI);
  }
  if (!free.empty())
    return "gravity turns the free joint(s) " + free +
           " and nothing holds them: a free joint rests only where gravity's torque on it vanishes (hanging, or "
           "inverted and unstable). Give it that angle, hold it (hold: locked or servo), or let it swing from rest "
           "(simulation.start: rest)";
  if (!model.getClosures().empty())
    return "the equilibrium path turns back or branches there (the article buckles or snaps through, e.g. a closure "
           "compresses a slender link beyond its buckling load)";
  return "the equilibrium path turns back or branches there (the article buckles or snaps through under its own "
         "weight: a link loaded in compression beyond its buckling load)";
}

}  // namespace

EquilibriumAssessment assessEquilibrium(const Model& model, const EquilibriumResult& eq) {
  EquilibriumAssessment a;
  const std::vector<int>& dofs = model.getDofs();
  const Eigen::VectorXd q = model.getQ(eq.state);
  const auto& coords = model.getCoordinates();
  for (int i = 0; i < static_cast<int>(coords.size()); ++i) {
    const Coordinate& c = coords[i];
    const double moved = (q[i] - c.reference) * 180 / M_PI;
    if (c.kind == CoordinateKind::Joint && !c.held && c.motion == CoordinateMotion::Rotation && std::abs(moved) > 0.5)
      a.moved_joints.push_back(strf("joint '%s' settled at %.1f deg, %.1f deg from its scene angle %.1f deg", c.name.c_str(),
                                    q[i] * 180 / M_PI, moved, c.reference * 180 / M_PI));
  }
  if (dofs.empty()) return a;
  SimTK::State st = eq.state;
  model.getSystem().realize(st, SimTK::Stage::Position);  // a copied State must be realized again
  Eigen::MatrixXd K = calcStiffness(model, st, dofs);
  if (model.getNumClosureRows() > 0) {
    K += calcPointForceStiffness(model, st, dofs, closureForces(model, eq.closure_multipliers));
    const Eigen::MatrixXd Z = nullSpace(calcClosureJacobian(model, st, dofs), static_cast<int>(dofs.size()));
    K = Z.transpose() * K * Z;
  }
  if (K.rows() == 0) return a;
  symmetrize(K);
  // The inertia of K (Sylvester): negative pivots of its LDL^T are negative eigenvalues.
  // Pivots within round-off of K's scale are a neutral direction (a mechanism), not an
  // instability.
  const Eigen::LDLT<Eigen::MatrixXd> ldlt(K);
  const double tiny = 1e-9 * K.diagonal().cwiseAbs().maxCoeff();
  for (Eigen::Index i = 0; i < K.rows(); ++i)
    if (ldlt.vectorD()[i] < -tiny) ++a.unstable_directions;
  return a;
}

EquilibriumResult solveEquilibrium(const Model& model, const EquilibriumOptions& options) {
  const std::vector<int>& dofs = model.getDofs();
  SimTK::State s = model.getReferenceState();
  model.getSystem().realize(s, SimTK::Stage::Position);  // a copied State must be realized again
  checkClosureRank(model, s, dofs);
  const Eigen::VectorXd q0 = model.getQ(s);
  const Eigen::VectorXd l0 = Eigen::VectorXd::Zero(model.getNumClosureRows());
  const double force_scale =
      std::max({model.calcAppliedForces(s).cwiseAbs().maxCoeff(), gravityMomentScale(model, s), 1e-300});
  double size = 1e-3;
  for (const auto& p : model.getPoints()) size = std::max(size, model.findPointLocation(s, p).norm());

  EquilibriumResult direct = newton(model, s, q0, l0, options, force_scale, size);
  if (direct.converged || !options.continuation || model.getGravity().norm() == 0.0) return direct;

  // Natural continuation in gravity: ramp g up, each step from the last equilibrium.
  int iterations = direct.iterations, steps = 0;
  double done = 0.0, step = 0.25;
  Eigen::VectorXd q = q0, lambda = l0;
  EquilibriumResult last;
  while (done < 1.0) {
    const double next = std::min(1.0, done + step);
    model.setGravityScale(s, next);
    EquilibriumResult r = newton(model, s, q, lambda, options, force_scale, size);
    iterations += r.iterations;
    if (r.converged) {
      done = next;
      q = r.q;
      lambda = r.closure_multipliers;
      last = r;
      ++steps;
      step = std::min(0.5, 1.5 * step);
    } else if ((step *= 0.5) < 1.0 / 1024) {
      std::ostringstream os;
      os << direct.failure << "; continuation in gravity stopped at " << std::fixed << std::setprecision(1)
         << 100 * done << " % of g: " << stalledContinuationCause(model, s, q0);
      r.failure = os.str();
      r.iterations = iterations;
      r.continuation_steps = steps;
      model.setGravityScale(r.state, 1.0);
      return r;
    }
  }
  last.iterations = iterations;
  last.continuation_steps = steps;
  return last;
}

}  // namespace mmv
