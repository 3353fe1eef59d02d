#include "sim/statics.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "sim/closures.hpp"
#include "sim/linearize.hpp"

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

EquilibriumResult solveEquilibrium(const Model& model, const EquilibriumOptions& options) {
  EquilibriumResult r;
  const std::vector<int>& dofs = model.getDofs();
  const int n = static_cast<int>(dofs.size());
  const int m = model.getNumClosureRows();
  SimTK::State s = model.getReferenceState();
  model.getSystem().realize(s, SimTK::Stage::Position);  // a copied State must be realized again
  checkClosureRank(model, s, dofs);
  Eigen::VectorXd q = model.getQ(s);
  Eigen::VectorXd lambda = Eigen::VectorXd::Zero(m);
  r.force_scale = std::max({model.calcAppliedForces(s).cwiseAbs().maxCoeff(), gravityMomentScale(model, s), 1e-300});
  const double tol = options.force_tolerance * r.force_scale;
  // Closures must close to 1e-12 of the article's size.
  double size = 1e-3;
  for (const auto& p : model.getPoints()) size = std::max(size, model.findPointLocation(s, p).norm());
  const double tol_closure = 1e-12 * size;

  // Residuals at (q, lambda): force part over the DOFs, closure part.
  struct Residual {
    Eigen::VectorXd f_all, force, closure;
    double merit = 0;  // max of both, each relative to its tolerance
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
    const double fr = n ? res.force.cwiseAbs().maxCoeff() / tol : 0.0;
    const double cr = m ? res.closure.cwiseAbs().maxCoeff() / tol_closure : 0.0;
    res.merit = std::max(fr, cr);
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
    if (res.merit <= 1.0 || n == 0) return finish(true, "", res);
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
      if (std::isfinite(trial.merit) && trial.merit <= (1.0 - 1e-4 * alpha) * res.merit) {
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
  if (res.merit <= 1.0) return finish(true, "", res);
  std::ostringstream os;
  os << "did not converge in " << options.max_iterations << " Newton iterations (residual "
     << (n ? res.force.cwiseAbs().maxCoeff() : 0.0) << " N*m, tolerance " << tol << " N*m";
  if (m > 0) os << "; closure error " << res.closure.cwiseAbs().maxCoeff() << " m";
  os << ")";
  return finish(false, os.str(), res);
}

}  // namespace mmv
