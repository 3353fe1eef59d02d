#include "sim/statics/damping_matrix.hpp"

#include <algorithm>
#include <cmath>

#include "sim/core/errors.hpp"
#include "sim/core/text.hpp"

namespace mmv {

std::string describeDamping(const DampingSpec& d) {
  switch (d.kind) {
    case DampingSpec::Kind::Modal: return strf("modal, %.3g %% of critical in every mode", 100 * d.modal_ratio);
    case DampingSpec::Kind::Rayleigh: return strf("Rayleigh, C = %.4g/s * M + %.4g s * K", d.alpha, d.beta);
    case DampingSpec::Kind::HingeViscous: return strf("hinge dampers c = %.4g s * k on every bending hinge", d.hinge_beta);
  }
  return "";
}

bool isMatrixDamping(const DampingSpec& d) {
  return d.kind == DampingSpec::Kind::Modal || d.kind == DampingSpec::Kind::Rayleigh;
}

Eigen::MatrixXd calcDampingMatrix(const LinearizedModel& lin, const DampingSpec& d) {
  const Eigen::Index n = lin.M.rows();
  MMV_DEMAND(lin.K.rows() == n && lin.K.cols() == n && lin.M.cols() == n);
  if (d.kind == DampingSpec::Kind::Rayleigh) return d.alpha * lin.M + d.beta * lin.K;
  MMV_DEMAND(d.kind == DampingSpec::Kind::Modal);
  if (n == 0) return Eigen::MatrixXd(0, 0);
  const Eigen::MatrixXd& Z = lin.Z;  // identity for an open tree
  MMV_DEMAND(Z.rows() == n);
  if (Z.cols() == 0) return Eigen::MatrixXd::Zero(n, n);  // the closures leave no motion
  const Eigen::MatrixXd My = Z.transpose() * lin.M * Z, Ky = Z.transpose() * lin.K * Z;
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> es(0.5 * (Ky + Ky.transpose()), 0.5 * (My + My.transpose()));
  if (es.info() != Eigen::Success)
    throw NumericalError("modal damping: the modes of the held article did not converge (is the mass matrix positive definite?)");
  // C = (M Phi) diag(2 zeta omega) (M Phi)^T with Phi = Z Y, Y^T My Y = I.
  const Eigen::MatrixXd B = lin.M * Z * es.eigenvectors();
  Eigen::VectorXd c(es.eigenvalues().size());
  for (Eigen::Index k = 0; k < c.size(); ++k) c[k] = 2 * d.modal_ratio * std::sqrt(std::max(es.eigenvalues()[k], 0.0));
  Eigen::MatrixXd C = B * c.asDiagonal() * B.transpose();
  return 0.5 * (C + C.transpose());
}

}  // namespace mmv
