#include "sim/linearize.hpp"

namespace mmv {

Eigen::MatrixXd calcStiffness(const Model& model, const SimTK::State& s, const std::vector<int>& dofs) {
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
