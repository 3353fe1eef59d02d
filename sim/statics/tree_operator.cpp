// M and K of an open tree as O(n) operators and their O(n) factorization
// (tree_operator.hpp).
#include "sim/statics/tree_operator.hpp"

#include <algorithm>

#include "sim/core/errors.hpp"

namespace mmv {
namespace {

Eigen::Matrix3d cross(const SimTK::Vec3& v) {
  Eigen::Matrix3d m;
  m << 0, -v[2], v[1], v[2], 0, -v[0], -v[1], v[0], 0;
  return m;
}

Eigen::Vector3d toEigen(const SimTK::Vec3& v) { return {v[0], v[1], v[2]}; }

/// Spatial inertia about the world origin, acting on (w; v_O): mass m, mass centre c,
/// central inertia Ic (world axes).
Matrix6d spatialInertia(double m, const SimTK::Vec3& c, const Eigen::Matrix3d& Ic) {
  const Eigen::Matrix3d cx = cross(c);
  Matrix6d I;
  I.topLeftCorner<3, 3>() = Ic + m * cx * cx.transpose();
  I.topRightCorner<3, 3>() = m * cx;
  I.bottomLeftCorner<3, 3>() = m * cx.transpose();
  I.bottomRightCorner<3, 3>() = m * Eigen::Matrix3d::Identity();
  return I;
}

/// X of a constant world force f at p (tree_operator.hpp): K_jk = S_j^T X S_k.
Matrix6d forceStiffness(const SimTK::Vec3& p, const SimTK::Vec3& f) {
  const Eigen::Vector3d pe = toEigen(p), fe = toEigen(f);
  Matrix6d X = Matrix6d::Zero();
  X.topLeftCorner<3, 3>() = pe.dot(fe) * Eigen::Matrix3d::Identity() - pe * fe.transpose();
  X.topRightCorner<3, 3>() = cross(f);
  return X;
}

}  // namespace

bool TreeOperator::appliesTo(const Model& model) {
  return model.getClosures().empty() && model.hasClosedFormForces() && model.getRotationSprings().empty();
}

TreeOperator::TreeOperator(const Model& model, const SimTK::State& state, const std::vector<int>& dofs) {
  MMV_DEMAND(appliesTo(model));
  SimTK::State s = state;  // a copied State must be realized again
  model.getSystem().realize(s, SimTK::Stage::Position);
  const auto& coords = model.getCoordinates();
  const auto& matter = model.getMatter();
  const int n = static_cast<int>(dofs.size());
  // Per mobilizer, its degrees of freedom inboard first: translations before rotations,
  // then in q order. The deepest one at or inboard of each mobilized body (bodies come
  // after their parents in Simbody's numbering).
  auto rank = [&](int c) { return std::make_pair(coords[c].motion == CoordinateMotion::Rotation, coords[c].mobilizer_q); };
  std::vector<std::vector<int>> own(matter.getNumBodies());
  for (int a = 0; a < n; ++a) own[coords[dofs[a]].mobod].push_back(a);
  for (auto& list : own)
    std::sort(list.begin(), list.end(), [&](int x, int y) { return rank(dofs[x]) < rank(dofs[y]); });
  std::vector<int> last(matter.getNumBodies(), -1);
  axis_.resize(n);
  parent_.resize(n);
  spring_.resize(n);
  for (SimTK::MobilizedBodyIndex mbx(1); mbx < matter.getNumBodies(); ++mbx) {
    const SimTK::MobilizedBody& mb = matter.getMobilizedBody(mbx);
    int inboard = last[mb.getParentMobilizedBody().getMobilizedBodyIndex()];
    for (int a : own[mbx]) {
      const Coordinate& c = coords[dofs[a]];
      const SimTK::SpatialVec h = mb.getHCol(s, SimTK::MobilizerUIndex(c.mobilizer_q));
      const SimTK::Vec3 vO = h[1] - h[0] % mb.getBodyOriginLocation(s);  // v at the world origin
      axis_[a] << h[0][0], h[0][1], h[0][2], vO[0], vO[1], vO[2];
      parent_[a] = inboard;
      spring_[a] = c.stiffness;
      order_.push_back(a);  // after its parent
      inboard = a;
    }
    last[mbx] = inboard;
  }

  mass_.assign(n, Matrix6d::Zero());
  stiff_.assign(n, Matrix6d::Zero());
  const SimTK::Vec3 g = model.getGravity(s);
  const auto& bodies = model.getBodies();
  std::vector<int> attached(bodies.size(), -1);
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    const int j = attached[b] = last[bodies[b].mobod];
    if (j < 0) continue;  // held still: in no row of M or K
    const SimTK::MobilizedBody& mb = matter.getMobilizedBody(bodies[b].mobod);
    const SimTK::MassProperties mp = mb.getBodyMassProperties(s);
    const SimTK::Rotation R = mb.getBodyRotation(s);
    const SimTK::Mat33 Ic = R * mp.calcCentralInertia().toMat33() * ~R;
    Eigen::Matrix3d ic;
    for (int r = 0; r < 3; ++r)
      for (int k = 0; k < 3; ++k) ic(r, k) = Ic(r, k);
    const SimTK::Vec3 com = mb.findStationLocationInGround(s, mp.getMassCenter());
    mass_[j] += spatialInertia(mp.getMass(), com, ic);
    stiff_[j] += forceStiffness(com, mp.getMass() * g);
  }
  for (const auto& load : model.getPointLoads()) {
    const int b = model.findBody(load.mobod);
    if (b < 0 || attached[b] < 0) continue;
    const SimTK::MobilizedBody& mb = matter.getMobilizedBody(load.mobod);
    stiff_[attached[b]] += forceStiffness(mb.findStationLocationInGround(s, load.station_B), load.force_W);
  }
  mass_composite_ = mass_;
  stiff_composite_ = stiff_;
  for (auto it = order_.rbegin(); it != order_.rend(); ++it)
    if (const int p = parent_[*it]; p >= 0) {
      mass_composite_[p] += mass_composite_[*it];
      stiff_composite_[p] += stiff_composite_[*it];
    }
}

