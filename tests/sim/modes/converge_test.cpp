#include "sim/modes/converge.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "article/beam_theory.hpp"
#include "sim/modes/system_modes.hpp"
#include "sim/scene/scene.hpp"
#include "support/scenes.hpp"

namespace mmv {
namespace {

// The study on a cantilever: the observed order is 2 and the Richardson value is
// closer to the exact frequency than the finest run (it removes the 1/N^2 term).
TEST(Converge, CantileverOrderAndRichardson) {
  const testing::Beam b;
  const ArticleScene s = testing::cantileverScene(b, 1, 0.0);
  const ConvergenceStudy c = runConvergence(s, 32, 3);
  ASSERT_EQ(c.runs.size(), 6u);  // 1, 2, 4, 8, 16, 32
  EXPECT_EQ(c.runs.back().segments, 32);
  EXPECT_EQ(c.runs.back().num_dofs, 32);
  const auto roots = cantileverTipMassRoots(0.0, 3);
  for (int i = 0; i < 3; ++i) {
    const ConvergenceMode& m = c.modes[i];
    ASSERT_TRUE(m.has_estimate && m.has_observed_order);
    EXPECT_NEAR(m.observed_order, 2.0, 0.1) << "mode " << i + 1;
    const double exact = beamFrequencyHz(roots[i], b.length, b.bendingStiffness(), b.massPerLength());
    EXPECT_LT(std::abs(m.extrapolated_hz - exact), std::abs(m.frequency_hz.back() - exact)) << "mode " << i + 1;
    EXPECT_GT(m.estimated_relative_error, 0.0);
    EXPECT_EQ(m.check, "ok") << "mode " << i + 1;
  }
  // N = 1 has one DOF: its column holds mode 1 only.
  EXPECT_TRUE(std::isfinite(c.modes[0].frequency_hz[0]));
  EXPECT_TRUE(std::isnan(c.modes[1].frequency_hz[0]));
}

// The closed tree at 1..16 segments: some modes are far from O(1/N^2) (the pinned
// tip's closure; modes trade places between runs). Those are flagged, and their error
// estimate is no longer Richardson's (which assumes order 2 and would claim 2.5 % for
// a mode whose two finest runs differ by 7 %).
TEST(Converge, ModesFarFromSecondOrderAreFlaggedAndNotUnderestimated) {
  const ArticleScene s = loadArticleSceneFile(MMVLAB_SOURCE_DIR "/scenes/mmv-closed.yaml");
  const ConvergenceStudy c = runConvergence(s, 16, 6);
  int flagged = 0;
  for (const ConvergenceMode& m : c.modes) {
    ASSERT_TRUE(m.has_estimate) << m.number;
    const double f1 = m.frequency_hz.back(), f2 = m.frequency_hz[m.frequency_hz.size() - 2];
    const double richardson = std::abs(f1 - f2) / 3 / std::abs(f1 + (f1 - f2) / 3);
    if (m.check == "ok") {
      EXPECT_NEAR(m.observed_order, 2.0, 0.5) << m.number;
      EXPECT_NEAR(m.estimated_relative_error, richardson, 1e-12) << m.number;
    } else {
      ++flagged;
      EXPECT_TRUE(m.check == "order" || m.check == "unconverged") << m.check;
      EXPECT_GT(m.estimated_relative_error, richardson) << m.number;
      if (m.check == "unconverged") EXPECT_DOUBLE_EQ(m.estimated_relative_error, std::abs(f1 - f2) / std::abs(f1));
    }
  }
  EXPECT_GE(flagged, 2);
}


}  // namespace
}  // namespace mmv

