// timeResponse (sim/linear/time_response.hpp) against closed forms: an oscillator's step
// response, and a ramp (linear between samples, so the first-order hold is exact at any
// step) at a coarse and a fine step.
#include "sim/linear/time_response.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace mmv {
namespace {

StateSpace oscillator(double wn, double zeta) {
  StateSpace s;
  s.E = Eigen::MatrixXd::Identity(2, 2);
  s.A.resize(2, 2);
  s.A << 0, 1, -wn * wn, -2 * zeta * wn;
  s.B.resize(2, 1);
  s.B << 0, 1;
  s.C.resize(1, 2);
  s.C << 1, 0;
  s.D = Eigen::MatrixXd::Zero(1, 1);
  return s;
}

// x'' + 2 zeta wn x' + wn^2 x = 1 from rest:
// x = (1 - e^{-zeta wn t} (cos wd t + zeta wn / wd sin wd t)) / wn^2.
TEST(TimeResponse, AnOscillatorsStepResponseIsTheClosedForm) {
  const double wn = 2 * M_PI * 3.0, zeta = 0.02, wd = wn * std::sqrt(1 - zeta * zeta), dt = 0.01;
  const Eigen::MatrixXd y = timeResponse(oscillator(wn, zeta), [](double) { return Eigen::VectorXd::Ones(1); }, dt, 300);
  ASSERT_EQ(y.rows(), 301);
  double worst = 0;
  for (int k = 0; k <= 300; ++k) {
    const double t = k * dt;
    const double exact = (1 - std::exp(-zeta * wn * t) * (std::cos(wd * t) + zeta * wn / wd * std::sin(wd * t))) / (wn * wn);
    worst = std::max(worst, std::abs(y(k, 0) - exact));
  }
  EXPECT_LT(worst, 1e-12 / (wn * wn));
}

// A ramp is linear between any samples: the 0.1 s and 0.001 s steps give the same
// response at their common times, stiff (1 kHz) mode and all, to the round-off of 2000
// steps (1e-10 seen; a hold that were not exact would be off by O(dt^2), 1e-3 here).
TEST(TimeResponse, ARampIsExactAtAnyStep) {
  const StateSpace s = oscillator(2 * M_PI * 1000.0, 0.05);
  const auto ramp = [](double t) { return Eigen::VectorXd::Constant(1, 3.0 * t); };
  const Eigen::MatrixXd coarse = timeResponse(s, ramp, 0.1, 20), fine = timeResponse(s, ramp, 0.001, 2000);
  for (int k = 0; k <= 20; ++k) EXPECT_NEAR(coarse(k, 0), fine(100 * k, 0), 1e-9 * std::abs(fine(100 * k, 0)) + 1e-18) << k;
}

}  // namespace
}  // namespace mmv
