#include "sim/statics/statics.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

#include "sim/statics/closures.hpp"
#include "sim/statics/linearize.hpp"

namespace mmv {
namespace {


/// The largest moment gravity could exert about any pin in this configuration,
/// max_k sum_{i outboard of k} m_i |g| |p_i - o_k|: a load scale that does not vanish
/// when the article happens to be balanced (e.g. an upright straight rod).
double gravityMomentScale(const Model& model, const SimTK::State& s) {
  const auto& matter = model.getMatter();
  const double g = model.getGravity().norm();
  std::vector<double> scale(model.getNumCoordinates(), 0.0);
  for (std::size_t b = 0; b < model.getBodies().size(); ++b) {
    const SimTK::MobilizedBody& mb = matter.getMobilizedBody(model.getBodies()[b].mobod);
    const SimTK::Vec3 c = mb.findStationLocationInGround(s, mb.getBodyMassCenterStation(s));
    for (int k : model.getAncestorCoordinates(static_cast<int>(b))) {
      const SimTK::Vec3 o = matter.getMobilizedBody(model.getCoordinates()[k].mobod).getBodyOriginLocation(s);
      scale[k] += mb.getBodyMass(s) * g * (c - o).norm();
    }
  }
  return scale.empty() ? 0.0 : *std::max_element(scale.begin(), scale.end());
}

}  // namespace

namespace {

/// Newton's method from (q, lambda) in state s (whose gravity scale is set).
EquilibriumResult newton(const Model& model, SimTK::State s, Eigen::VectorXd q, Eigen::VectorXd lambda,
                         const EquilibriumOptions& options, double force_scale, double size) {
  EquilibriumResult r;
  const std::vector<int>& dofs = model.getDofs();
  const int n = static_cast<int>(dofs.size());
  const int m = model.getNumClosureRows();
  r.force_scale = force_scale;
  const double tol = options.force_tolerance * r.force_scale;
  const double tol_closure = 1e-12 * size;  // closures must close to 1e-12 of the article's size

  // Residuals at (q, lambda): force part over the DOFs, closure part.
  struct Residual {
    Eigen::VectorXd f_all, force, closure;
    double merit = 0;
    bool converged = false;
  };
  auto evaluate = [&](const Eigen::VectorXd& qv, const Eigen::VectorXd& lv) {
    Residual res;
    model.setQ(s, qv);
    res.f_all = model.calcAppliedForces(s);
    res.force.resize(n);
    for (int i = 0; i < n; ++i) res.force[i] = res.f_all[dofs[i]];
    if (m > 0) {
      res.force += calcClosureJacobian(model, s, dofs).transpose() * lv;
      res.closure = calcClosureErrors(model, s);
    } else {
      res.closure.resize(0);
    }
    // Converged when both parts are within tolerance; the line search uses the sum of
    // squares of both parts, each relative to its physical scale (force scale, size).
    const double fr = n ? res.force.cwiseAbs().maxCoeff() / tol : 0.0;
    const double cr = m ? res.closure.cwiseAbs().maxCoeff() / tol_closure : 0.0;
    res.converged = std::max(fr, cr) <= 1.0;
    res.merit = (n ? (res.force / r.force_scale).squaredNorm() : 0.0) + (m ? (res.closure / size).squaredNorm() : 0.0);
    return res;
  };

  auto finish = [&](bool ok, const std::string& why, const Residual& res) {
    model.setQ(s, q);
    model.getSystem().realize(s, SimTK::Stage::Position);
    r.generalized_force = res.f_all;
    if (m > 0) {
      // Closure forces on every coordinate (held joints included) for the torques.
      std::vector<int> all(model.getNumCoordinates());
      for (int i = 0; i < model.getNumCoordinates(); ++i) all[i] = i;
      r.generalized_force += calcClosureJacobian(model, s, all).transpose() * lambda;
    }
    r.converged = ok;
    r.failure = why;
    r.residual = n ? res.force.cwiseAbs().maxCoeff() : 0.0;
    r.closure_error = m ? res.closure.cwiseAbs().maxCoeff() : 0.0;
    r.closure_multipliers = lambda;
    r.q = q;
    r.state = s;
    return r;
  };

  Residual res = evaluate(q, lambda);
  for (r.iterations = 0; r.iterations < options.max_iterations; ++r.iterations) {
    if (!std::isfinite(res.merit)) return finish(false, "non-finite generalized force", res);
    if (res.converged || n == 0) return finish(true, "", res);
    model.setQ(s, q);
    model.getSystem().realize(s, SimTK::Stage::Position);
    const Eigen::MatrixXd K = calcStiffness(model, s, dofs);
    Eigen::MatrixXd A = Eigen::MatrixXd::Zero(n + m, n + m);
    A.topLeftCorner(n, n) = -K;
    if (m > 0) {
      const Eigen::MatrixXd G = calcClosureJacobian(model, s, dofs);
      A.topLeftCorner(n, n) -= calcPointForceStiffness(model, s, dofs, closureForces(model, lambda));
      A.topRightCorner(n, m) = G.transpose();
      A.bottomLeftCorner(m, n) = G;
    }
    Eigen::VectorXd rhs(n + m);
    rhs << -res.force, -res.closure;
    // Singular relative to the problem, not only to A itself: a 1x1 K of 1e-17 N*m/rad
    // is singular next to a 100 N*m load even though it is its own largest pivot.
    Eigen::PartialPivLU<Eigen::MatrixXd> lu(A);
    const double k_ref = std::max(K.diagonal().cwiseAbs().maxCoeff(), r.force_scale);
    const double pivot = lu.matrixLU().diagonal().head(n).cwiseAbs().minCoeff();
    if (!(pivot >= 1e-12 * k_ref) || !(lu.rcond() >= 1e-15)) {
      std::ostringstream os;
      os << "tangent stiffness is singular at iteration " << r.iterations
         << " (a free joint with nothing to restore it, or a mechanism)";
      return finish(false, os.str(), res);
    }
    const Eigen::VectorXd step = lu.solve(rhs);
    // Backtracking: accept the first step that reduces the residual sufficiently.
    double alpha = 1.0;
    bool accepted = false;
    Eigen::VectorXd q_try, l_try;
    Residual trial;
    for (int ls = 0; ls < 40; ++ls, alpha *= 0.5) {
      q_try = q;
      for (int i = 0; i < n; ++i) q_try[dofs[i]] += alpha * step[i];
      l_try = lambda + alpha * step.tail(m);
      trial = evaluate(q_try, l_try);
      if (std::isfinite(trial.merit) && (trial.merit <= (1.0 - 1e-4 * alpha) * res.merit || trial.converged)) {
        accepted = true;
        break;
      }
    }
    if (!accepted) {
      std::ostringstream os;
      os << "line search failed at iteration " << r.iterations << " (residual " << res.force.cwiseAbs().maxCoeff()
         << " N*m)";
      return finish(false, os.str(), res);
    }
    q = q_try;
    lambda = l_try;
    res = trial;
  }
  if (res.converged) return finish(true, "", res);
  std::ostringstream os;
  os << "did not converge in " << options.max_iterations << " Newton iterations (residual "
     << (n ? res.force.cwiseAbs().maxCoeff() : 0.0) << " N*m, tolerance " << tol << " N*m";
  if (m > 0) os << "; closure error " << res.closure.cwiseAbs().maxCoeff() << " m";
  os << ")";
  return finish(false, os.str(), res);
}

}  // namespace

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
         << 100 * done << " % of g: the equilibrium path turns back or branches there (the article buckles or snaps, "
         << "e.g. a closure compresses a slender link beyond its buckling load)";
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