namespace mmv {
namespace {

// `modes`' own error estimate: the default article (16 segments per link) solved again
// at 4 and 8; the Richardson value is checked against the scene at 64 segments: for the
// first 8 modes the estimate is within a factor of 3 of the 16-segment run's actual
// error, and the extrapolation is closer than the 16-segment frequency.
TEST(Discretization, EstimateMatchesAFinerRun) {
  const ArticleScene s = loadDefaultScene();
  ModesOptions mo;
  mo.max_modes = 8;
  mo.with_shapes = false;
  const ModesReport own = runModes(s, mo);
  const std::vector<double> f16 = reportFrequencies(own);
  const DiscretizationEstimate e = estimateDiscretization(s, own);
  ASSERT_TRUE(e.available);
  EXPECT_EQ(e.divisors, (std::vector<int>{4, 2}));
  ArticleScene fine = s;
  overrideSegments(fine, 64);
  const ModesSolve f64 = solveSceneModes(fine, {}, 8);
  for (int i = 0; i < 8; ++i) {
    const ConvergenceMode& m = e.modes[i];
    EXPECT_EQ(m.check, "ok") << i;
    const double actual = std::abs(f16[i] - f64.frequencies_hz[i]) / f64.frequencies_hz[i];
    EXPECT_GT(m.estimated_relative_error, actual / 3) << i;
    EXPECT_LT(m.estimated_relative_error, actual * 3) << i;
    EXPECT_LT(std::abs(m.extrapolated_hz - f64.frequencies_hz[i]), std::abs(f16[i] - f64.frequencies_hz[i])) << i;
  }
  ArticleScene odd = s;
  overrideSegments(odd, 5);
  EXPECT_FALSE(estimateDiscretization(odd, own).available);
}


}  // namespace
}  // namespace mmv

namespace mmv {
namespace {

// `modes --target-error`: on a cantilever the segments chosen for 1e-3 give each of the
// first three frequencies within 1e-3 of the closed form; the count before did not
// meet its own estimate, so the choice is the fewest on the ladder.
TEST(SegmentsForTarget, TheChoiceMeetsTheClosedFormAndIsTheFewest) {
  const testing::Beam b;
  const ArticleScene s = testing::cantileverScene(b, 1, 0.0);
  const SegmentsChoice c = segmentsForTarget(s, 3, 1e-3, 256);
  ASSERT_GT(c.segments, 0);
  ASSERT_GE(c.ladder.size(), 2u);
  EXPECT_TRUE(c.ladder.back().met);
  EXPECT_FALSE(c.ladder[c.ladder.size() - 2].met);
  EXPECT_EQ(c.ladder.back().segments, c.segments);
  ArticleScene chosen = s;
  overrideSegments(chosen, c.segments);
  const ModesSolve sol = solveSceneModes(chosen, {}, 3);
  const auto roots = cantileverTipMassRoots(0.0, 3);
  for (int i = 0; i < 3; ++i) {
    const double exact = beamFrequencyHz(roots[i], b.length, b.bendingStiffness(), b.massPerLength());
    EXPECT_LE(std::abs(sol.frequencies_hz[i] / exact - 1), 1e-3) << "mode " << i + 1 << " at " << c.segments;
  }
  // Tighter targets need more segments; one past the ladder's end is refused, naming the best reached.
  EXPECT_GT(segmentsForTarget(s, 3, 1e-4, 256).segments, c.segments);
  try {
    segmentsForTarget(s, 3, 1e-9, 16);
    FAIL() << "1e-9 met with 16 segments";
  } catch (const NumericalError& e) {
    EXPECT_NE(std::string(e.what()).find("with up to 16 segments per link"), std::string::npos) << e.what();
  }
  EXPECT_THROW(segmentsForTarget(s, 3, 0.0, 16), InternalError);  // the study checks the target (sim/app)
  try {  // a budget spent before the target is met: refused, naming the budget and the level reached
    segmentsForTarget(s, 3, 1e-9, 256, 1e-9);
    FAIL() << "1e-9 met within 1e-9 s";
  } catch (const NumericalError& e) {
    EXPECT_NE(std::string(e.what()).find("within the 1e-09 s budget"), std::string::npos) << e.what();
  }
}

// The default article: the 12 modes at the count chosen for 1e-3 are within 1e-3 of a
// reference extrapolated from 256 and 512 segments per link.
TEST(SegmentsForTarget, TheDefaultArticleMeetsAFineReference) {
  const ArticleScene s = loadDefaultScene();
  const SegmentsChoice c = segmentsForTarget(s, 12, 1e-3, 256);
  ArticleScene a = s, fine = s, finer = s;
  overrideSegments(a, c.segments);
  overrideSegments(fine, 256);
  overrideSegments(finer, 512);
  const ModesSolve got = solveSceneModes(a, {}, 12), f1 = solveSceneModes(fine, {}, 12), f2 = solveSceneModes(finer, {}, 12);
  for (int i = 0; i < 12; ++i) {
    const double reference = f2.frequencies_hz[i] + (f2.frequencies_hz[i] - f1.frequencies_hz[i]) / 3;
    EXPECT_LE(std::abs(got.frequencies_hz[i] / reference - 1), 1e-3) << "mode " << i + 1 << " at " << c.segments;
  }
}


}  // namespace
}  // namespace mmv

