#include "sim/statics/linearize.hpp"

#include "sim/core/linalg.hpp"
#include "sim/core/errors.hpp"
#include "sim/statics/closures.hpp"
#include "sim/statics/tree_operator.hpp"

#include <stdexcept>

namespace mmv {

Eigen::MatrixXd calcStiffness(const Model& model, const SimTK::State& s, const std::vector<int>& dofs) {
  return model.hasClosedFormForces() ? calcStiffnessClosedForm(model, s, dofs)
                                             : calcStiffnessByDifferences(model, s, dofs);
}

namespace {

/// The closed form's per-rotation sums over the point forces outboard of rotation k:
/// S_k = sum F . (p - o_k) and, in a spatial model, V_k = sum (F . a_k) (p - o_k),
/// with a_k the axis (world) and o_k a point on it. For rotations j inboard of or equal
/// to k, d^2 p / dq_j dq_k = a_j x (a_k x (p - o_k)), so
///     K_jk = -F . d^2 p / dq_j dq_k = (a_j . a_k) S_k - a_j . V_k
/// which is S_k (the planar G_k) when every axis is z and every force in the plane.
class GeometricTerms {
 public:
  GeometricTerms(const Model& model, const SimTK::State& s)
      : model_(model), s_(s), spatial_(model.isSpatial()), g_(model.getNumCoordinates(), 0.0),
        v_(model.getNumCoordinates(), SimTK::Vec3(0)), origin_(model.getNumCoordinates()),
        axis_(model.getNumCoordinates(), SimTK::Vec3(0, 0, 1)), rotation_(model.getNumCoordinates(), false) {
    const auto& coords = model_.getCoordinates();
    for (std::size_t k = 0; k < coords.size(); ++k) {  // each axis once, not once per body outboard of it
      rotation_[k] = coords[k].motion == CoordinateMotion::Rotation;
      if (!rotation_[k]) continue;
      const SimTK::MobilizedBody& mb = model_.getMatter().getMobilizedBody(coords[k].mobod);
      origin_[k] = mb.getBodyOriginLocation(s_);
      if (spatial_) axis_[k] = mb.getHCol(s_, SimTK::MobilizerUIndex(coords[k].mobilizer_q))[0];
    }
  }

  void add(int body, const SimTK::Vec3& p_W, const SimTK::Vec3& F_W) {
    for (int k : model_.getAncestorCoordinates(body)) {
      if (!rotation_[k]) continue;
      const SimTK::Vec3 r = p_W - origin_[k];
      g_[k] += ~F_W * r;
      if (spatial_) v_[k] += (~F_W * axis_[k]) * r;
    }
  }
  void addStation(int body, const SimTK::Vec3& station_B, const SimTK::Vec3& F_W) {
    const SimTK::MobilizedBody& mb = model_.getMatter().getMobilizedBody(model_.getBodies()[body].mobod);
    add(body, mb.findStationLocationInGround(s_, station_B), F_W);
  }

  /// K_jk for rotations j inboard of or equal to k (both ways), over `dofs`.
  Eigen::MatrixXd matrix(const std::vector<int>& dofs) const {
    const auto& coords = model_.getCoordinates();
    const int n = static_cast<int>(dofs.size());
    std::vector<int> column(coords.size(), -1);  // coordinate -> row/column, -1 if held
    for (int a = 0; a < n; ++a) column[dofs[a]] = a;
    Eigen::MatrixXd K = Eigen::MatrixXd::Zero(n, n);
    for (int b = 0; b < n; ++b) {
      const int k = dofs[b];
      if (!rotation_[k]) continue;
      // Every rotation j that moves k's body is inboard of or equal to k, except the
      // later rotations of k's own mobilizer (a gimbal's): those are outboard of k.
      for (int j : model_.getAncestorCoordinates(model_.getCoordinateBody(k))) {
        const int a = column[j];
        if (a < 0 || !rotation_[j]) continue;
        if (coords[j].mobod == coords[k].mobod && coords[j].mobilizer_q > coords[k].mobilizer_q) continue;
        const double kjk = spatial_ ? (~axis_[j] * axis_[k]) * g_[k] - ~axis_[j] * v_[k] : g_[k];
        K(a, b) = kjk;
        K(b, a) = kjk;
      }
    }
    return K;
  }

