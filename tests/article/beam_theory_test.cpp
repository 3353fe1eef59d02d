#include "article/beam_theory.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace mmv {
namespace {

// Classical cantilever roots (Blevins, Formulas for Natural Frequency and Mode Shape,
// table 8-1), quoted to 6 digits.
TEST(BeamTheory, CantileverRootsWithoutTipMass) {
  const auto r = cantileverTipMassRoots(0.0, 4);
  ASSERT_EQ(r.size(), 4u);
  EXPECT_NEAR(r[0], 1.875104, 1e-6);
  EXPECT_NEAR(r[1], 4.694091, 1e-6);
  EXPECT_NEAR(r[2], 7.854757, 1e-6);
  EXPECT_NEAR(r[3], 10.995541, 1e-6);
}

// With a tip mass the roots satisfy the frequency equation and fall as mu grows
// (a heavier tip lowers every frequency); mu = 1 gives 1.24792 (Blevins 8-1).
TEST(BeamTheory, TipMassRootsSolveTheEquationAndDecrease) {
  EXPECT_NEAR(cantileverTipMassRoots(1.0, 1)[0], 1.24792, 1e-5);
  std::vector<double> prev = cantileverTipMassRoots(0.0, 3);
  for (double mu : {0.1, 1.0, 5.0}) {
    const auto r = cantileverTipMassRoots(mu, 3);
    ASSERT_EQ(r.size(), 3u);
    for (int i = 0; i < 3; ++i) {
      const double x = r[i];
      const double eq = 1 + std::cos(x) * std::cosh(x) + mu * x * (std::cos(x) * std::sinh(x) - std::sin(x) * std::cosh(x));
      EXPECT_NEAR(eq / std::cosh(x), 0.0, 1e-12) << "mu " << mu << " root " << i;
      EXPECT_LT(r[i], prev[i]);
    }
    prev = r;
  }
}

TEST(BeamTheory, FrequencyFormulaMatchesReportLink3) {
  // Link 3 of the MMV article clamped-free with the report's rounded Table 1 values
  // (A = 5.07e-6 m^2, I = 2.04e-12 m^4): the report prints 3.287 Hz (4 digits).
  const double ei = 61.0e9 * 2.04e-12, rho_a = 2110 * 5.07e-6;
  EXPECT_NEAR(beamFrequencyHz(1.875104, 0.762, ei, rho_a), 3.287, 0.0005);
}

}  // namespace
}  // namespace mmv
