#include "sim/linear/state_space.hpp"

#include <atomic>
#include <Eigen/Eigenvalues>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>
#include <algorithm>
#include <cmath>

#include "sim/core/errors.hpp"
#include "sim/core/progress.hpp"
#include "sim/core/text.hpp"
#include "sim/linear/hessenberg.hpp"

namespace mmv {

using cd = std::complex<double>;

Eigen::MatrixXcd StateSpace::response(double omega) const {
  const Eigen::MatrixXcd sEA = cd(0, omega) * E.cast<cd>() - A.cast<cd>();
  const Eigen::MatrixXcd X = sEA.partialPivLu().solve(B.cast<cd>());
  return C.cast<cd>() * X + D.cast<cd>();
}

StateSpaceResponses::StateSpaceResponses(const StateSpace& s, const std::vector<double>& check_omegas) : s_(s) {
  const Eigen::Index N = s.A.rows();
  if (N == 0 || check_omegas.empty()) return;
  const Eigen::PartialPivLU<Eigen::MatrixXd> lu(s.E);
  if (!(lu.rcond() > 1e-12)) return;  // singular E: the LU of i w E - A at each frequency
  Eigen::MatrixXd A1 = lu.solve(s.A);
  const Eigen::VectorXd d = detail::balance(A1);  // A1 := D^-1 E^-1 A D
  const Eigen::HessenbergDecomposition<Eigen::MatrixXd> hd(A1);
  H_ = hd.matrixH();
  const Eigen::MatrixXd Q = hd.matrixQ();
  Bh_ = Q.transpose() * (d.cwiseInverse().asDiagonal() * lu.solve(s.B));
  Ch_ = s.C * d.asDiagonal() * Q;
  if (!H_.allFinite() || !Bh_.allFinite() || !Ch_.allFinite()) return;
  hessenberg_ = true;
  for (std::size_t k : {std::size_t{0}, check_omegas.size() / 2, check_omegas.size() - 1}) {
    const Eigen::MatrixXcd ref = s.response(check_omegas[k]);
    const double scale = std::max(ref.cwiseAbs().maxCoeff(), 1e-300);
    if (!((at(check_omegas[k]) - ref).cwiseAbs().maxCoeff() <= 1e-10 * scale)) {
      hessenberg_ = false;
      return;
    }
  }
}

Eigen::MatrixXcd StateSpaceResponses::at(double omega) const {
  if (!hessenberg_) return s_.response(omega);
  const detail::HessenbergLu lu(H_, omega);
  detail::RowMajorXcd z = Bh_.cast<cd>();
  lu.solve(z);
  Eigen::MatrixXcd y(Ch_.rows(), z.cols());
  y.real() = Ch_ * z.real();
  y.imag() = Ch_ * z.imag();
  return y + s_.D.cast<cd>();
}

StateSpace StateSpace::standardForm() const {
  StateSpace s = *this;
  const Eigen::Index N = E.rows(), n = N / 2;
  // E = diag(I, M), as secondOrderModel builds it: only the lower rows change, by M^-1
  // (an n^3 factorization, not (2n)^3; the full model's .mat file at 64 segments a link).
  const bool second_order = N > 0 && N % 2 == 0 && E.topLeftCorner(n, n).isIdentity(0) &&
                            E.topRightCorner(n, n).isZero(0) && E.bottomLeftCorner(n, n).isZero(0);
  if (second_order) {
    const Eigen::PartialPivLU<Eigen::MatrixXd> lu(E.bottomRightCorner(n, n));
    s.A.bottomRows(n) = lu.solve(A.bottomRows(n));
    s.B.bottomRows(n) = lu.solve(B.bottomRows(n));
  } else {
    const Eigen::PartialPivLU<Eigen::MatrixXd> lu(E);
    s.A = lu.solve(A);
    s.B = lu.solve(B);
  }
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

std::vector<double> resolveResonances(const std::vector<double>& grid, const std::vector<double>& fn_hz,
                                      const std::vector<double>& zeta, int per_half_band) {
  if (grid.empty()) return grid;
  std::vector<double> f = grid;
  const double lo = *std::min_element(grid.begin(), grid.end()), hi = *std::max_element(grid.begin(), grid.end());
  for (std::size_t m = 0; m < fn_hz.size() && m < zeta.size(); ++m) {
    const double fn = fn_hz[m], z = zeta[m];
    if (!(z > 0 && z < 0.5) || !(fn > lo && fn < hi)) continue;
    auto add = [&](double x) {
      if (x >= lo && x <= hi) f.push_back(x);
    };
    for (int k = -2 * per_half_band; k <= 2 * per_half_band; ++k) add(fn * (1 + z * k / per_half_band));
    add(fn * std::sqrt(1 - 2 * z * z));
  }
  std::sort(f.begin(), f.end());
  std::vector<double> out;
  for (double x : f)
    if (out.empty() || x > out.back() * (1 + 1e-9)) out.push_back(x);
  return out;
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

namespace {

/// Largest |a - b| over the frequencies, relative to the peak of |a|, per pair;
/// `full(k, w)` is a's response at omegas[k] = w.
/// Each pair's round-off floor: 1e-9 of the largest peak among the pairs of its units
/// (output unit over input unit; one group when the model names none).
Eigen::MatrixXd unitFloors(const StateSpace& b, const Eigen::MatrixXd& peak) {
  const auto unit = [&](const std::vector<std::string>& units, Eigen::Index k) {
    return static_cast<std::size_t>(k) < units.size() ? units[static_cast<std::size_t>(k)] : std::string();
  };
  Eigen::MatrixXd floor(peak.rows(), peak.cols());
  for (Eigen::Index o = 0; o < peak.rows(); ++o)
    for (Eigen::Index i = 0; i < peak.cols(); ++i) {
      double largest = 0;
      for (Eigen::Index p = 0; p < peak.rows(); ++p)
        for (Eigen::Index q = 0; q < peak.cols(); ++q)
          if (unit(b.output_units, p) == unit(b.output_units, o) && unit(b.input_units, q) == unit(b.input_units, i))
            largest = std::max(largest, peak(p, q));
      floor(o, i) = std::max(1e-9 * largest, 1e-300);
    }
  return floor;
}

template <class FullAt>
ModelError compareWith(const FullAt& full, const StateSpace& b, const std::vector<double>& omegas) {
  const Eigen::Index no = b.C.rows(), ni = b.B.cols();
  Eigen::MatrixXd diff = Eigen::MatrixXd::Zero(no, ni), peak = Eigen::MatrixXd::Zero(no, ni);
  std::vector<Eigen::MatrixXd> gap(omegas.size()), size(omegas.size());  // |a - b|, |a| per frequency
  const ProgressStage stage("comparing the reduced model with the full one");
  // The frequencies on every core (each its own LU of the reduced model), then the
  // maxima in order: the same numbers as one after the other.
  std::atomic<long> done{0};
  const StateSpaceResponses hb_at(b, omegas);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, omegas.size(), 16), [&](const tbb::blocked_range<std::size_t>& range) {
    for (std::size_t k = range.begin(); k != range.end(); ++k) {
      const Eigen::MatrixXcd ha = full(k, omegas[k]), hb = hb_at.at(omegas[k]);
      gap[k] = (ha - hb).cwiseAbs();
      size[k] = ha.cwiseAbs();
      progressCount(++done, static_cast<long>(omegas.size()), "frequency");
    }
  });
  for (std::size_t k = 0; k < omegas.size(); ++k) {
    diff = diff.cwiseMax(gap[k]);
    peak = peak.cwiseMax(size[k]);
  }
  // A pair that is zero up to round-off (a pinned point's response) is measured against
  // the largest response of the pairs in its units instead, so its noise is not
  // reported as an error (a stress in Pa beside a strain in m/m: each against its own).
  ModelError e;
  const Eigen::MatrixXd floor = unitFloors(b, peak);
  e.relative = diff.cwiseQuotient(peak.cwiseMax(floor));
  // A pair whose full response never reaches the floor is zero (a pair that symmetry
  // decouples): both models give round-off there, which is no error of the reduction.
  e.zero = (peak.array() < floor.array()).cast<bool>().matrix();
  for (Eigen::Index o = 0; o < no; ++o)
    for (Eigen::Index i = 0; i < ni; ++i)
      if (e.zero(o, i)) e.relative(o, i) = 0;
  e.max_relative = e.relative.size() ? e.relative.maxCoeff() : 0.0;
  // Local: against the full response at the same frequency (the same floor), which a
  // peak-normalized error hides near an antiresonance or far down a roll-off.
  e.local = Eigen::MatrixXd::Zero(no, ni);
  e.local_hz = Eigen::MatrixXd::Zero(no, ni);
  for (std::size_t k = 0; k < omegas.size(); ++k)
    for (Eigen::Index o = 0; o < no; ++o)
      for (Eigen::Index i = 0; i < ni; ++i) {
        const double r = e.zero(o, i) ? 0.0 : gap[k](o, i) / std::max(size[k](o, i), floor(o, i));
        if (r > e.local(o, i)) e.local(o, i) = r, e.local_hz(o, i) = omegas[k] / (2 * M_PI);
      }
  if (e.local.size()) {
    Eigen::Index o = 0, i = 0;
    e.max_local = e.local.maxCoeff(&o, &i);
    e.max_local_hz = e.local_hz(o, i);
    e.max_local_pair = {o, i};
  }
  return e;
}

}  // namespace

ModelError compareResponses(const StateSpace& a, const StateSpace& b, const std::vector<double>& omegas) {
  return compareWith([&](std::size_t, double w) { return a.response(w); }, b, omegas);
}

ModelError compareResponses(const SecondOrderResponse& a, const StateSpace& b, const std::vector<double>& omegas) {
  return compareWith([&](std::size_t, double w) { return a.response(w); }, b, omegas);
}

ModelError compareResponses(const std::vector<Eigen::MatrixXcd>& a, const StateSpace& b, const std::vector<double>& omegas) {
  MMV_DEMAND(a.size() == omegas.size());
  return compareWith([&](std::size_t k, double) { return a[k]; }, b, omegas);
}

std::vector<Eigen::MatrixXcd> fullResponses(const SecondOrderResponse& h, const std::vector<double>& omegas) {
  // Frequencies are independent: spread over the cores (each response is computed the
  // same way on any thread, so the result does not depend on how many there are).
  std::vector<Eigen::MatrixXcd> out(omegas.size());
  const ProgressStage stage("frequency response of the full model");
  std::atomic<long> done{0};
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, omegas.size(), 8), [&](const tbb::blocked_range<std::size_t>& r) {
    for (std::size_t k = r.begin(); k != r.end(); ++k) {
      out[k] = h.response(omegas[k]);
      progressCount(++done, static_cast<long>(omegas.size()), "frequency");
    }
  });
  return out;
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

