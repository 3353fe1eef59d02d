#include "sim/time/modal_links.hpp"

#include <algorithm>
#include <cmath>

#include "sim/core/errors.hpp"
#include "sim/core/text.hpp"
#include "sim/statics/linearize.hpp"
#include "sim/time/fidelity.hpp"

namespace mmv {

namespace {

/// The viscous damping over the free coordinates `free`: the hinge dampers, and a modal
/// or Rayleigh damping matrix (Model::getLinearDamping) where the model carries one.
Eigen::MatrixXd dampingOverFree(const Model& model, const std::vector<int>& free) {
  const int n = static_cast<int>(free.size());
  Eigen::MatrixXd C = Eigen::MatrixXd::Zero(n, n);
  for (int r = 0; r < n; ++r) C(r, r) = model.getCoordinates()[free[r]].damping;
  const std::vector<int>& damped = model.getLinearDampingCoordinates();
  std::vector<int> row(damped.size(), -1);  // each damped coordinate's row in free
  for (std::size_t a = 0; a < damped.size(); ++a) {
    const auto it = std::find(free.begin(), free.end(), damped[a]);
    if (it != free.end()) row[a] = static_cast<int>(it - free.begin());
  }
  for (std::size_t a = 0; a < damped.size(); ++a)
    for (std::size_t b = 0; b < damped.size(); ++b)
      if (row[a] >= 0 && row[b] >= 0)
        C(row[a], row[b]) += model.getLinearDamping()(static_cast<Eigen::Index>(a), static_cast<Eigen::Index>(b));
  return C;
}

/// The generalized forces at the start over the free mobilities `free_u` (gravity, the
/// hinges' springs: minus the inverse dynamics' residual at rest with no acceleration),
/// the load a release applies at once; empty when no link keeps modes for a release.
Eigen::VectorXd releaseLoad(const Model& model, const ArticleSpec& article, const SimTK::State& start,
                            const std::vector<int>& free_u) {
  if (std::none_of(article.links.begin(), article.links.end(), [](const LinkSpec& l) { return l.modes_cover_release; }))
    return {};
  SimTK::State s = start;
  const SimTK::MultibodySystem& sys = model.getSystem();
  s.updU() = 0;
  sys.realize(s, SimTK::Stage::Dynamics);
  SimTK::Vector residual;
  model.getMatter().calcResidualForceIgnoringConstraints(s, sys.getMobilityForces(s, SimTK::Stage::Dynamics),
                                                         sys.getRigidBodyForces(s, SimTK::Stage::Dynamics),
                                                         SimTK::Vector(s.getNU(), 0.0), residual);
  Eigen::VectorXd f(free_u.size());
  for (std::size_t r = 0; r < free_u.size(); ++r) f[static_cast<Eigen::Index>(r)] = -residual[free_u[r]];
  return f;
}

/// Body b's transform in ground from a State realized to Position.
auto simbodyTransforms(const SimTK::SimbodyMatterSubsystem& matter, const SimTK::State& s) {
  return [&matter, &s](int b) -> const SimTK::Transform& {
    return matter.getMobilizedBody(SimTK::MobilizedBodyIndex(b)).getBodyTransform(s);
  };
}

}  // namespace

Eigen::VectorXd staticShares(const Eigen::MatrixXd& Phi, const Eigen::VectorXd& lambda, const Eigen::VectorXd& f) {
  const Eigen::VectorXd p = Phi.transpose() * f;
  Eigen::VectorXd energy = Eigen::VectorXd::Zero(lambda.size());
  for (Eigen::Index j = 0; j < lambda.size(); ++j)
    if (lambda[j] > 0) energy[j] = p[j] * p[j] / lambda[j];
  const double total = energy.sum();
  return total > 0 ? (energy / total).eval() : energy;
}

int companionModes(const Eigen::VectorXd& lambda, int kept, double factor) {
  const int h = static_cast<int>(lambda.size());
  if (!(factor > 1) || kept >= h) return kept;
  // Frequencies as the eigenvalues: omega_j <= factor omega_k when lambda_j <= factor^2 lambda_k.
  const double up_to = factor * factor * std::max(0.0, lambda[kept - 1]);
  int more = kept + 1;
  while (more < h && lambda[more] <= up_to) ++more;
  return more;
}

int modesForRelease(const Eigen::VectorXd& shares, int at_least) {
  const int h = static_cast<int>(shares.size());
  int kept = std::min(h, at_least);
  while (kept < h && shares.tail(h - kept).sum() > kReleaseStaticShare) ++kept;
  return kept;
}

ModalLinks::ModalLinks(const Model& model, const ArticleSpec& article, const SimTK::State& start)
    : model_(model), rhs_(start) {
  const auto& moved = model.getReducedMotions().mobilizers();
  for (int i = 0; i < model.getNumCoordinates(); ++i)
    if (std::find(moved.begin(), moved.end(), model.getCoordinates()[i].mobod) != moved.end()) free_.push_back(i);
  const int n = static_cast<int>(free_.size());
  start_.resize(n);
  for (int r = 0; r < n; ++r) {
    free_q_.push_back(model.getQIndex(free_[r]));
    free_u_.push_back(model.getUIndex(free_[r]));
    start_[r] = start.getQ()[free_q_[r]];
  }
  SimTK::Matrix Ms;
  model.getMatter().calcM(start, Ms);
  Eigen::MatrixXd M(n, n);
  for (int r = 0; r < n; ++r)
    for (int c = 0; c < n; ++c) M(r, c) = Ms(free_u_[r], free_u_[c]);
  // The stiffness over every free coordinate, once: each link's modes take its block,
  // and the Newton iteration's Jacobian the projection.
  Eigen::MatrixXd K = calcStiffness(model, start, free_);
  K = 0.5 * (K + K.transpose()).eval();
  const Eigen::VectorXd load = releaseLoad(model, article, start, free_u_);
  std::vector<Eigen::VectorXd> columns;
  std::vector<bool> in_a_link(n, false);
  for (const auto& l : article.links) {
    if (!l.modal()) continue;
    std::vector<int> rows;  // into free_
    for (int r = 0; r < n; ++r) {
      const Coordinate& c = model.getCoordinates()[free_[r]];
      if (c.kind == CoordinateKind::Hinge && c.part == l.name) rows.push_back(r), in_a_link[r] = true;
    }
    addLink(l, rows, M, K, load, columns);
  }
  for (int r = 0; r < n; ++r) {  // every other free coordinate is its own
    if (in_a_link[r]) continue;
    columns.push_back(Eigen::VectorXd::Unit(n, r));
  }
  T_.resize(n, static_cast<int>(columns.size()));
  for (std::size_t j = 0; j < columns.size(); ++j) T_.col(static_cast<int>(j)) = columns[j];
  // The Newton iteration's Jacobian: the stiffness and damping at the start, projected.
  const Eigen::MatrixXd C = dampingOverFree(model, free_);
  K_ = T_.transpose() * K * T_;
  C_ = T_.transpose() * C * T_;
  const int nu = start.getNU();
  udot_ = SimTK::Vector(nu, 0.0);
  v_ = SimTK::Vector(nu, 0.0);
  readBodies(model, start);
}

void ModalLinks::readBodies(const Model& model, const SimTK::State& start) {
  // The mass matrix in closed form when every free coordinate is a pin (one per
  // mobilizer) and their axes are parallel, the planar article's case; else M v products.
  // (The planar article's pins stay parallel as it moves: only the gimbal, below all
  // of them, can turn their common axis, which is read at each evaluation.)
  const SimTK::SimbodyMatterSubsystem& matter = model.getMatter();
  bodies_.assign(matter.getNumBodies(), PinBody{});
  parallel_pins_ = true;
  const int n = static_cast<int>(free_.size());
  for (int r = 0; r < n; ++r) {
    const Coordinate& c = model.getCoordinates()[free_[r]];
    const SimTK::MobilizedBody& mb = matter.getMobilizedBody(c.mobod);
    const SimTK::Vec3 a = mb.getBodyRotation(start) * mb.getOutboardFrame(start).R().z();
    if (r == 0) axis_ = a, axis_body_ = c.mobod, axis_M_ = SimTK::Vec3(mb.getOutboardFrame(start).R().z());
    if (c.motion != CoordinateMotion::Rotation || mb.getNumU(start) != 1 || (a - axis_).norm() > 1e-12)
      parallel_pins_ = false;
    bodies_[c.mobod].free_row = r;
  }
  for (int b = 1; b < matter.getNumBodies(); ++b) {
    const SimTK::MobilizedBody& mb = matter.getMobilizedBody(SimTK::MobilizedBodyIndex(b));
    PinBody& body = bodies_[b];
    body.parent = mb.getParentMobilizedBody().getMobilizedBodyIndex();
    body.pin_B = mb.getOutboardFrame(start).p();
    const SimTK::MassProperties& mp = mb.getBodyMassProperties(start);
    body.mass = mp.getMass();
    body.com_B = mp.getMassCenter();
    body.central = mp.calcCentralInertia();
  }
  // Every other mobility follows a Motion whose acceleration the builder registered.
  for (int i = 0; i < model.getNumCoordinates(); ++i) {
    const Coordinate& c = model.getCoordinates()[i];
    if (std::find(free_.begin(), free_.end(), i) != free_.end()) continue;
    const PrescribedMotion* motion = model.findPrescribedMotion(c.mobod);
    if (!motion) throw InternalError("coordinate " + c.name + " is neither free nor prescribed with a known motion");
    prescribed_.push_back({i, motion});
  }
  // The own inverse dynamics where it writes the model out and the pins are parallel
  // (its mass matrix is the closed form's).
  if (parallel_pins_ && TreeDynamics::supports(model)) {
    tree_ = std::make_unique<TreeDynamics>(model, start);
    const int nc = model.getNumCoordinates();
    q_start_.resize(nc);
    for (int i = 0; i < nc; ++i) q_start_[i] = start.getQ()[model.getQIndex(i)];
    tq_ = q_start_;
    tu_.setZero(nc);
    tudot_.setZero(nc);
  }
}

void ModalLinks::addLink(const LinkSpec& l, const std::vector<int>& rows, const Eigen::MatrixXd& M,
                         const Eigen::MatrixXd& K_free, const Eigen::VectorXd& load, std::vector<Eigen::VectorXd>& columns) {
  const int h = static_cast<int>(rows.size());
  if (h < l.modes) throw InternalError(strf("link %s: %d modes asked of %d hinges", l.name.c_str(), l.modes, h));
  Eigen::MatrixXd Mh(h, h), K(h, h);
  for (int r = 0; r < h; ++r)
    for (int c = 0; c < h; ++c) Mh(r, c) = M(rows[r], rows[c]), K(r, c) = K_free(rows[r], rows[c]);
  Eigen::LLT<Eigen::MatrixXd> chol(Mh);
  if (chol.info() != Eigen::Success)
    throw NumericalError("link " + l.name + ": its mass matrix with the root held is not positive definite");
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> eig(K, Mh);
  if (eig.info() != Eigen::Success) throw NumericalError("link " + l.name + ": its modes did not converge");
  const int n = static_cast<int>(free_.size());
  auto hz = [&](int j) { return std::sqrt(std::max(0.0, eig.eigenvalues()[j])) / (2 * M_PI); };
  int kept = l.modes;
  Eigen::VectorXd share;  // a release's static shares
  if (kept <= 0) {  // the default fidelity's rule (sim/time/fidelity.hpp): up to the cutoff, at least the minimum
    kept = std::min(h, kFidelityMinModes);
    while (kept < h && hz(kept) <= *l.modes_up_to_hz) ++kept;
    if (l.modes_cover_release) {  // and what the release's step needs
      Eigen::VectorXd f(h);
      for (int r = 0; r < h; ++r) f[r] = load[rows[r]];
      share = staticShares(eig.eigenvectors(), eig.eigenvalues(), f);
      kept = modesForRelease(share, kept);
    }
  }
  kept = companionModes(eig.eigenvalues(), kept, l.modes_frequency_factor);
  std::optional<double> release_left;
  if (share.size() > 0) release_left = share.tail(h - kept).sum();
  for (int j = 0; j < kept; ++j) {
    Eigen::VectorXd col = Eigen::VectorXd::Zero(n);
    for (int r = 0; r < h; ++r) col[rows[r]] = eig.eigenvectors()(r, j);  // M-normalized
    columns.push_back(col);
  }
  summary_.push_back({l.name, kept, h, hz(kept - 1), kept < h ? hz(kept) : 0.0, release_left});
}

void ModalLinks::project(const SimTK::State& s, double* y) const {
  const int n = static_cast<int>(free_.size()), k = static_cast<int>(T_.cols());
  Eigen::VectorXd dq(n), u(n);
  for (int r = 0; r < n; ++r) dq[r] = s.getQ()[free_q_[r]] - start_[r], u[r] = s.getU()[free_u_[r]];
  const auto qr = T_.colPivHouseholderQr();
  Eigen::Map<Eigen::VectorXd>(y, k) = qr.solve(dq);
  Eigen::Map<Eigen::VectorXd>(y + k, k) = qr.solve(u);
}

void ModalLinks::load(double t, const double* y, SimTK::State& s, double* ydot, bool full) const {
  const int k = static_cast<int>(T_.cols());
  // A right-hand side in a State of its own without the reduced Motions; a sample in the
  // run's State, whose reduced Motions then take the accelerations, realized to
  // Acceleration (outputs, motion forces, energy).
  // A sample whose accelerations the own inverse dynamics gave realizes Dynamics once,
  // after they are set (Simbody's path realized it for the residual, and setting them
  // invalidated it).
  accelerations(t, y, full ? s : rhs_);
  for (int j = 0; j < k; ++j) ydot[j] = y[k + j], ydot[k + j] = a_[j];
  if (!full) return;
  if (tree_) setState(t, y, s);
  const int n = static_cast<int>(free_.size());
  x_.noalias() = T_ * a_;
  for (int r = 0; r < n; ++r) udot_[free_u_[r]] = x_[r];
  model_.getReducedMotions().setAccelerations(s, udot_);
  for (int r = 0; r < n; ++r) udot_[free_u_[r]] = 0.0;
  model_.getSystem().realize(s, SimTK::Stage::Acceleration);
}

bool ModalLinks::jacobian(double t, const double* y, double* J) const {
  // dy'/dy ~ [0 I; -G^-1 K  -G^-1 C] with G at y: the springs and dampers dominate the
  // stiff part; the velocity-dependent inertial terms and the change of G are left out.
  accelerations(t, y, rhs_);
  const int k = static_cast<int>(T_.cols());
  Eigen::Map<Eigen::MatrixXd> Jm(J, 2 * k, 2 * k);
  Jm.setZero();
  Jm.topRightCorner(k, k).setIdentity();
  const Eigen::LLT<Eigen::MatrixXd> llt(G_);
  Jm.bottomLeftCorner(k, k) = -llt.solve(K_);
  Jm.bottomRightCorner(k, k) = -llt.solve(C_);
  return true;
}

void ModalLinks::ownResidual(double t, const double* y) const {
  const int n = static_cast<int>(free_.size()), k = static_cast<int>(T_.cols());
  const Eigen::Map<const Eigen::VectorXd> q(y, k), u(y + k, k);
  x_.noalias() = T_ * q;
  for (int r = 0; r < n; ++r) tq_[free_[r]] = start_[r] + x_[r];
  x_.noalias() = T_ * u;
  for (int r = 0; r < n; ++r) tu_[free_[r]] = x_[r], tudot_[free_[r]] = 0.0;
  for (const auto& [i, motion] : prescribed_) {
    if (motion->q) tq_[i] = motion->q(t), tu_[i] = motion->u(t);
    tudot_[i] = motion->udot(t);
  }
  tree_->residual(t, tq_, tu_, tudot_, tr_);
  for (int r = 0; r < n; ++r) x_[r] = -tr_[free_[r]];
}

void ModalLinks::setState(double t, const double* y, SimTK::State& s) const {
  const SimTK::MultibodySystem& sys = model_.getSystem();
  const int n = static_cast<int>(free_.size()), k = static_cast<int>(T_.cols());
  const Eigen::Map<const Eigen::VectorXd> q(y, k), u(y + k, k);
  x_.noalias() = T_ * q;
  s.setTime(t);
  SimTK::Vector& Q = s.updQ();
  for (int r = 0; r < n; ++r) Q[free_q_[r]] = start_[r] + x_[r];
  x_.noalias() = T_ * u;
  SimTK::Vector& U = s.updU();
  for (int r = 0; r < n; ++r) U[free_u_[r]] = x_[r];
  sys.realize(s, SimTK::Stage::Time);
  sys.prescribeQ(s);
  sys.realize(s, SimTK::Stage::Position);
  sys.prescribeU(s);
}

void ModalLinks::accelerations(double t, const double* y, SimTK::State& s, bool own) const {
  const int k = static_cast<int>(T_.cols());
  if (own && tree_) {
    ownResidual(t, y);
    b_.noalias() = T_.transpose() * x_;
    planarMassMatrix([&](int b) -> const SimTK::Transform& { return tree_->bodyTransform(b); });
    a_ = G_.llt().solve(b_);
    return;
  }
  const SimTK::MultibodySystem& sys = model_.getSystem();
  const SimTK::SimbodyMatterSubsystem& matter = model_.getMatter();
  const int n = static_cast<int>(free_.size());
  setState(t, y, s);
  // The residual M udot + c - f of the inverse dynamics with the reduced accelerations
  // zero and the prescribed ones as commanded: O(n), no forward dynamics (it ignores
  // Motions, so `s` may have the reduced ones enabled).
  for (const auto& [i, motion] : prescribed_) udot_[model_.getUIndex(i)] = motion->udot(t);
  sys.realize(s, SimTK::Stage::Dynamics);
  matter.calcResidualForceIgnoringConstraints(s, sys.getMobilityForces(s, SimTK::Stage::Dynamics),
                                              sys.getRigidBodyForces(s, SimTK::Stage::Dynamics), udot_, f_);
  b_.resize(k);
  G_.resize(k, k);
  x_.resize(n);
  for (int r = 0; r < n; ++r) x_[r] = -f_[free_u_[r]];
  b_.noalias() = T_.transpose() * x_;
  if (parallel_pins_) planarMassMatrix(simbodyTransforms(matter, s));
  else productsMassMatrix(s);
  // T^T (r0 + M T a) = 0: the projected forces do no work on the reduced coordinates.
  a_ = G_.llt().solve(b_);
}

void ModalLinks::productsMassMatrix(const SimTK::State& s) const {
  const int n = static_cast<int>(free_.size()), k = static_cast<int>(T_.cols());
  G_.resize(k, k);
  x_.resize(n);
  for (int j = 0; j < k; ++j) {
    for (int r = 0; r < n; ++r) v_[free_u_[r]] = T_(r, j);
    model_.getMatter().multiplyByM(s, v_, Mv_);
    for (int r = 0; r < n; ++r) x_[r] = Mv_[free_u_[r]];
    G_.col(j).noalias() = T_.transpose() * x_;
  }
  for (int r = 0; r < n; ++r) v_[free_u_[r]] = 0.0;
}

std::pair<Eigen::MatrixXd, Eigen::MatrixXd> ModalLinks::massMatrices(double t, const double* y) const {
  accelerations(t, y, rhs_, false);
  std::pair<Eigen::MatrixXd, Eigen::MatrixXd> out;
  if (parallel_pins_) {
    planarMassMatrix(simbodyTransforms(model_.getMatter(), rhs_));
    out.first = G_;
  }
  productsMassMatrix(rhs_);
  out.second = G_;
  return out;
}

template <class BodyTransform>
void ModalLinks::planarMassMatrix(const BodyTransform& X) const {
  // Free pins with one axis a through points o_i: a unit rate of reduced coordinate j
  // turns body b at S_bj = sum_i T_ij (i: its free ancestors and itself) and moves its
  // mass centre p_b at a x (p_b S_bj - P_bj), P_bj = sum_i T_ij o_i; both accumulate
  // outward. G = sum_b m_b v_b^T v_b + (a^T I_b a) S_b^T S_b = A^T A.
  const int k = static_cast<int>(T_.cols()), nb = static_cast<int>(bodies_.size());
  S_.setZero(nb, k);
  P_.setZero(3 * nb, k);
  A_.setZero(4 * nb, k);
  const SimTK::Vec3 axis_G = X(axis_body_).R() * axis_M_;
  const Eigen::Vector3d axis(axis_G[0], axis_G[1], axis_G[2]);
  for (int b = 1; b < nb; ++b) {  // parents come before children
    const PinBody& body = bodies_[b];
    const SimTK::Transform& X_GB = X(b);
    S_.row(b) = S_.row(body.parent);
    P_.middleRows(3 * b, 3) = P_.middleRows(3 * body.parent, 3);
    if (body.free_row >= 0) {
      const SimTK::Vec3 o = X_GB * body.pin_B;
      S_.row(b) += T_.row(body.free_row);
      for (int c = 0; c < 3; ++c) P_.row(3 * b + c) += o[c] * T_.row(body.free_row);
    }
    if (!(body.mass > 0)) continue;
    const SimTK::Vec3 p = X_GB * body.com_B;
    const SimTK::Vec3 a_B = ~X_GB.R() * axis_G;
    const double Ia = std::max(0.0, ~a_B * (body.central * a_B));
    const Eigen::Vector3d pe(p[0], p[1], p[2]);
    const double sm = std::sqrt(body.mass);
    for (int j = 0; j < k; ++j) {
      const Eigen::Vector3d d = pe * S_(b, j) - P_.block<3, 1>(3 * b, j);
      A_.block<3, 1>(4 * b, j) = sm * axis.cross(d);
    }
    A_.row(4 * b + 3) = std::sqrt(Ia) * S_.row(b);
  }
  G_.noalias() = A_.transpose() * A_;
}

}  // namespace mmv
