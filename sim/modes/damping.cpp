#include "sim/modes/damping.hpp"

#include <algorithm>
#include <cmath>
#include <complex>

#include "sim/core/errors.hpp"
#include "sim/core/text.hpp"

namespace mmv {

Eigen::VectorXd hingeDampers(const Model& model, const std::vector<int>& dofs, double hinge_beta_s) {
  Eigen::VectorXd c(dofs.size());
  for (std::size_t a = 0; a < dofs.size(); ++a) {
    const Coordinate& co = model.getCoordinates()[dofs[a]];
    c[a] = co.kind == CoordinateKind::Hinge ? hinge_beta_s * co.stiffness : 0.0;
  }
  return c;
}

namespace {

/// Phi^T C Phi over the modes held, for the damping model.
Eigen::MatrixXd projectedDamping(const Model& model, const LinearizedModel& lin, const ModalSolution& modes,
                                 const DampingSpec& d) {
  const Eigen::MatrixXd& P = modes.shapes;
  const Eigen::Index m = P.cols();
  switch (d.kind) {
    case DampingSpec::Kind::Modal: {
      Eigen::VectorXd c(m);
      for (Eigen::Index k = 0; k < m; ++k) c[k] = 2 * d.modal_ratio * std::sqrt(std::max(modes.omega2[k], 0.0));
      return c.asDiagonal();
    }
    case DampingSpec::Kind::Rayleigh: {
      Eigen::MatrixXd c = Eigen::MatrixXd::Identity(m, m) * d.alpha;
      c.diagonal() += d.beta * modes.omega2;
      return c;
    }
    case DampingSpec::Kind::HingeViscous:
      return P.transpose() * hingeDampers(model, lin.dofs, d.hinge_beta).asDiagonal() * P;
  }
  return Eigen::MatrixXd::Zero(m, m);
}

}  // namespace

ModalDamping modalDamping(const Model& model, const LinearizedModel& lin, const ModalSolution& all_modes,
                          const DampingSpec& damping, int count) {
  MMV_DEMAND(count >= 0 && count <= all_modes.shapes.cols());
  // The basis: every mode held, up to kMaxDampingBasis (a dense nonsymmetric eigenproblem
  // of twice its size); past that the lowest kMaxDampingBasis, and ratios for the lower half.
  ModalSolution modes = all_modes;
  if (modes.shapes.cols() > kMaxDampingBasis) {
    modes.shapes = all_modes.shapes.leftCols(kMaxDampingBasis);
    modes.omega2 = all_modes.omega2.head(kMaxDampingBasis);
    count = std::min(count, kMaxDampingBasis / 2);
  }
  const Eigen::Index m = modes.shapes.cols();
  ModalDamping out;
  out.basis_modes = static_cast<int>(m);
  out.exact = m == static_cast<Eigen::Index>(lin.Z.cols() > 0 ? lin.Z.cols() : lin.dofs.size());
  if (m == 0) return out;
  const Eigen::MatrixXd Ct = projectedDamping(model, lin, modes, damping);
  if (damping.kind != DampingSpec::Kind::HingeViscous) {
    // Modal and Rayleigh damping are diagonal over the modes: each mode is its own
    // oscillator, lambda^2 + c lambda + omega^2 = 0, no eigen solution needed (it cost
    // the most of a 64-segment frf: a 2m x 2m nonsymmetric problem, m up to 400).
    for (int k = 0; k < count; ++k) {
      const double w = std::sqrt(std::max(modes.omega2[k], 0.0)), c = Ct(k, k);
      if (modes.isRigidBody(k) || !modes.isStable(k)) {
        out.ratio.push_back(0.0);
        out.natural_hz.push_back(modes.frequencyHz(k));
      } else if (c < 2 * w) {  // underdamped: |lambda| = omega, zeta = c / (2 omega)
        out.ratio.push_back(c / (2 * w));
        out.natural_hz.push_back(w / (2 * M_PI));
      } else {  // overdamped: two real roots; the slower one, which the decay shows
        out.ratio.push_back(1.0);
        out.natural_hz.push_back(w * w / (c / 2 + std::sqrt(std::max(c * c / 4 - w * w, 0.0))) / (2 * M_PI));
      }
    }
    return out;
  }
  // First-order form of lambda^2 y + lambda Ct y + Omega^2 y = 0.
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(2 * m, 2 * m);
  A.topRightCorner(m, m).setIdentity();
  A.bottomLeftCorner(m, m) = -modes.omega2.asDiagonal().toDenseMatrix();
  A.bottomRightCorner(m, m) = -Ct;
  Eigen::EigenSolver<Eigen::MatrixXd> es(A, true);
  if (es.info() != Eigen::Success) throw NumericalError("damped modes: the eigen solution of the damped model failed");
  const Eigen::VectorXcd lambda = es.eigenvalues();
  const Eigen::MatrixXcd V = es.eigenvectors();
  for (int k = 0; k < count; ++k) {
    if (modes.isRigidBody(k) || !modes.isStable(k)) {
      out.ratio.push_back(0.0);
      out.natural_hz.push_back(modes.frequencyHz(k));
      continue;
    }
    Eigen::Index best = -1;
    double best_share = -1;
    for (Eigen::Index j = 0; j < lambda.size(); ++j) {
      if (lambda[j].imag() < 0) continue;  // one of each pair
      const Eigen::VectorXcd y = V.col(j).head(m);
      const double share = std::norm(y[k]) / std::max(y.squaredNorm(), 1e-300);
      if (share > best_share) best_share = share, best = j;
    }
    MMV_DEMAND(best >= 0);
    const std::complex<double> l = lambda[best];
    const double mag = std::abs(l);
    out.natural_hz.push_back(mag / (2 * M_PI));
    out.ratio.push_back(l.imag() > 0 && mag > 0 ? std::min(1.0, -l.real() / mag) : 1.0);
  }
  return out;
}

}  // namespace mmv