namespace {

/// The maximum of a unimodal f on [a, b] by Brent's method (golden section with
/// parabolic interpolation; Brent, Algorithms for Minimization without Derivatives,
/// 1973, ch. 5), to a bracket of 1e-9 of the abscissa: about a third of the
/// evaluations of golden section alone on a resonance peak.
template <class F>
std::pair<double, double> brentMaximum(const F& f, double a, double b) {
  const double c = 0.5 * (3.0 - std::sqrt(5.0));
  double x = a + c * (b - a), w = x, v = x, fx = -f(x), fw = fx, fv = fx, d = 0, e = 0;
  for (int it = 0; it < 100; ++it) {
    const double m = 0.5 * (a + b), tol = 2.5e-10 * std::abs(x) + 1e-300, t2 = 2 * tol;
    if (std::abs(x - m) <= t2 - 0.5 * (b - a)) break;
    bool golden = true;
    if (std::abs(e) > tol) {  // a parabola through x, w, v
      double r = (x - w) * (fx - fv), q = (x - v) * (fx - fw), p = (x - v) * q - (x - w) * r;
      q = 2 * (q - r);
      if (q > 0) p = -p;
      q = std::abs(q);
      const double e_old = e;
      e = d;
      if (std::abs(p) < std::abs(0.5 * q * e_old) && p > q * (a - x) && p < q * (b - x)) {
        d = p / q;
        golden = false;
        if (x + d - a < t2 || b - (x + d) < t2) d = x < m ? tol : -tol;
      }
    }
    if (golden) {
      e = (x < m ? b : a) - x;
      d = c * e;
    }
    const double u = x + (std::abs(d) >= tol ? d : (d > 0 ? tol : -tol)), fu = -f(u);
    if (fu <= fx) {
      (u < x ? b : a) = x;
      v = w, fv = fw, w = x, fw = fx, x = u, fx = fu;
    } else {
      (u < x ? a : b) = u;
      if (fu <= fw || w == x) {
        v = w, fv = fw, w = u, fw = fu;
      } else if (fu <= fv || v == x || v == w) {
        v = u, fv = fu;
      }
    }
  }
  return {x, -fx};
}

}  // namespace

