// M and K of an open tree as O(n) operators and their O(n) factorization
// (tree_operator.hpp).
#include "sim/statics/tree_operator.hpp"

#include <algorithm>

#include "sim/core/errors.hpp"
#include "sim/model/rotation_spring.hpp"

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
  if (!model.getClosures().empty() || !model.hasClosedFormForces()) return false;
  std::vector<int> on(static_cast<std::size_t>(model.getMatter().getNumBodies()), 0);  // coordinates a mobilizer
  for (const Coordinate& c : model.getCoordinates())
    if (++on[c.mobod] > kMaxNodeDofs) return false;
  return true;
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
  std::vector<int> node_of(n, -1);
  for (SimTK::MobilizedBodyIndex mbx(1); mbx < matter.getNumBodies(); ++mbx) {
    const SimTK::MobilizedBody& mb = matter.getMobilizedBody(mbx);
    int inboard = last[mb.getParentMobilizedBody().getMobilizedBodyIndex()];
    if (!own[mbx].empty()) {
      nodes_.push_back({own[mbx], inboard < 0 ? -1 : node_of[inboard]});
      for (int a : own[mbx]) node_of[a] = static_cast<int>(nodes_.size()) - 1;
    }
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
  coupling_ = rotationSpringCoupling(model, s, dofs);
  buildSpringBlocks(node_of);
  mass_composite_ = mass_;
  stiff_composite_ = stiff_;
  for (auto it = order_.rbegin(); it != order_.rend(); ++it)
    if (const int p = parent_[*it]; p >= 0) {
      mass_composite_[p] += mass_composite_[*it];
      stiff_composite_[p] += stiff_composite_[*it];
    }
}

void TreeOperator::buildSpringBlocks(const std::vector<int>& node_of) {
  std::vector<int> slot(size(), -1);  // a degree of freedom's place in its node
  for (const Node& node : nodes_)
    for (std::size_t k = 0; k < node.dofs.size(); ++k) slot[node.dofs[k]] = static_cast<int>(k);
  for (const Node& node : nodes_) {
    const int m = static_cast<int>(node.dofs.size());
    spring_blocks_.push_back(NodeBlock::Zero(m, m));
    for (int k = 0; k < m; ++k) spring_blocks_.back()(k, k) = spring_[node.dofs[k]];
  }
  for (const StiffnessEntry& c : coupling_) {
    MMV_DEMAND(node_of[c.row] == node_of[c.column]);  // a gimbal's angles share one mobilizer
    spring_blocks_[node_of[c.row]](slot[c.row], slot[c.column]) += c.value;
  }
}

std::vector<StiffnessEntry> rotationSpringCoupling(const Model& model, const SimTK::State& s, const std::vector<int>& dofs) {
  std::vector<int> column(model.getNumCoordinates(), -1);
  for (std::size_t a = 0; a < dofs.size(); ++a) column[dofs[a]] = static_cast<int>(a);
  const Eigen::VectorXd q = model.getQ(s);
  std::vector<StiffnessEntry> out;
  for (const RotationSpring& r : model.getRotationSprings()) {
    const SimTK::Mat33 H = rotationSpringHessian(SimTK::Vec3(q[r.coords[0]], q[r.coords[1]], q[r.coords[2]]), r.k);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        const int a = column[r.coords[i]], b = column[r.coords[j]];
        const double v = H(i, j) - (i == j ? r.k[i] : 0.0);
        if (a >= 0 && b >= 0 && v != 0) out.push_back({a, b, v});
      }
  }
  return out;
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
  if (diag)  // K: the springs' coupling with them
    for (const StiffnessEntry& c : coupling_) y[c.row] += c.value * x[c.column];
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
  for (const StiffnessEntry& c : coupling_)
    if (c.row == c.column) d[c.row] += c.value;
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
  if (diag)
    for (const StiffnessEntry& c : coupling_) A(c.row, c.column) += c.value;
  return A;
}
Eigen::MatrixXd TreeOperator::denseM() const { return dense(mass_composite_, nullptr); }
Eigen::MatrixXd TreeOperator::denseK() const { return dense(stiff_composite_, &spring_); }

