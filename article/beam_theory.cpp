#include "article/beam_theory.hpp"

#include <cmath>

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