PeakTable refinedPeaks(const SecondOrderResponse& h, const std::vector<double>& f,
                       const std::vector<Eigen::MatrixXcd>& responses) {
  MMV_DEMAND(!f.empty() && (responses.empty() || responses.size() == f.size()));
  const ProgressStage stage("refining the response peaks");
  std::vector<Eigen::MatrixXd> grid;
  grid.reserve(f.size());
  for (std::size_t k = 0; k < f.size(); ++k)
    grid.push_back((responses.empty() ? h.response(2 * M_PI * f[k]) : responses[k]).cwiseAbs());
  const Eigen::Index no = grid.front().rows(), ni = grid.front().cols();
  PeakTable t{Eigen::MatrixXd(no, ni), Eigen::MatrixXd(no, ni), Eigen::MatrixXd(no, ni)};
  // Each pair's search is sequential; the pairs are spread over the cores.
  tbb::parallel_for(Eigen::Index(0), no * ni, [&](Eigen::Index pair) {
    const Eigen::Index o = pair % no, i = pair / no;
    auto mag = [&](double hz) { return std::abs(h.response(2 * M_PI * hz)(o, i)); };
    std::size_t best = 0;
    for (std::size_t k = 0; k < f.size(); ++k)
      if (grid[k](o, i) > grid[best](o, i)) best = k;
    // Brent's search between the grid neighbours: parabolic steps near the (smooth)
    // peak, golden-section ones otherwise, to 1e-9 of the frequency.
    const auto [fpeak0, peak0] = brentMaximum(mag, f[best > 0 ? best - 1 : 0], f[std::min(best + 1, f.size() - 1)]);
    double fpeak = fpeak0, peak = peak0;
    if (grid[best](o, i) > peak) fpeak = f[best], peak = grid[best](o, i);
    t.hz(o, i) = fpeak;
    t.magnitude(o, i) = peak;
    // Half-power points: the first grid point on each side below peak / sqrt(2), then
    // bisection between it and its neighbour towards the peak, to 1e-9 of the frequency.
    const double half = peak / std::sqrt(2.0);
    auto crossing = [&](int dir) -> double {
      const std::ptrdiff_t n = static_cast<std::ptrdiff_t>(f.size());
      // The grid point next to the refined peak on this side, then outwards to half power.
      std::ptrdiff_t k = std::upper_bound(f.begin(), f.end(), fpeak) - f.begin();
      if (dir < 0) k = std::lower_bound(f.begin(), f.end(), fpeak) - f.begin() - 1;
      const std::ptrdiff_t first = k;
      while (k >= 0 && k < n && grid[k](o, i) >= half) k += dir;
      if (k < 0 || k >= n) return -1.0;  // not inside the grid
      double below = f[k], above = k == first ? fpeak : f[k - dir];
      for (int it = 0; it < 200 && std::abs(above - below) > 1e-9 * above; ++it) {
        const double mid = 0.5 * (above + below);
        (mag(mid) >= half ? above : below) = mid;
      }
      return 0.5 * (above + below);
    };
    const double f1 = crossing(-1), f2 = crossing(+1);
    t.half_power_damping(o, i) = f1 > 0 && f2 > 0 && fpeak > 0 ? (f2 - f1) / (2 * fpeak) : -1.0;
  });
  return t;
}

}  // namespace mmv