TreeFactor TreeOperator::factor(double sigma) const {
  const int n = size();
  const std::size_t nn = nodes_.size();
  TreeFactor f(*this);
  f.u_.resize(nn);
  f.g_.resize(nn);
  f.inverse_.resize(nn);
  f.vectors_.resize(nn);
  f.values_.resize(nn);
  f.pivot_.setZero(n);
  std::vector<Matrix6d> articulated(nn, Matrix6d::Zero());
  for (std::size_t i = 0; i < nn; ++i)
    for (int j : nodes_[i].dofs) articulated[i] += stiff_[j] - sigma * mass_[j];
  std::vector<NodeBlock> blocks = spring_blocks_;
  for (std::size_t r = nn; r-- > 0;) {
    const Node& node = nodes_[r];
    const int m = static_cast<int>(node.dofs.size());
    NodeAxes S(6, m);
    for (int k = 0; k < m; ++k) S.col(k) = axis_[node.dofs[k]];
    f.u_[r] = articulated[r] * S;
    // D from the upper triangle of S^T IA S: row j inboard of column k (tree_operator.hpp).
    const NodeBlock B = S.transpose() * f.u_[r];
    NodeBlock& D = blocks[r];
    for (int j = 0; j < m; ++j)
      for (int k = j; k < m; ++k) {
        D(j, k) += B(j, k);
        if (k != j) D(k, j) += B(j, k);
      }
    const Eigen::SelfAdjointEigenSolver<NodeBlock> es(D);
    f.vectors_[r] = es.eigenvectors();
    f.values_[r] = es.eigenvalues();
    for (int k = 0; k < m; ++k) f.pivot_[node.dofs[k]] = f.values_[r][k];
    if (!(f.values_[r].cwiseAbs().minCoeff() > 0) || !f.values_[r].allFinite()) {
      f.invertible_ = false;  // the pivots stay a count of the inertia up to here; solve is refused
      continue;
    }
    f.inverse_[r] = f.vectors_[r] * f.values_[r].cwiseInverse().asDiagonal() * f.vectors_[r].transpose();
    f.g_[r] = f.u_[r] * f.inverse_[r];
    if (node.parent >= 0) articulated[node.parent] += articulated[r] - f.g_[r] * f.u_[r].transpose();
  }
  return f;
}

int TreeFactor::negativePivots() const { return static_cast<int>((pivot_.array() < 0).count()); }

NodeVector TreeFactor::gather(const Eigen::VectorXd& v, std::size_t node) const {
  const auto& dofs = op_->nodes_[node].dofs;
  NodeVector s(static_cast<Eigen::Index>(dofs.size()));
  for (std::size_t k = 0; k < dofs.size(); ++k) s[static_cast<Eigen::Index>(k)] = v[dofs[k]];
  return s;
}

void TreeFactor::scatter(const NodeVector& s, std::size_t node, Eigen::VectorXd& v) const {
  const auto& dofs = op_->nodes_[node].dofs;
  for (std::size_t k = 0; k < dofs.size(); ++k) v[dofs[k]] = s[static_cast<Eigen::Index>(k)];
}

Eigen::VectorXd TreeFactor::forward(const Eigen::VectorXd& r) const {
  const TreeOperator& op = *op_;
  const std::size_t nn = op.nodes_.size();
  MMV_DEMAND(invertible_ && r.size() == op.size());
  std::vector<Vector6d> bias(nn, Vector6d::Zero());
  Eigen::VectorXd z(op.size());
  for (std::size_t i = nn; i-- > 0;) {
    const auto& dofs = op.nodes_[i].dofs;
    NodeVector zi = gather(r, i);
    for (std::size_t k = 0; k < dofs.size(); ++k) zi[static_cast<Eigen::Index>(k)] -= op.axis_[dofs[k]].dot(bias[i]);
    scatter(zi, i, z);
    if (const int p = op.nodes_[i].parent; p >= 0)
      bias[p] += bias[i] + g_[i] * zi;
  }
  return z;
}

Eigen::VectorXd TreeFactor::backward(const Eigen::VectorXd& w) const {
  const TreeOperator& op = *op_;
  const std::size_t nn = op.nodes_.size();
  MMV_DEMAND(invertible_ && w.size() == op.size());
  std::vector<Vector6d> a(nn);
  Eigen::VectorXd x(op.size());
  for (std::size_t i = 0; i < nn; ++i) {
    const int p = op.nodes_[i].parent;
    const Vector6d inboard = p >= 0 ? a[p] : Vector6d::Zero();
    const NodeVector xi = gather(w, i) - g_[i].transpose() * inboard;  // D^-1 U^T a: D is symmetric
    scatter(xi, i, x);
    a[i] = inboard;
    const auto& dofs = op.nodes_[i].dofs;
    for (std::size_t k = 0; k < dofs.size(); ++k) a[i] += op.axis_[dofs[k]] * xi[static_cast<Eigen::Index>(k)];
  }
  return x;
}

Eigen::VectorXd TreeFactor::halfInverse(const Eigen::VectorXd& z) const {
  Eigen::VectorXd y(z.size());
  for (std::size_t i = 0; i < vectors_.size(); ++i)
    scatter(values_[i].cwiseSqrt().cwiseInverse().asDiagonal() * (vectors_[i].transpose() * gather(z, i)), i, y);
  return y;
}

Eigen::VectorXd TreeFactor::halfInverseTransposed(const Eigen::VectorXd& y) const {
  Eigen::VectorXd z(y.size());
  for (std::size_t i = 0; i < vectors_.size(); ++i)
    scatter(vectors_[i] * (values_[i].cwiseSqrt().cwiseInverse().asDiagonal() * gather(y, i)), i, z);
  return z;
}

Eigen::VectorXd TreeFactor::solve(const Eigen::VectorXd& r) const {
  Eigen::VectorXd z = forward(r);
  for (std::size_t i = 0; i < vectors_.size(); ++i)
    scatter(inverse_[i] * gather(z, i), i, z);
  return backward(z);
}

}  // namespace mmv
