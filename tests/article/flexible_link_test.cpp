// The discretization of a flexible link (article/flexible_link.hpp) against
// Euler-Bernoulli theory, through the whole pipeline (scene -> Simbody -> modes).

#include "article/flexible_link.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "article/beam_theory.hpp"
#include "sim/model/article_builder.hpp"
#include "sim/modes/system_modes.hpp"
#include "support/scenes.hpp"

namespace mmv {
namespace {

using testing::Beam;
using testing::cantileverScene;

TEST(FlexibleLink, PiecesCarryTheWholeLinkAndHingesSitAtElementMidpoints) {
  const LinkDiscretization d = discretizeLink(2.0, 3.0, 50.0, 4, false);
  ASSERT_EQ(d.pieces.size(), 5u);
  ASSERT_EQ(d.hinge_x.size(), 4u);
  double mass = 0, length = 0;
  for (const auto& p : d.pieces) {
    mass += p.mass;
    length += p.length;
    EXPECT_NEAR(p.inertia_zz_about_com, p.mass * p.length * p.length / 12, 1e-15);
  }
  EXPECT_NEAR(mass, 6.0, 1e-14);
  EXPECT_NEAR(length, 2.0, 1e-14);
  for (int k = 0; k < 4; ++k) {
    EXPECT_NEAR(d.hinge_x[k], (k + 0.5) * 0.5, 1e-14);
    EXPECT_NEAR(d.hinge_stiffness[k], 50.0 / 0.5, 1e-12);
    EXPECT_NEAR(d.pieces[k + 1].x_start, d.hinge_x[k], 1e-14);
  }
  const LinkDiscretization r = discretizeLink(2.0, 3.0, 50.0, 4, true);
  ASSERT_EQ(r.pieces.size(), 1u);
  EXPECT_TRUE(r.hinge_x.empty());
}

double cantileverFrequencyHz(const Beam& b, int segments, double mu, int mode) {
  const ArticleScene s = cantileverScene(b, segments, 0.0, 0.0, mu * b.massPerLength() * b.length);
  return solveSceneModes(s).frequencies_hz[mode];
}

// docs/sources.md section 4: clamped-free Euler-Bernoulli beam with a tip mass ratio mu.
// At 64 segments the measured discretization error is 0.003-0.006 % for mode 1 and
// 0.029-0.032 % for mode 3 over these mass ratios, so 0.1 % leaves a margin of 3.
class CantileverTipMass : public ::testing::TestWithParam<double> {};

TEST_P(CantileverTipMass, FirstThreeFrequenciesWithinPointOnePercent) {
  const double mu = GetParam();
  const Beam b;
  const auto roots = cantileverTipMassRoots(mu, 3);
  ASSERT_EQ(roots.size(), 3u);
  for (int i = 0; i < 3; ++i) {
    const double exact = beamFrequencyHz(roots[i], b.length, b.bendingStiffness(), b.massPerLength());
    const double f = cantileverFrequencyHz(b, 64, mu, i);
    EXPECT_NEAR(f / exact - 1.0, 0.0, 1e-3) << "mu " << mu << " mode " << i + 1;
  }
}

// The error must fall as 1/N^2: the order observed between 16, 32 and 64 segments is 2
// within 0.1 (the next term of the error expansion is O(1/N^4), so at these N the
// observed order differs from 2 by well under 0.1).
TEST_P(CantileverTipMass, ConvergesAtSecondOrder) {
  const double mu = GetParam();
  const Beam b;
  const auto roots = cantileverTipMassRoots(mu, 3);
  for (int i = 0; i < 3; ++i) {
    const double exact = beamFrequencyHz(roots[i], b.length, b.bendingStiffness(), b.massPerLength());
    const double e16 = std::abs(cantileverFrequencyHz(b, 16, mu, i) - exact);
    const double e32 = std::abs(cantileverFrequencyHz(b, 32, mu, i) - exact);
    const double e64 = std::abs(cantileverFrequencyHz(b, 64, mu, i) - exact);
    EXPECT_NEAR(std::log2(e16 / e32), 2.0, 0.1) << "mu " << mu << " mode " << i + 1;
    EXPECT_NEAR(std::log2(e32 / e64), 2.0, 0.1) << "mu " << mu << " mode " << i + 1;
  }
}

INSTANTIATE_TEST_SUITE_P(MassRatios, CantileverTipMass, ::testing::Values(0.0, 0.1, 1.0, 5.0));

// The report's link 3 (one S-glass branch) alone, clamped-free, no gravity: Table 2
// prints 3.287, 20.60, 57.68, 113.0 Hz. Required within 0.5 % (the report's own
// rounding is 0.02-0.05 %; 32 segments put our discretization error under 0.1 %).
TEST(FlexibleLink, ReportLink3ClampedFree) {
  Beam b;
  b.length = 0.762;
  b.density = 2110;
  b.youngs = 61.0e9;
  b.area = M_PI * 0.00127 * 0.00127;
  b.second_moment = M_PI * std::pow(0.00127, 4) / 4;
  const ArticleScene s = cantileverScene(b, 32, 0.0);
  const auto f = solveSceneModes(s).frequencies_hz;
  const double report[] = {3.287, 20.60, 57.68, 113.0};
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(f[i] / report[i] - 1.0, 0.0, 5e-3) << "mode " << i + 1;
}

TEST(FlexibleLink, RigidLinkIsOneBodyWithoutDegreesOfFreedomWhenHeld) {
  const ArticleScene s = cantileverScene(Beam{}, 8, 9.81, 0.0, 0.0, true);
  const auto model = buildArticleModel(s);
  EXPECT_EQ(model->getNumCoordinates(), 1);  // the held joint only
  EXPECT_TRUE(model->getDofs().empty());
}

}  // namespace
}  // namespace mmv