namespace mmv {
namespace {

// A 20 x 5 mm aluminium strip, clamped, on the spatial model: in-plane bending,
// out-of-plane bending and torsion interleave, and not the same way on every mesh (at
// 64 segments mode 16 is in-plane and 17 torsion; at 32 the other way round). Pairing by
// index extrapolated an in-plane mode from torsion frequencies and called it converged.
// Each mode's ladder must now hold frequencies of its own family on every mesh: checked
// here against the coarse meshes solved on their own.
const char* const kStrip = R"(name: strip
gravity: [0, 0, 0]
model: spatial
materials: {aluminium: {density: 2700, youngs_modulus: 69e9, shear_modulus: 26e9}}
sections: {strip: {shape: rectangle, b: 0.02, h: 0.005}}
base: {position: [0, 0, 0], direction_deg: 0}
joints: [{name: root, parent: base, angle_deg: 0, hold: locked}]
links: [{name: strip, joint: root, material: aluminium, section: strip, length: 1.0, segments: 64}]
)";

TEST(Discretization, ModesArePairedWithinTheirFamilyAcrossMeshes) {
  const Scene parsed = parseScene(kStrip, "strip.yaml");
  const ArticleScene& s = std::get<ArticleScene>(parsed);
  ModesOptions mo;
  mo.max_modes = 22;
  mo.with_shapes = false;
  const ModesReport fine = runModes(s, mo);
  const DiscretizationEstimate e = estimateDiscretization(s, fine);
  ASSERT_TRUE(e.available);
  ASSERT_EQ(e.divisors, (std::vector<int>{4, 2}));
  std::vector<ModesReport> coarse;
  for (int n : {16, 32}) {
    ArticleScene c = s;
    overrideSegments(c, n);
    mo.max_modes = 40;
    coarse.push_back(runModes(c, mo));
  }
  int crossings = 0;
  for (std::size_t i = 0; i < fine.modes.size(); ++i) {
    const ConvergenceMode& m = e.modes[i];
    ASSERT_EQ(m.frequency_hz.size(), 3u);
    for (std::size_t k = 0; k < 2; ++k) {
      const auto it = std::find_if(coarse[k].modes.begin(), coarse[k].modes.end(),
                                   [&](const ModeInfo& c) { return c.frequency_hz == m.frequency_hz[k]; });
      ASSERT_NE(it, coarse[k].modes.end()) << "mode " << i + 1;
      EXPECT_EQ(it->family.label, fine.modes[i].family.label) << "mode " << i + 1 << " at " << (k ? 32 : 16) << " segments";
      crossings += it->number != ModeNumber::atIndex(static_cast<int>(i));  // where pairing by index would have gone wrong
    }
  }
  EXPECT_GE(crossings, 2);  // the case is one that needs it
  // Mode 16 (in-plane) does not converge monotonically on this model (docs/spatial.md):
  // said so, not extrapolated from the torsion mode beside it.
  EXPECT_EQ(fine.modes[15].family.label, "in-plane");
  EXPECT_NE(e.modes[15].check, "ok");
  EXPECT_EQ(fine.modes[16].family.label, "torsion");
  EXPECT_EQ(e.modes[16].check, "ok");
}

/// The cantilever's k-th root of 1 + cos(b) cosh(b) = 0 (bisection).
double cantileverRoot(int k) {
  double lo = (k - 0.5) * M_PI - 1.0, hi = (k - 0.5) * M_PI + 1.0;
  if (k == 1) lo = 1.0, hi = 2.5;
  auto g = [](double b) { return 1 + std::cos(b) * std::cosh(b); };
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (g(lo) * g(mid) <= 0 ? hi : lo) = mid;
  }
  return 0.5 * (lo + hi);
}

