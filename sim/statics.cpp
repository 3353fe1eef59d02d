#include "sim/statics.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "sim/linearize.hpp"

namespace mmv {
namespace {

double maxAbsAt(const Eigen::VectorXd& f, const std::vector<int>& idx) {
  double m = 0;
  for (int i : idx) m = std::max(m, std::abs(f[i]));
  return m;
}

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
  SimTK::State s = model.getReferenceState();
  Eigen::VectorXd q = model.getQ(s);
  Eigen::VectorXd f = model.calcAppliedForces(s);
  r.force_scale = std::max({f.cwiseAbs().maxCoeff(), gravityMomentScale(model, s), 1e-300});
  const double tol = options.force_tolerance * r.force_scale;
  double res = maxAbsAt(f, dofs);

  auto finish = [&](bool ok, const std::string& why) {
    model.setQ(s, q);
    r.generalized_force = model.calcAppliedForces(s);
    r.converged = ok;
    r.failure = why;
    r.residual = maxAbsAt(r.generalized_force, dofs);
    r.q = q;
    r.state = s;
    return r;
  };

  for (r.iterations = 0; r.iterations < options.max_iterations; ++r.iterations) {
    if (!std::isfinite(res)) return finish(false, "non-finite generalized force");
    if (res <= tol || n == 0) return finish(true, "");
    model.setQ(s, q);
    const Eigen::MatrixXd K = calcStiffness(model, s, dofs);
    Eigen::VectorXd fx(n);
    for (int i = 0; i < n; ++i) fx[i] = f[dofs[i]];
    // Singular relative to the problem, not only to K itself: a 1x1 K of 1e-17 N*m/rad
    // is singular next to a 100 N*m load even though it is its own largest pivot.
    Eigen::PartialPivLU<Eigen::MatrixXd> lu(K);
    const double k_ref = std::max(K.diagonal().cwiseAbs().maxCoeff(), r.force_scale);
    const double pivot = lu.matrixLU().diagonal().cwiseAbs().minCoeff();
    if (!(pivot >= 1e-12 * k_ref) || !(lu.rcond() >= 1e-15)) {
      std::ostringstream os;
      os << "tangent stiffness is singular at iteration " << r.iterations
         << " (a free joint with nothing to restore it, or a mechanism)";
      return finish(false, os.str());
    }
    const Eigen::VectorXd dx = lu.solve(fx);  // f + (-K) dx = 0
    // Backtracking on ||f_x||: accept the first step that reduces it sufficiently.
    double alpha = 1.0;
    bool accepted = false;
    Eigen::VectorXd q_try = q, f_try;
    double res_try = res;
    for (int ls = 0; ls < 40; ++ls, alpha *= 0.5) {
      q_try = q;
      for (int i = 0; i < n; ++i) q_try[dofs[i]] += alpha * dx[i];
      model.setQ(s, q_try);
      f_try = model.calcAppliedForces(s);
      res_try = maxAbsAt(f_try, dofs);
      if (std::isfinite(res_try) && res_try <= (1.0 - 1e-4 * alpha) * res) {
        accepted = true;
        break;
      }
    }
    if (!accepted) {
      std::ostringstream os;
      os << "line search failed at iteration " << r.iterations << " (residual " << res << " N*m)";
      return finish(false, os.str());
    }
    q = q_try;
    f = f_try;
    res = res_try;
  }
  if (res <= tol) return finish(true, "");
  std::ostringstream os;
  os << "did not converge in " << options.max_iterations << " Newton iterations (residual " << res
     << " N*m, tolerance " << tol << " N*m)";
  return finish(false, os.str());
}

}  // namespace mmv