Eigen::VectorXd TreeOperator::apply(const std::vector<Matrix6d>& own, const std::vector<Matrix6d>& composite,
                                    const Eigen::VectorXd* diag, const Eigen::VectorXd& x) const {
  const int n = size();
  MMV_DEMAND(x.size() == n);
  std::vector<Vector6d> a(n), inboard(n), force(n);
  for (int j : order_) {  // a_j = sum of S_k x_k over the path; inboard: the parent's
    inboard[j] = parent_[j] >= 0 ? a[parent_[j]] : Vector6d::Zero();
    a[j] = inboard[j] + axis_[j] * x[j];
    force[j] = own[j] * a[j];
  }
  for (auto it = order_.rbegin(); it != order_.rend(); ++it)
    if (const int p = parent_[*it]; p >= 0) force[p] += force[*it];
  // y_j = k_j x_j + S_j^T (F_j - C_j a_parent) + (C_j S_j)^T a_parent: the first
  // product covers k outboard of or at j, the second k inboard of j (tree_operator.hpp).
  Eigen::VectorXd y(n);
  for (int j = 0; j < n; ++j)
    y[j] = axis_[j].dot(force[j] - composite[j] * inboard[j]) + (composite[j] * axis_[j]).dot(inboard[j]) +
           (diag ? (*diag)[j] * x[j] : 0.0);
  return y;
}

Eigen::VectorXd TreeOperator::multiplyM(const Eigen::VectorXd& x) const { return apply(mass_, mass_composite_, nullptr, x); }
Eigen::VectorXd TreeOperator::multiplyK(const Eigen::VectorXd& x) const {
  return apply(stiff_, stiff_composite_, &spring_, x);
}
Eigen::MatrixXd TreeOperator::multiplyM(const Eigen::MatrixXd& X) const {
  Eigen::MatrixXd Y(X.rows(), X.cols());
  for (Eigen::Index c = 0; c < X.cols(); ++c) Y.col(c) = multiplyM(Eigen::VectorXd(X.col(c)));
  return Y;
}
Eigen::MatrixXd TreeOperator::multiplyK(const Eigen::MatrixXd& X) const {
  Eigen::MatrixXd Y(X.rows(), X.cols());
  for (Eigen::Index c = 0; c < X.cols(); ++c) Y.col(c) = multiplyK(Eigen::VectorXd(X.col(c)));
  return Y;
}

