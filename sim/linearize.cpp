#include "sim/linearize.hpp"

#include <stdexcept>

namespace mmv {

Eigen::MatrixXd calcStiffness(const Model& model, const SimTK::State& s, const std::vector<int>& dofs) {
  return model.hasOnlyGravityAndPinSprings() ? calcStiffnessClosedForm(model, s, dofs)
                                             : calcStiffnessByDifferences(model, s, dofs);
}

Eigen::MatrixXd calcStiffnessClosedForm(const Model& model, const SimTK::State& s, const std::vector<int>& dofs) {
  if (!model.hasOnlyGravityAndPinSprings())
    throw std::logic_error("calcStiffnessClosedForm: the model has forces other than gravity and pin springs");
  SimTK::State work = s;
  model.getSystem().realize(work, SimTK::Stage::Position);
  const auto& matter = model.getMatter();
  const auto& bodies = model.getBodies();
  const int nc = model.getNumCoordinates();
  // Mass and first moment outboard of every coordinate's pin.
  std::vector<double> mass(nc, 0.0);
  std::vector<SimTK::Vec3> moment(nc, SimTK::Vec3(0));
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    const SimTK::MobilizedBody& mb = matter.getMobilizedBody(bodies[b].mobod);
    const double m = mb.getBodyMass(work);
    const SimTK::Vec3 c = mb.findStationLocationInGround(work, mb.getBodyMassCenterStation(work));
    for (int k : model.getAncestorCoordinates(static_cast<int>(b))) {
      mass[k] += m;
      moment[k] += m * c;
    }
  }
  const SimTK::Vec3& g = model.getGravity();
  std::vector<double> gk(nc);
  for (int k = 0; k < nc; ++k) {
    // The pin's axis passes through its body's origin (builders put M at the origin).
    const SimTK::Vec3 o = matter.getMobilizedBody(model.getCoordinates()[k].mobod).getBodyOriginLocation(work);
    gk[k] = ~g * (moment[k] - mass[k] * o);
  }
  const int n = static_cast<int>(dofs.size());
  std::vector<int> column(nc, -1);  // coordinate -> row/column in K, -1 if held
  for (int a = 0; a < n; ++a) column[dofs[a]] = a;
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(n, n);
  for (int b = 0; b < n; ++b) {
    const int k = dofs[b];
    // Every j that moves pin k's body (k itself included) is inboard of or equal to k,
    // so the pair (j, k) gets k's term.
    for (int j : model.getAncestorCoordinates(model.getCoordinateBody(k))) {
      const int a = column[j];
      if (a < 0) continue;
      K(a, b) = gk[k];
      K(b, a) = gk[k];
    }
    K(b, b) += model.getCoordinates()[k].stiffness;
  }
  return K;
}

Eigen::MatrixXd calcStiffnessByDifferences(const Model& model, const SimTK::State& s, const std::vector<int>& dofs) {
  constexpr double kStep = 1e-6;  // rad
  SimTK::State work = s;
  model.getSystem().realize(work, SimTK::Stage::Position);
  const Eigen::VectorXd q0 = model.getQ(s);
  const int n = static_cast<int>(dofs.size());
  Eigen::MatrixXd K(n, n);
  Eigen::VectorXd q = q0;
  for (int j = 0; j < n; ++j) {
    const int c = dofs[j];
    q[c] = q0[c] + kStep;
    model.setQ(work, q);
    const Eigen::VectorXd fp = model.calcAppliedForces(work);
    q[c] = q0[c] - kStep;
    model.setQ(work, q);
    const Eigen::VectorXd fm = model.calcAppliedForces(work);
    q[c] = q0[c];
    for (int i = 0; i < n; ++i) K(i, j) = -(fp[dofs[i]] - fm[dofs[i]]) / (2 * kStep);
  }
  return K;
}

Eigen::MatrixXd calcMass(const Model& model, const SimTK::State& s, const std::vector<int>& dofs) {
  SimTK::State work = s;
  model.getSystem().realize(work, SimTK::Stage::Position);
  SimTK::Matrix m;
  model.getMatter().calcM(work, m);
  // Coordinate i is mobility u[i] of its mobilizer; the model keeps them in u order.
  const int n = static_cast<int>(dofs.size());
  Eigen::MatrixXd M(n, n);
  std::vector<int> u(n);
  for (int i = 0; i < n; ++i) u[i] = model.getUIndex(dofs[i]);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) M(i, j) = m(u[i], u[j]);
  return M;
}

LinearizedModel linearize(const Model& model, const SimTK::State& equilibrium) {
  LinearizedModel lin;
  lin.dofs = model.getDofs();
  const int n = static_cast<int>(lin.dofs.size());
  lin.M = calcMass(model, equilibrium, lin.dofs);
  lin.M = 0.5 * (lin.M + lin.M.transpose());
  const Eigen::MatrixXd K_raw = calcStiffness(model, equilibrium, lin.dofs);
  const double scale = n > 0 ? K_raw.cwiseAbs().maxCoeff() : 0.0;
  lin.asymmetry = scale > 0 ? (K_raw - K_raw.transpose()).cwiseAbs().maxCoeff() / scale : 0.0;
  lin.K = 0.5 * (K_raw + K_raw.transpose());
  lin.K_elastic = Eigen::MatrixXd::Zero(n, n);
  for (int i = 0; i < n; ++i) lin.K_elastic(i, i) = model.getCoordinates()[lin.dofs[i]].stiffness;
  lin.K_geometric = lin.K - lin.K_elastic;
  return lin;
}

}  // namespace mmv