 private:
  const Model& model_;
  const SimTK::State& s_;
  bool spatial_;
  std::vector<double> g_;         ///< S_k.
  std::vector<SimTK::Vec3> v_;    ///< V_k (spatial models).
  std::vector<SimTK::Vec3> origin_;  ///< o_k, world frame (rotations only).
  std::vector<SimTK::Vec3> axis_;    ///< a_k, world frame (z in a planar model).
  std::vector<bool> rotation_;
};

}  // namespace

Eigen::MatrixXd calcPointForceStiffness(const Model& model, const SimTK::State& s, const std::vector<int>& dofs,
                                        const std::vector<PointForce>& forces) {
  SimTK::State work = s;
  model.getSystem().realize(work, SimTK::Stage::Position);
  GeometricTerms terms(model, work);
  for (const auto& f : forces) terms.addStation(f.body, f.station_B, f.force_W);
  return terms.matrix(dofs);
}

Eigen::MatrixXd calcStiffnessClosedForm(const Model& model, const SimTK::State& s, const std::vector<int>& dofs,
                                        const std::vector<PointForce>& extra) {
  if (!model.hasClosedFormForces())
    throw InternalError("calcStiffnessClosedForm: the model has forces other than gravity, loads and springs");
  SimTK::State work = s;
  model.getSystem().realize(work, SimTK::Stage::Position);
  const auto& matter = model.getMatter();
  const auto& bodies = model.getBodies();
  GeometricTerms terms(model, work);
  const SimTK::Vec3 g = model.getGravity(work);
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    const SimTK::MobilizedBody& mb = matter.getMobilizedBody(bodies[b].mobod);
    terms.addStation(static_cast<int>(b), mb.getBodyMassCenterStation(work), mb.getBodyMass(work) * g);
  }
  for (const auto& load : model.getPointLoads()) terms.addStation(model.findBody(load.mobod), load.station_B, load.force_W);
  for (const auto& f : extra) terms.addStation(f.body, f.station_B, f.force_W);
  Eigen::MatrixXd K = terms.matrix(dofs);
  for (std::size_t b = 0; b < dofs.size(); ++b) K(b, b) += model.getCoordinates()[dofs[b]].stiffness;
  for (const StiffnessEntry& e : rotationSpringCoupling(model, work, dofs)) K(e.row, e.column) += e.value;
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

LinearizedModel linearize(const Model& model, const SimTK::State& equilibrium,
                          const Eigen::VectorXd& closure_multipliers) {
  LinearizedModel lin;
  lin.dofs = model.getDofs();
  const int n = static_cast<int>(lin.dofs.size());
  const int m = model.getNumClosureRows();
  Eigen::MatrixXd K_raw;
  if (m == 0 && TreeOperator::appliesTo(model)) {
    // An open tree with closed-form forces: the same matrices from the tree's recursions
    // (tree_operator.hpp; equal to Simbody's M and the closed-form K to 1e-12,
    // TreeOperator.EqualsTheDenseMatrices*), 0.6 ms against 15 ms at 256 DOF.
    const TreeOperator op(model, equilibrium, lin.dofs);
    lin.M = op.denseM();
    K_raw = op.denseK();
  } else {
    lin.M = calcMass(model, equilibrium, lin.dofs);
    K_raw = calcStiffness(model, equilibrium, lin.dofs);
  }
  symmetrize(lin.M);
  if (m > 0) {
    MMV_DEMAND(closure_multipliers.size() == m);  // one multiplier per closure row
    K_raw += calcPointForceStiffness(model, equilibrium, lin.dofs, closureForces(model, closure_multipliers));
    SimTK::State work = equilibrium;
    model.getSystem().realize(work, SimTK::Stage::Position);
    lin.G = calcClosureJacobian(model, work, lin.dofs);
  } else {
    lin.G.resize(0, n);
  }
  lin.Z = nullSpace(lin.G, n);
  const double scale = n > 0 ? K_raw.cwiseAbs().maxCoeff() : 0.0;
  lin.asymmetry = scale > 0 ? (K_raw - K_raw.transpose()).cwiseAbs().maxCoeff() / scale : 0.0;
  lin.K = 0.5 * (K_raw + K_raw.transpose());
  lin.K_elastic = Eigen::MatrixXd::Zero(n, n);
  for (int i = 0; i < n; ++i) lin.K_elastic(i, i) = model.getCoordinates()[lin.dofs[i]].stiffness;
  lin.K_geometric = lin.K - lin.K_elastic;
  return lin;
}

LinearizedModel linearizeOperators(const Model& model, const SimTK::State& equilibrium,
                                   const Eigen::VectorXd& closure_multipliers) {
  if (!TreeOperator::appliesTo(model) || static_cast<int>(model.getDofs().size()) < kTreeOperatorMinDofs)
    return linearize(model, equilibrium, closure_multipliers);
  LinearizedModel lin;
  lin.dofs = model.getDofs();
  lin.tree = std::make_shared<const TreeOperator>(model, equilibrium, lin.dofs);
  return lin;
}

void addDenseMatrices(LinearizedModel& lin) {
  if (!lin.tree || lin.M.size()) return;
  const int n = lin.tree->size();
  lin.M = lin.tree->denseM();
  lin.K = lin.tree->denseK();
  symmetrize(lin.K);  // as linearize makes it (a spatial rotation spring's coupling entries)
  lin.K_elastic = Eigen::MatrixXd(lin.tree->springs().asDiagonal());
  lin.K_geometric = lin.K - lin.K_elastic;
  lin.G.resize(0, n);
  lin.Z = Eigen::MatrixXd::Identity(n, n);
}

Eigen::MatrixXd massTimes(const LinearizedModel& lin, const Eigen::MatrixXd& V) {
  return lin.tree ? lin.tree->multiplyM(V) : Eigen::MatrixXd(lin.M * V);
}

Eigen::MatrixXd stiffnessTimes(const LinearizedModel& lin, const Eigen::MatrixXd& V) {
  return lin.tree ? lin.tree->multiplyK(V) : Eigen::MatrixXd(lin.K * V);
}

Eigen::VectorXd springDiagonal(const LinearizedModel& lin) {
  return lin.tree ? lin.tree->springs() : Eigen::VectorXd(lin.K_elastic.diagonal());
}

}  // namespace mmv
