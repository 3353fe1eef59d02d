#include "sim/linear/state_space.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

#include "sim/core/errors.hpp"

namespace mmv {

using cd = std::complex<double>;

Eigen::MatrixXcd StateSpace::response(double omega) const {
  const Eigen::MatrixXcd sEA = cd(0, omega) * E.cast<cd>() - A.cast<cd>();
  const Eigen::MatrixXcd X = sEA.partialPivLu().solve(B.cast<cd>());
  return C.cast<cd>() * X + D.cast<cd>();
}

StateSpace StateSpace::standardForm() const {
  StateSpace s = *this;
  const Eigen::PartialPivLU<Eigen::MatrixXd> lu(E);
  s.A = lu.solve(A);
  s.B = lu.solve(B);
  s.E = Eigen::MatrixXd::Identity(A.rows(), A.cols());
  return s;
}

Eigen::VectorXcd StateSpace::poles() const {
  Eigen::EigenSolver<Eigen::MatrixXd> es(E.partialPivLu().solve(A), false);
  return es.eigenvalues();
}

std::vector<double> logFrequencies(double f0, double f1, int n) {
  std::vector<double> f(n);
  for (int i = 0; i < n; ++i) f[i] = f0 * std::pow(f1 / f0, n > 1 ? double(i) / (n - 1) : 0.0);
  return f;
}

StateSpace secondOrderModel(const Eigen::MatrixXd& M, const Eigen::MatrixXd& C, const Eigen::MatrixXd& K,
                            const Eigen::MatrixXd& Bq, const Eigen::MatrixXd& Cd, const Eigen::MatrixXd& Cv,
                            const Eigen::MatrixXd& Ca, const Eigen::MatrixXd& Dextra) {
  const Eigen::Index n = M.rows(), ni = Bq.cols();
  const Eigen::Index no = std::max({Cd.rows(), Cv.rows(), Ca.rows(), Dextra.rows()});
  auto rows = [&](const Eigen::MatrixXd& X) { return X.size() ? X : Eigen::MatrixXd::Zero(no, n); };
  StateSpace ss;
  ss.E = Eigen::MatrixXd::Identity(2 * n, 2 * n);
  ss.E.bottomRightCorner(n, n) = M;
  ss.A = Eigen::MatrixXd::Zero(2 * n, 2 * n);
  ss.A.topRightCorner(n, n) = Eigen::MatrixXd::Identity(n, n);
  ss.A.bottomLeftCorner(n, n) = -K;
  ss.A.bottomRightCorner(n, n) = -C;
  ss.B = Eigen::MatrixXd::Zero(2 * n, ni);
  ss.B.bottomRows(n) = Bq;
  // q'' = M^-1 (Bq u - C q' - K q): an acceleration row P becomes P M^-1 [-K -C], D = P M^-1 Bq.
  const Eigen::MatrixXd PMi = M.partialPivLu().solve(rows(Ca).transpose()).transpose();  // (M symmetric)
  ss.C.resize(no, 2 * n);
  ss.C << rows(Cd) - PMi * K, rows(Cv) - PMi * C;
  ss.D = PMi * Bq + (Dextra.size() ? Dextra : Eigen::MatrixXd::Zero(no, ni));
  return ss;
}

void SecondOrderResponse::prepare() {
  modal_ = false;
  const Eigen::Index n = K.rows();
  if (n == 0) return;
  const double scale = K.cwiseAbs().maxCoeff();
  if (!((K - K.transpose()).cwiseAbs().maxCoeff() <= 1e-12 * scale) || !((C - C.transpose()).cwiseAbs().maxCoeff() <= 1e-12 * std::max(C.cwiseAbs().maxCoeff(), 1e-300)))
    return;
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> es(K, M);
  if (es.info() != Eigen::Success) return;
  const Eigen::MatrixXd& phi = es.eigenvectors();
  const Eigen::MatrixXd cm = phi.transpose() * C * phi;
  const Eigen::VectorXd diag = cm.diagonal();
  const double off = (cm - Eigen::MatrixXd(diag.asDiagonal())).cwiseAbs().maxCoeff();
  if (!(off <= 1e-10 * std::max(diag.cwiseAbs().maxCoeff(), 1e-300)) && C.cwiseAbs().maxCoeff() > 0) return;
  w2_ = es.eigenvalues();
  c_ = diag;
  P_ = phi.transpose() * Bq;
  const auto times = [&](const Eigen::MatrixXd& o) { return o.size() ? Eigen::MatrixXd(o * phi) : Eigen::MatrixXd::Zero(D.rows(), n); };
  Od_ = times(Cd), Ov_ = times(Cv), Oa_ = times(Ca);
  modal_ = true;
}

bool SecondOrderResponse::adoptStateModes(const StateModes& sm, const std::vector<double>& check_omegas) {
  const Eigen::Index n = K.rows();
  if (modal_ || n == 0 || sm.V.rows() != 2 * n) return false;
  const Eigen::PartialPivLU<Eigen::MatrixXd> mlu(M);
  const Eigen::MatrixXcd Minv = mlu.inverse().cast<cd>();
  SecondOrderResponse trial = *this;
  trial.lambda_ = sm.lambda;
  trial.Vq_ = sm.V.topRows(n);
  trial.Wv_ = sm.W.rightCols(n) * Minv;
  trial.WB_ = trial.Wv_ * Bq.cast<cd>();
  trial.state_modal_ = true;
  for (double w : check_omegas) {
    const Eigen::MatrixXcd direct = response(w), modal = trial.response(w);
    const double scale = std::max(direct.cwiseAbs().maxCoeff(), 1e-300);
    if (!((direct - modal).cwiseAbs().maxCoeff() <= 1e-10 * scale)) return false;
  }
  *this = std::move(trial);
  return true;
}

Eigen::MatrixXcd SecondOrderResponse::response(double w) const {
  if (state_modal_) {
    // Column by column (matrix-vector products: no packing of the large factors for
    // a few inputs), the real matrices applied to real and imaginary parts apart.
    const Eigen::Index n = K.rows();
    Eigen::VectorXcd g(lambda_.size());
    for (Eigen::Index k = 0; k < g.size(); ++k) g[k] = 1.0 / (cd(0, w) - lambda_[k]);
    const auto real = [](const Eigen::MatrixXd& A, const Eigen::VectorXcd& x) {
      Eigen::VectorXcd y(A.rows());
      y.real() = A * x.real();
      y.imag() = A * x.imag();
      return y;
    };
    Eigen::MatrixXcd q(n, Bq.cols());
    for (Eigen::Index j = 0; j < Bq.cols(); ++j) {
      Eigen::VectorXcd qj = Vq_ * g.cwiseProduct(WB_.col(j));
      const Eigen::VectorXcd r = Bq.col(j).cast<cd>() - real(K, qj) + w * w * real(M, qj) - cd(0, w) * real(C, qj);
      qj += Vq_ * g.cwiseProduct(Wv_ * r);
      q.col(j) = qj;
    }
    return Cd.cast<cd>() * q + cd(0, w) * Cv.cast<cd>() * q - w * w * Ca.cast<cd>() * q + D.cast<cd>();
  }
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

namespace {

/// Largest |a - b| over the frequencies, relative to the peak of |a|, per pair.
template <class Full>
ModelError compareWith(const Full& a, const StateSpace& b, const std::vector<double>& omegas) {
  const Eigen::Index no = b.C.rows(), ni = b.B.cols();
  Eigen::MatrixXd diff = Eigen::MatrixXd::Zero(no, ni), peak = Eigen::MatrixXd::Zero(no, ni);
  for (double w : omegas) {
    const Eigen::MatrixXcd ha = a.response(w), hb = b.response(w);
    diff = diff.cwiseMax((ha - hb).cwiseAbs());
    peak = peak.cwiseMax(ha.cwiseAbs());
  }
  // A pair that is zero up to round-off (a pinned point's response) is measured against
  // the model's largest response instead, so its noise is not reported as an error.
  ModelError e;
  const double floor = 1e-9 * (peak.size() ? peak.maxCoeff() : 0.0);
  e.relative = diff.cwiseQuotient(peak.cwiseMax(std::max(floor, 1e-300)));
  e.max_relative = e.relative.size() ? e.relative.maxCoeff() : 0.0;
  return e;
}

}  // namespace

ModelError compareResponses(const StateSpace& a, const StateSpace& b, const std::vector<double>& omegas) {
  return compareWith(a, b, omegas);
}

ModelError compareResponses(const SecondOrderResponse& a, const StateSpace& b, const std::vector<double>& omegas) {
  return compareWith(a, b, omegas);
}

Eigen::VectorXcd polesFromIntegratorJacobian(const StateSpace& m, double c) {
  const Eigen::MatrixXd Jp = m.E - c * m.A, Jm = m.E + c * m.A;  // J(c), J(-c)
  // J(-c) v = Lambda J(c) v. J(c) is invertible unless a pole sits at 1/c, so the
  // pencil is solved as the standard problem J(c)^-1 J(-c) (Eigen's real QZ solver
  // lost the large eigenvalues here).
  const Eigen::FullPivLU<Eigen::MatrixXd> lu(Jp);
  if (!lu.isInvertible()) throw NumericalError("integrator Jacobian J(dCoef) is singular: a pole sits at 1/dCoef");
  Eigen::EigenSolver<Eigen::MatrixXd> es(lu.solve(Jm), false);
  const Eigen::VectorXcd Lambda = es.eigenvalues();
  Eigen::VectorXcd lambda(Lambda.size());
  for (Eigen::Index i = 0; i < Lambda.size(); ++i) lambda[i] = (Lambda[i] - 1.0) / (c * (Lambda[i] + 1.0));
  return lambda;
}

PeakTable refinedPeaks(const SecondOrderResponse& h, const std::vector<double>& f) {
  MMV_DEMAND(!f.empty());
  auto magnitudes = [&](double hz) { return Eigen::MatrixXd(h.response(2 * M_PI * hz).cwiseAbs()); };
  std::vector<Eigen::MatrixXd> grid;
  grid.reserve(f.size());
  for (double hz : f) grid.push_back(magnitudes(hz));
  const Eigen::Index no = grid.front().rows(), ni = grid.front().cols();
  PeakTable t{Eigen::MatrixXd(no, ni), Eigen::MatrixXd(no, ni)};
  const double g = 0.5 * (std::sqrt(5.0) - 1);
  for (Eigen::Index o = 0; o < no; ++o)
    for (Eigen::Index i = 0; i < ni; ++i) {
      auto mag = [&](double hz) { return std::abs(h.response(2 * M_PI * hz)(o, i)); };
      std::size_t best = 0;
      for (std::size_t k = 0; k < f.size(); ++k)
        if (grid[k](o, i) > grid[best](o, i)) best = k;
      // Golden section between the grid neighbours, one new point per step.
      double lo = f[best > 0 ? best - 1 : 0], hi = f[std::min(best + 1, f.size() - 1)];
      double a = hi - g * (hi - lo), b = lo + g * (hi - lo), ma = mag(a), mb = mag(b);
      for (int it = 0; it < 80 && hi - lo > 1e-9 * hi; ++it) {
        if (ma > mb) {
          hi = b, b = a, mb = ma, a = hi - g * (hi - lo), ma = mag(a);
        } else {
          lo = a, a = b, ma = mb, b = lo + g * (hi - lo), mb = mag(b);
        }
      }
      double fpeak = 0.5 * (lo + hi), peak = mag(fpeak);
      if (grid[best](o, i) > peak) fpeak = f[best], peak = grid[best](o, i);
      t.hz(o, i) = fpeak;
      t.magnitude(o, i) = peak;
    }
  return t;
}

}  // namespace mmv
