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

// The general boundary determinant against the classical roots (Blevins, table 8-1):
// clamped-pinned and pinned-free share 3.92660, 7.06858, 10.21018; free-free and
// clamped-clamped 4.73004, 7.85320, 10.99561; pinned-pinned n pi.
TEST(BeamTheory, BoundaryDeterminantClassicalRoots) {
  auto expect = [](BeamEnd r, BeamEnd t, std::vector<double> want, const char* what) {
    const auto got = beamRoots(r, t, 0.0, 0.0, static_cast<int>(want.size()));
    ASSERT_EQ(got.size(), want.size()) << what;
    for (std::size_t i = 0; i < want.size(); ++i) EXPECT_NEAR(got[i], want[i], 2e-5) << what << " root " << i;
  };
  expect(BeamEnd::Clamped, BeamEnd::Free, {1.875104, 4.694091, 7.854757}, "clamped-free");
  expect(BeamEnd::Clamped, BeamEnd::Pinned, {3.926602, 7.068583, 10.210176}, "clamped-pinned");
  expect(BeamEnd::Pinned, BeamEnd::Free, {3.926602, 7.068583, 10.210176}, "pinned-free");
  expect(BeamEnd::Free, BeamEnd::Free, {4.730041, 7.853205, 10.995608}, "free-free");
  expect(BeamEnd::Clamped, BeamEnd::Clamped, {4.730041, 7.853205, 10.995608}, "clamped-clamped");
  expect(BeamEnd::Pinned, BeamEnd::Pinned, {M_PI, 2 * M_PI, 3 * M_PI}, "pinned-pinned");
}

// Two independent routes to the cantilever with a tip mass: the determinant and the
// closed frequency equation must give the same roots.
TEST(BeamTheory, BoundaryDeterminantAgreesWithTipMassEquation) {
  for (double mu : {0.1, 1.0, 1.7984, 5.0}) {
    const auto a = beamRoots(BeamEnd::Clamped, BeamEnd::Free, mu, 0.0, 3);
    const auto b = cantileverTipMassRoots(mu, 3);
    ASSERT_EQ(a.size(), 3u);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(a[i], b[i], 1e-9) << "mu " << mu;
  }
  // A tip rotary inertia lowers every root.
  const auto with_j = beamRoots(BeamEnd::Clamped, BeamEnd::Free, 1.0, 0.05, 3);
  const auto without = beamRoots(BeamEnd::Clamped, BeamEnd::Free, 1.0, 0.0, 3);
  for (int i = 0; i < 3; ++i) EXPECT_LT(with_j[i], without[i]);
}

TEST(BeamTheory, FrequencyFormulaMatchesReportLink3) {
  // Link 3 of the MMV article clamped-free with the report's rounded Table 1 values
  // (A = 5.07e-6 m^2, I = 2.04e-12 m^4): the report prints 3.287 Hz (4 digits).
  const double ei = 61.0e9 * 2.04e-12, rho_a = 2110 * 5.07e-6;
  EXPECT_NEAR(beamFrequencyHz(1.875104, 0.762, ei, rho_a), 3.287, 0.0005);
}

}  // namespace
}  // namespace mmv

namespace mmv {
namespace {

// Torsion of a shaft with a tip disk: the classical roots without the disk, the
// frequency equation at every root with it, and the heavy-disk limit (a rigid disk on
// the shaft's torsion spring G J / L: beta^2 = rho I_p L / J_d = 1 / r).
TEST(BeamTheory, TorsionRootsWithAndWithoutATipDisk) {
  const auto clamped = torsionRoots(BeamEnd::Clamped, 0.0, 3), free_root = torsionRoots(BeamEnd::Free, 0.0, 3);
  ASSERT_EQ(clamped.size(), 3u);
  ASSERT_EQ(free_root.size(), 3u);
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(clamped[k], (2 * k + 1) * M_PI / 2, 1e-12);
    EXPECT_NEAR(free_root[k], (k + 1) * M_PI, 1e-12);
  }
  for (double r : {0.1, 1.0, 30.0}) {
    for (double b : torsionRoots(BeamEnd::Clamped, r, 3)) EXPECT_NEAR(b * std::tan(b), 1.0 / r, 1e-9 * (1 + 1 / r));
    for (double b : torsionRoots(BeamEnd::Free, r, 3)) EXPECT_NEAR(std::tan(b), -r * b, 1e-9 * (1 + r * b));
  }
  const double r = 1e6;
  EXPECT_NEAR(torsionRoots(BeamEnd::Clamped, r, 1).at(0), 1 / std::sqrt(r), 1e-6 / std::sqrt(r));
  EXPECT_NEAR(torsionFrequencyHz(M_PI / 2, 2.0, 4.0, 1.0), M_PI / 2 / (2 * M_PI * 2.0) * 2.0, 1e-15);
}

}  // namespace
}  // namespace mmv
