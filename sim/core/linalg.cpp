#include "sim/core/linalg.hpp"

namespace mmv {

void symmetrize(Eigen::MatrixXd& A) {
  for (Eigen::Index j = 0; j < A.cols(); ++j)
    for (Eigen::Index i = 0; i < j; ++i) A(i, j) = A(j, i) = 0.5 * (A(i, j) + A(j, i));
}

EquilibratedLu::EquilibratedLu(const Eigen::MatrixXd& A) {
  const Eigen::Index n = A.rows();
  r_ = A.cwiseAbs().rowwise().maxCoeff();
  if (n == 0 || !(r_.minCoeff() > 0)) return;
  r_ = r_.cwiseInverse();
  const Eigen::MatrixXd Ar = r_.asDiagonal() * A;
  c_ = Ar.cwiseAbs().colwise().maxCoeff().transpose();
  if (!(c_.minCoeff() > 0)) return;
  c_ = c_.cwiseInverse();
  lu_.compute(Ar * c_.asDiagonal());
  ok_ = lu_.isInvertible();
}

Eigen::MatrixXd EquilibratedLu::solve(const Eigen::MatrixXd& B) const {
  return c_.asDiagonal() * lu_.solve(r_.asDiagonal() * B);
}

}  // namespace mmv