/// The cantilever mode's integral of phi'^2 over that of phi^2 (L = 1), phi written so
/// that the exponentials do not cancel (1 - sigma ~ e^-beta computed as such); Simpson.
double slopeToDisplacementRatio(double beta) {
  const double sigma = (std::cosh(beta) + std::cos(beta)) / (std::sinh(beta) + std::sin(beta));
  const double one_minus = (-std::exp(-beta) + std::sin(beta) - std::cos(beta)) / (std::sinh(beta) + std::sin(beta));
  auto phi = [&](double x) {
    return 0.5 * (one_minus * std::exp(beta * x) + (1 + sigma) * std::exp(-beta * x)) - std::cos(beta * x) + sigma * std::sin(beta * x);
  };
  auto slope = [&](double x) {
    return beta * (0.5 * (one_minus * std::exp(beta * x) - (1 + sigma) * std::exp(-beta * x)) + std::sin(beta * x) + sigma * std::cos(beta * x));
  };
  const int n = 4000;
  double a = 0, b = 0;
  for (int i = 0; i <= n; ++i) {
    const double x = static_cast<double>(i) / n, w = (i == 0 || i == n) ? 1 : (i % 2 ? 4 : 2);
    a += w * slope(x) * slope(x);
    b += w * phi(x) * phi(x);
  }
  return a / b;
}

// The spatial pieces' rotary inertia (spatialPieceBody): a short piece needs some to be a
// valid rigid body, and it now gets the section's own, m I/A about the in-plane bending
// axis and m I_out/A about the other. Before, both got m (I + I_out)/(2A), 8.5 times the
// true in-plane value for this strip, and its in-plane modes went +1.5e-3 (64 segments),
// +3.6e-4 (128), -2.5e-3 (256) about the beam's: no limit. Now every refinement moves
// each in-plane mode down towards one value, at second order, and that value is the
// Rayleigh beam's (Euler-Bernoulli with the section's rotary inertia: from the Rayleigh
// quotient, to first order f_EB (1 - r^2 int phi'^2 / (2 int phi^2)), r^2 = I/A, about
// 1e-3 here), the continuum this model converges to.
TEST(Discretization, AThickStripsInPlaneModesConvergeToTheRayleighBeam) {
  const Scene parsed = parseScene(kStrip, "strip.yaml");
  std::vector<std::vector<double>> in_plane;  // per mesh, the in-plane modes' frequencies
  for (int n : {64, 128, 256}) {
    ArticleScene s = std::get<ArticleScene>(parsed);
    overrideSegments(s, n);
    ModesOptions mo;
    mo.max_modes = 22;
    mo.with_shapes = false;
    std::vector<double> f;
    for (const ModeInfo& m : runModes(s, mo).modes)
      if (m.family.label == "in-plane") f.push_back(m.frequency_hz);
    in_plane.push_back(f);
  }
  const double E = 69e9, rho = 2700, b = 0.02, h = 0.005, L = 1.0, A = b * h, I = b * h * h * h / 12, r2 = I / A;
  ASSERT_GE(in_plane[2].size(), 10u);
  for (std::size_t k = 0; k < 10; ++k) {
    const double f1 = in_plane[0][k], f2 = in_plane[1][k], f3 = in_plane[2][k];
    EXPECT_GT(f1, f2) << "in-plane mode " << k + 1;  // from above, every refinement
    EXPECT_GT(f2, f3) << "in-plane mode " << k + 1;
    const double order = std::log2((f1 - f2) / (f2 - f3));
    if (k >= 2) EXPECT_NEAR(order, 2.0, 0.3) << "in-plane mode " << k + 1;  // the lowest two: round-off
    const double beta = cantileverRoot(static_cast<int>(k) + 1);
    const double eb = beta * beta / (2 * M_PI * L * L) * std::sqrt(E * I / (rho * A));
    const double rayleigh = eb * (1 - 0.5 * r2 * slopeToDisplacementRatio(beta) / (L * L));
    const double extrapolated = f3 + (f3 - f2) / 3;
    EXPECT_NEAR(extrapolated / rayleigh - 1, 0.0, 3e-6) << "in-plane mode " << k + 1 << ": " << extrapolated << " Hz, Rayleigh "
                                                       << rayleigh << ", Euler-Bernoulli " << eb;
  }
}