Eigen::VectorXd TreeOperator::diagonalM() const {
  Eigen::VectorXd d(size());
  for (int j = 0; j < size(); ++j) d[j] = axis_[j].dot(mass_composite_[j] * axis_[j]);
  return d;
}
Eigen::VectorXd TreeOperator::diagonalK() const {
  Eigen::VectorXd d(size());
  for (int j = 0; j < size(); ++j) d[j] = spring_[j] + axis_[j].dot(stiff_composite_[j] * axis_[j]);
  return d;
}

Eigen::MatrixXd TreeOperator::dense(const std::vector<Matrix6d>& composite, const Eigen::VectorXd* diag) const {
  const int n = size();
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(n, n);
  for (int k = 0; k < n; ++k) {
    const Vector6d u = composite[k] * axis_[k];
    for (int j = k; j >= 0; j = parent_[j]) A(j, k) = A(k, j) = axis_[j].dot(u);
    if (diag) A(k, k) += (*diag)[k];
  }
  return A;
}
Eigen::MatrixXd TreeOperator::denseM() const { return dense(mass_composite_, nullptr); }
Eigen::MatrixXd TreeOperator::denseK() const { return dense(stiff_composite_, &spring_); }

TreeFactor TreeOperator::factor(double sigma) const {
  const int n = size();
  TreeFactor f(*this);
  f.u_.resize(n);
  f.pivot_.resize(n);
  std::vector<Matrix6d> articulated(n);
  for (int j = 0; j < n; ++j) articulated[j] = stiff_[j] - sigma * mass_[j];
  for (auto it = order_.rbegin(); it != order_.rend(); ++it) {
    const int j = *it;
    f.u_[j] = articulated[j] * axis_[j];
    const double d = f.pivot_[j] = spring_[j] + axis_[j].dot(f.u_[j]);
    if (!(d != 0) || !std::isfinite(d)) {
      f.invertible_ = false;
      f.pivot_[j] = 0;
      continue;  // the pivots stay a count of the inertia up to here; solve is refused
    }
    if (const int p = parent_[j]; p >= 0) articulated[p] += articulated[j] - f.u_[j] * f.u_[j].transpose() / d;
  }
  return f;
}

int TreeFactor::negativePivots() const { return static_cast<int>((pivot_.array() < 0).count()); }

Eigen::VectorXd TreeFactor::forward(const Eigen::VectorXd& r) const {
  const TreeOperator& op = *op_;
  const int n = op.size();
  MMV_DEMAND(invertible_ && r.size() == n);
  std::vector<Vector6d> bias(n, Vector6d::Zero());
  Eigen::VectorXd z(n);
  for (auto it = op.order_.rbegin(); it != op.order_.rend(); ++it) {
    const int j = *it;
    z[j] = r[j] - op.axis_[j].dot(bias[j]);
    if (const int p = op.parent_[j]; p >= 0) bias[p] += bias[j] + u_[j] * (z[j] / pivot_[j]);
  }
  return z;
}

Eigen::VectorXd TreeFactor::backward(const Eigen::VectorXd& w) const {
  const TreeOperator& op = *op_;
  const int n = op.size();
  MMV_DEMAND(invertible_ && w.size() == n);
  std::vector<Vector6d> a(n);
  Eigen::VectorXd x(n);
  for (int j : op.order_) {
    const int p = op.parent_[j];
    const Vector6d inboard = p >= 0 ? a[p] : Vector6d::Zero();
    x[j] = w[j] - u_[j].dot(inboard) / pivot_[j];
    a[j] = inboard + op.axis_[j] * x[j];
  }
  return x;
}

Eigen::VectorXd TreeFactor::solve(const Eigen::VectorXd& r) const {
  return backward(forward(r).cwiseQuotient(pivot_));
}

}  // namespace mmv
