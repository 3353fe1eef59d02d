// The full second-order model's frequency response (SecondOrderResponse in
// sim/linear/state_space.hpp): the modal sum for proportional damping, the Hessenberg
// form of the first-order matrix for any other.
#include <tbb/parallel_invoke.h>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

#include "sim/core/errors.hpp"
#include "sim/core/progress.hpp"
#include "sim/core/text.hpp"
#include "sim/linear/hessenberg.hpp"
#include "sim/linear/state_space.hpp"

namespace mmv {

using cd = std::complex<double>;


void SecondOrderResponse::prepareHessenberg() {
  const Eigen::Index n = K.rows(), N = 2 * n;
  const Eigen::PartialPivLU<Eigen::MatrixXd> mlu(M);
  Eigen::MatrixXd A1 = Eigen::MatrixXd::Zero(N, N);
  A1.topRightCorner(n, n).setIdentity();
  A1.bottomLeftCorner(n, n) = -mlu.solve(K);
  A1.bottomRightCorner(n, n) = -mlu.solve(C);
  // Balanced first (stiff hinges put omega_max^2 ~ 1e8 beside the identity block, and
  // the reduction's backward error is eps times the matrix's norm): A1 := D^-1 A1 D.
  const Eigen::VectorXd d = detail::balance(A1);
  const Eigen::HessenbergDecomposition<Eigen::MatrixXd> hd(A1);
  H_ = hd.matrixH();
  const Eigen::MatrixXd Q = hd.matrixQ();
  Bh_ = Q.bottomRows(n).transpose() * d.tail(n).cwiseInverse().asDiagonal() * mlu.solve(Bq);
  // Outputs on the whole state, accelerations eliminated as secondOrderModel does
  // (y = C1 x + D1): -w^2 Ca q would cancel against Ca M^-1 Bq at high frequency.
  const Eigen::Index no = D.rows();
  auto rows = [&](const Eigen::MatrixXd& X) { return X.size() ? X : Eigen::MatrixXd::Zero(no, n); };
  const Eigen::MatrixXd PMi = mlu.solve(rows(Ca).transpose()).transpose();  // (M symmetric)
  Eigen::MatrixXd C1(no, N);
  C1 << rows(Cd) - PMi * K, rows(Cv) - PMi * C;
  // The refinement (hessenbergResponse) works on q alone: q = (D Q)_q z, and a
  // residual r on the second-order form is carried back as z += (Q^T D^-1)_v M^-1 r.
  Qq_ = d.head(n).asDiagonal() * Q.topRows(n);
  Rv_ = mlu.solve(d.tail(n).cwiseInverse().asDiagonal() * Q.bottomRows(n)).transpose();  // (M symmetric)
  C1q_ = C1.leftCols(n);
  C1v_ = C1.rightCols(n);
  C1qQq_ = C1q_ * Qq_;
  C1vQq_ = C1v_ * Qq_;
  D1_ = PMi * Bq + D;
  c_diagonal_ = C.isDiagonal(0);
  hessenberg_ = H_.allFinite() && Bh_.allFinite() && Qq_.allFinite() && Rv_.allFinite();
}


Eigen::MatrixXcd SecondOrderResponse::hessenbergResponse(double w) const {
  const detail::HessenbergLu lu(H_, w);
  detail::RowMajorXcd Z = Bh_.cast<cd>();
  lu.solve(Z);
  // q = (D Q)_q z, refined once on the residual of the second-order form,
  // r = Bq - (K - w^2 M + i w C) q (the explicit M^-1 K of the Hessenberg matrix costs
  // digits when M is ill-conditioned): with v = i w q the first-order residual is
  // [0; r], so the correction solves (i w I - A1) dx = [0; M^-1 r] in the balanced
  // Hessenberg basis, and q += (D Q)_q dz.
  // Real A times complex v, a column at a time: v has a column per input (a few), and a
  // matrix product would pack all of A into a blocking buffer on every call, which cost as
  // much as the product itself (and 27x under AddressSanitizer, whose fresh buffers each
  // page-fault); a matrix-vector product reads A once, in place.
  const auto real = [](const Eigen::MatrixXd& A, const auto& v) {
    const Eigen::Index m = v.cols();
    Eigen::MatrixXd x(v.rows(), 2 * m), ax(A.rows(), 2 * m);
    x.leftCols(m) = v.real();
    x.rightCols(m) = v.imag();
    for (Eigen::Index j = 0; j < 2 * m; ++j) ax.col(j).noalias() = A * x.col(j);
    Eigen::MatrixXcd y(A.rows(), m);
    y.real() = ax.leftCols(m);
    y.imag() = ax.rightCols(m);
    return y;
  };
  Eigen::MatrixXcd q = real(Qq_, Z);
  Eigen::MatrixXcd r = Bq.cast<cd>() - real(K, q) + (w * w) * real(M, q);
  if (c_diagonal_)
    r -= cd(0, w) * (C.diagonal().cast<cd>().asDiagonal() * q);
  else
    r -= cd(0, w) * real(C, q);
  detail::RowMajorXcd dz = real(Rv_, r);
  lu.solve(dz);
  // y = C1 [q; i w q] + D1 with q + (D Q)_q dz, the correction taken to the outputs directly.
  return real(C1q_, q) + cd(0, w) * real(C1v_, q) + real(C1qQq_, dz) + cd(0, w) * real(C1vQq_, dz) + D1_.cast<cd>();
}

void SecondOrderResponse::setModalBasis(Eigen::VectorXd omega2, Eigen::MatrixXd shapes, Eigen::VectorXd c) {
  MMV_DEMAND(shapes.cols() == omega2.size() && c.size() == omega2.size());
  w2_ = std::move(omega2);
  basis_ = std::move(shapes);
  c_ = std::move(c);
}

void SecondOrderResponse::prepare() {
  modal_ = hessenberg_ = false;
  const Eigen::Index n = K.rows();
  if (n == 0) return;
  const ProgressStage stage(strf("factorizing the second-order model (%ld DOF)", static_cast<long>(n)));
  const auto useModes = [&](const Eigen::MatrixXd& phi) {
    P_ = phi.transpose() * Bq;
    const auto times = [&](const Eigen::MatrixXd& o) { return o.size() ? Eigen::MatrixXd(o * phi) : Eigen::MatrixXd::Zero(D.rows(), n); };
    Od_ = times(Cd), Ov_ = times(Cv), Oa_ = times(Ca);
    modal_ = true;
  };
  if (basis_.size()) {
    MMV_DEMAND(basis_.rows() == n && basis_.cols() == n);
    useModes(basis_);
    basis_ = Eigen::MatrixXd();
    return;
  }
  const double scale = K.cwiseAbs().maxCoeff();
  const bool symmetric = (K - K.transpose()).cwiseAbs().maxCoeff() <= 1e-12 * scale &&
                         (C - C.transpose()).cwiseAbs().maxCoeff() <= 1e-12 * std::max(C.cwiseAbs().maxCoeff(), 1e-300);
  if (!symmetric) return prepareHessenberg();
  // Whether the real modes diagonalise C (proportional damping) is known only after a
  // symmetric eigen solution; the Hessenberg form the other case needs is prepared beside
  // it and dropped if unused (the wall time of the two is that of the longer).
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> es;
  SecondOrderResponse general = *this;
  tbb::parallel_invoke([&] { es.compute(K, M); }, [&] { general.prepareHessenberg(); });
  const auto useGeneral = [&] { *this = std::move(general); };
  if (es.info() != Eigen::Success) return useGeneral();
  const Eigen::MatrixXd& phi = es.eigenvectors();
  const Eigen::MatrixXd cm = phi.transpose() * C * phi;
  const Eigen::VectorXd diag = cm.diagonal();
  const double off = (cm - Eigen::MatrixXd(diag.asDiagonal())).cwiseAbs().maxCoeff();
  if (!(off <= 1e-10 * std::max(diag.cwiseAbs().maxCoeff(), 1e-300)) && C.cwiseAbs().maxCoeff() > 0)
    return useGeneral();
  w2_ = es.eigenvalues();
  c_ = diag;
  useModes(phi);
}

Eigen::MatrixXcd SecondOrderResponse::response(double w) const {
  if (hessenberg_) return hessenbergResponse(w);
  if (modal_) {
    Eigen::VectorXcd g(w2_.size());
    for (Eigen::Index k = 0; k < g.size(); ++k) g[k] = 1.0 / cd(w2_[k] - w * w, w * c_[k]);
    const Eigen::MatrixXcd O = Od_.cast<cd>() + cd(0, w) * Ov_.cast<cd>() - w * w * Oa_.cast<cd>();
    return O * g.asDiagonal() * P_.cast<cd>() + D.cast<cd>();
  }
  const Eigen::MatrixXcd dyn = K.cast<cd>() - w * w * M.cast<cd>() + cd(0, w) * C.cast<cd>();
  const Eigen::MatrixXcd q = dyn.partialPivLu().solve(Bq.cast<cd>());  // per unit input
  return Cd.cast<cd>() * q + cd(0, w) * Cv.cast<cd>() * q - w * w * Ca.cast<cd>() * q + D.cast<cd>();
}

}  // namespace mmv
