#include "article/beam_theory.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace mmv {

std::vector<double> findRoots(const std::function<double(double)>& f, double lo, double hi,
                              double step, int count) {
  std::vector<double> roots;
  double a = lo, fa = f(a);
  for (double b = lo + step; b <= hi && static_cast<int>(roots.size()) < count; b += step) {
    const double fb = f(b);
    if (fa == 0.0) {
      roots.push_back(a);
    } else if (std::signbit(fa) != std::signbit(fb) && fb != 0.0) {
      double l = a, r = b, fl = fa;
      for (int i = 0; i < 200 && r - l > 1e-15 * std::abs(r); ++i) {
        const double m = 0.5 * (l + r), fm = f(m);
        if (std::signbit(fm) == std::signbit(fl)) {
          l = m;
          fl = fm;
        } else {
          r = m;
        }
      }
      roots.push_back(0.5 * (l + r));
    }
    a = b;
    fa = fb;
  }
  return roots;
}

std::vector<double> cantileverTipMassRoots(double mu, int count) {
  // Divided by cosh(bL) so the function stays bounded for large bL.
  auto f = [mu](double x) {
    const double th = std::tanh(x);
    return 1.0 / std::cosh(x) + std::cos(x) + mu * x * (std::cos(x) * th - std::sin(x));
  };
  return findRoots(f, 1e-6, 100.0, 1e-3, count);
}

namespace {

/// Determinant of the 4x4 boundary matrix at lambda.
double boundaryDeterminant(BeamEnd root, BeamEnd tip, double mu, double j, double l) {
  double a[4][4];
  // Root rows (x = 0): cos = cosh = 1, sin = sinh = 0; derivatives divided by l^k.
  const double w0[4] = {1, 0, 1, 0}, d1[4] = {0, 1, 0, 1}, d2[4] = {-1, 0, 1, 0}, d3[4] = {0, -1, 0, 1};
  const double* r0 = root == BeamEnd::Free ? d2 : w0;
  const double* r1 = root == BeamEnd::Clamped ? d1 : root == BeamEnd::Pinned ? d2 : d3;
  for (int k = 0; k < 4; ++k) {
    a[0][k] = r0[k];
    a[1][k] = r1[k];
  }
  // Tip rows (x = 1), scaled by 1/cosh(l).
  const double c = std::cos(l), s = std::sin(l), ch = 1.0, sh = std::tanh(l), e = 1.0 / std::cosh(l);
  const double w[4] = {c * e, s * e, ch, sh};
  const double w1[4] = {-s * e, c * e, sh, ch};        // w' / l
  const double w2[4] = {-c * e, -s * e, ch, sh};       // w'' / l^2
  const double w3[4] = {s * e, -c * e, sh, ch};        // w''' / l^3
  for (int k = 0; k < 4; ++k) {
    const double moment = w2[k] - std::pow(l, 3) * j * w1[k];  // (w'' - l^4 j w') / l^2
    const double shear = w3[k] + l * mu * w[k];                  // (w''' + l^4 mu w) / l^3
    switch (tip) {
      case BeamEnd::Clamped: a[2][k] = w[k]; a[3][k] = w1[k]; break;
      case BeamEnd::Pinned: a[2][k] = w[k]; a[3][k] = moment; break;
      case BeamEnd::Free: a[2][k] = moment; a[3][k] = shear; break;
    }
  }
  // Determinant by expansion (Gaussian elimination with partial pivoting).
  double det = 1.0;
  for (int col = 0; col < 4; ++col) {
    int piv = col;
    for (int r = col + 1; r < 4; ++r)
      if (std::abs(a[r][col]) > std::abs(a[piv][col])) piv = r;
    if (a[piv][col] == 0.0) return 0.0;
    if (piv != col) {
      for (int k = 0; k < 4; ++k) std::swap(a[piv][k], a[col][k]);
      det = -det;
    }
    det *= a[col][col];
    for (int r = col + 1; r < 4; ++r) {
      const double f = a[r][col] / a[col][col];
      for (int k = col; k < 4; ++k) a[r][k] -= f * a[col][k];
    }
  }
  return det;
}

}  // namespace

std::vector<double> beamRoots(BeamEnd root, BeamEnd tip, double mu, double j, int count) {
  auto f = [&](double l) { return boundaryDeterminant(root, tip, mu, j, l); };
  // Rigid-body roots sit at 0; the first elastic root of any case here is above 0.05
  // for mu, j up to ~1e4.
  return findRoots(f, 0.02, 200.0, 1e-3, count);
}

std::vector<double> torsionRoots(BeamEnd root, double r, int count) {
  const bool free_root = root == BeamEnd::Free;
  auto f = [&](double b) { return free_root ? std::sin(b) + r * b * std::cos(b) : std::cos(b) - r * b * std::sin(b); };
  // A heavy disk pulls the first root of a clamped shaft down to about 1/sqrt(r): the
  // scan's step resolves it; roots k sit below k pi.
  const double step = std::min(1e-3, 0.05 / std::sqrt(1.0 + r));
  return findRoots(f, step, (count + 1) * M_PI, step, count);
}

double torsionFrequencyHz(double beta, double length, double torsion_stiffness, double polar_inertia_per_length) {
  return beta / (2.0 * M_PI * length) * std::sqrt(torsion_stiffness / polar_inertia_per_length);
}

double beamFrequencyHz(double beta_l, double length, double bending_stiffness,
                       double mass_per_length) {
  return beta_l * beta_l / (2.0 * M_PI * length * length) *
         std::sqrt(bending_stiffness / mass_per_length);
}

double cantileverSelfWeightTipDeflection(double w, double length, double bending_stiffness) {
  return w * std::pow(length, 4) / (8.0 * bending_stiffness);
}

double cantileverTipLoadDeflection(double p, double length, double bending_stiffness) {
  return p * std::pow(length, 3) / (3.0 * bending_stiffness);
}

}  // namespace mmv