// The spatial article under gravity: every one of its first nine modes, the
// torsion-coupled ones included, falls monotonically at second order from 4 to 16
// segments (below the meshes where the pieces start to carry their section's rotary
// inertia, docs/spatial.md). With springs on the hinges' gimbal angles (before the
// rotation vector, sim/model/rotation_spring.hpp) gravity's in-plane bend coupled twist
// and out-of-plane bending by O(h): mode 8 went 6.59448, 6.59099, 6.59532 Hz (not
// monotone) and mode 2 converged at order 1.7 here, 1.1 from 32 to 256 segments.
TEST(Discretization, TheSpatialArticleUnderGravityConvergesAtSecondOrder) {
  ArticleScene s = loadDefaultScene();
  s.article.model = ArticleModel::Spatial;
  const ConvergenceStudy c = runConvergence(s, 16, 9);
  ASSERT_EQ(c.runs.back().segments, 16);
  ASSERT_EQ(c.modes.size(), 9u);
  for (const ConvergenceMode& m : c.modes) {
    const std::size_t n = m.frequency_hz.size();
    const double f4 = m.frequency_hz[n - 3], f8 = m.frequency_hz[n - 2], f16 = m.frequency_hz[n - 1];
    EXPECT_GT(f4, f8) << "mode " << m.number;  // from above, as a chain of hinged pieces
    EXPECT_GT(f8, f16) << "mode " << m.number;
    ASSERT_TRUE(m.has_observed_order) << "mode " << m.number;
    EXPECT_NEAR(m.observed_order, 2.0, 0.1) << "mode " << m.number << ": " << f4 << ", " << f8 << ", " << f16 << " Hz";
    EXPECT_EQ(m.check, "ok") << "mode " << m.number;
  }
}

// An observed order above the scheme's 2 (meshes short of the asymptotic range) may not
// shrink the estimate below Richardson's: on 4.454, 3.430, 3.280 Hz (the spatial
// article's mode 3 at 1, 2 and 4 segments, observed order 2.8, 1.45 % above its
// converged 3.2325 Hz) the estimate is |f4 - f2| / 3 / f4, not / (2^2.8 - 1).
TEST(Discretization, AnOrderAboveTwoDoesNotShrinkTheEstimate) {
  const ConvergenceMode m = assessLadder(ModeNumber(3), {4.45419, 3.43002, 3.27969});
  EXPECT_EQ(m.check, "order");
  EXPECT_NEAR(m.observed_order, 2.77, 0.01);
  EXPECT_NEAR(m.estimated_relative_error, (3.43002 - 3.27969) / 3 / 3.27969, 1e-12);
  EXPECT_GT(m.estimated_relative_error, 0.01);  // so a 1 % target goes on to 8 segments
  // Slower than 2, the observed order still makes the estimate larger.
  const ConvergenceMode slow = assessLadder(ModeNumber(1), {1.0 + 0.4, 1.0 + 0.2, 1.0 + 0.1});
  EXPECT_NEAR(slow.observed_order, 1.0, 1e-12);
  EXPECT_NEAR(slow.estimated_relative_error, 0.1 / 1 / 1.1, 1e-12);
}

}  // namespace
}  // namespace mmv
