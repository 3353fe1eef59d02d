#include "sim/linear/hessenberg.hpp"

#include <cmath>

namespace mmv::detail {

using cd = std::complex<double>;

Eigen::VectorXd balance(Eigen::MatrixXd& A) {
  const Eigen::Index N = A.rows();
  Eigen::VectorXd d = Eigen::VectorXd::Ones(N);
  for (bool changed = true; changed;) {
    changed = false;
    for (Eigen::Index i = 0; i < N; ++i) {
      double c = A.col(i).cwiseAbs().sum() - std::abs(A(i, i)), r = A.row(i).cwiseAbs().sum() - std::abs(A(i, i));
      if (c == 0 || r == 0) continue;
      const double s0 = c + r;
      double f = 1;
      while (c < r / 2) c *= 2, r /= 2, f *= 2;
      while (c >= r * 2) c /= 2, r *= 2, f /= 2;
      if (c + r < 0.95 * s0) {
        changed = true;
        d[i] *= f;
        A.row(i) /= f;
        A.col(i) *= f;
      }
    }
  }
  return d;
}

HessenbergLu::HessenbergLu(const RowMajorXd& H, double w)
    : N_(H.rows()), swap_(N_, 0), l_(N_, 0.0) {
  thread_local std::vector<double> packed_re, packed_im, carry_re, carry_im;
  for (auto* v : {&packed_re, &packed_im}) v->resize(N_ * (N_ + 1) / 2);
  for (auto* v : {&carry_re, &carry_im}) v->resize(N_);
  re_ = packed_re.data(), im_ = packed_im.data();
  using Vec = Eigen::Map<Eigen::ArrayXd>;
  Vec rr(carry_re.data(), N_), ri(carry_im.data(), N_);  // the row carried down, columns k..N-1
  rr = -H.row(0).transpose().array();
  ri.setZero();
  ri[0] = w;
  for (Eigen::Index k = 0; k + 1 < N_; ++k) {
    const Eigen::Index len = N_ - k, m = len - 1;
    Vec ur(re_ + offset(k), len), ui(im_ + offset(k), len);
    const auto t = -H.row(k + 1).segment(k, len).transpose().array();  // row k + 1 of -H from column k
    const double tk = t[0];
    if (std::abs(tk) > std::hypot(rr[k], ri[k])) {  // the next row is the pivot
      swap_[k] = 1;
      ur = t;
      ui.setZero();
      ui[1] = w;
      const cd l = cd(rr[k], ri[k]) / tk;
      l_[k] = l;
      rr.segment(k + 1, m) -= l.real() * ur.tail(m) - l.imag() * ui.tail(m);
      ri.segment(k + 1, m) -= l.real() * ui.tail(m) + l.imag() * ur.tail(m);
    } else {
      ur = rr.segment(k, len);
      ui = ri.segment(k, len);
      const cd l = tk != 0.0 ? tk / cd(ur[0], ui[0]) : cd(0.0);
      l_[k] = l;
      rr.segment(k + 1, m) = t.tail(m) - (l.real() * ur.tail(m) - l.imag() * ui.tail(m));
      ri.segment(k + 1, m) = -(l.real() * ui.tail(m) + l.imag() * ur.tail(m));
      ri[k + 1] += w;
    }
  }
  re_[offset(N_ - 1)] = rr[N_ - 1];
  im_[offset(N_ - 1)] = ri[N_ - 1];
}

void HessenbergLu::solve(RowMajorXcd& X) const {
  for (Eigen::Index k = 0; k + 1 < N_; ++k) {
    if (swap_[k]) X.row(k).swap(X.row(k + 1));
    X.row(k + 1) -= l_[k] * X.row(k);
  }
  Eigen::VectorXd xr(N_), xi(N_);
  for (Eigen::Index c = 0; c < X.cols(); ++c) {
    xr = X.col(c).real();
    xi = X.col(c).imag();
    for (Eigen::Index k = N_ - 1; k >= 0; --k) {
      const Eigen::Index len = N_ - k, m = len - 1;
      const Eigen::Map<const Eigen::VectorXd> ur(re_ + offset(k), len), ui(im_ + offset(k), len);
      cd x(xr[k], xi[k]);
      if (m > 0) {
        const auto br = xr.tail(m), bi = xi.tail(m);
        x -= cd(ur.tail(m).dot(br) - ui.tail(m).dot(bi), ur.tail(m).dot(bi) + ui.tail(m).dot(br));
      }
      x /= cd(ur[0], ui[0]);
      xr[k] = x.real(), xi[k] = x.imag();
    }
    X.col(c).real() = xr;
    X.col(c).imag() = xi;
  }
}

}  // namespace mmv::detail
