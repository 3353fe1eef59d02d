// The default fidelity of a time run (sim/time/fidelity.hpp): a scene file that names
// neither an integrator nor a fidelity gets links in modal coordinates, with the modes
// its programs excite, or the segment model with the reason; and the choice meets the
// accuracy `--verify` states, which sees the modes left out.
#include "sim/time/fidelity.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <functional>

#include "facility/slews.hpp"
#include "sim/time/modal_links.hpp"
#include "sim/time/simulation.hpp"
#include "sim/time/verify.hpp"
#include "support/scenes.hpp"

namespace mmv {
namespace {

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

ArticleScene userTableScene(int segments) { return testing::templateOnTheTable(segments, 2.0); }

TEST(Fidelity, AFileThatNamesNeitherLeavesBothToTheRun) {
  const ArticleScene s = loadDefaultScene();
  EXPECT_EQ(s.simulation.fidelity, SimulationSpec::Fidelity::Auto);
  EXPECT_EQ(s.simulation.integrator, "");
  // A spec built in code keeps what it says.
  EXPECT_EQ(SimulationSpec{}.fidelity, SimulationSpec::Fidelity::Segments);
}

// The rule: each link's modes up to 10 x the band, at least 4, under CVODE BDF when the
// scene names no integrator. The band of each program two ways: the table's random
// program's top line, and a cycloidal slew's main lobe 2 / T with T from the slew's
// rate and acceleration limits (the larger of 2 d / w and sqrt(2 pi d / a)).
TEST(Fidelity, TheRuleTakesTheBandOfTheScenesPrograms) {
  ArticleScene table = userTableScene(16);
  const FidelityChoice c = resolveFidelity(table);
  EXPECT_TRUE(c.modal && c.by_rule);
  EXPECT_DOUBLE_EQ(c.band_hz, 10.0);
  EXPECT_DOUBLE_EQ(c.cutoff_hz, 100.0);
  EXPECT_EQ(table.simulation.integrator, "cvode_bdf");
  for (const auto& l : table.article.links) EXPECT_EQ(l.modes_up_to_hz.value_or(-1), 100.0) << l.name;
  EXPECT_TRUE(has(c.reason, "each link's modes up to 100 Hz (10 x the 10 Hz the table's program reaches), at least 4"))
      << c.reason;
  EXPECT_TRUE(has(c.reason, "simulation.fidelity: segments")) << c.reason;

  ArticleScene held = loadDefaultScene();
  const FidelityChoice h = resolveFidelity(held);
  EXPECT_TRUE(h.modal);
  EXPECT_EQ(h.band_hz, 0.0);
  EXPECT_TRUE(has(h.reason, "first 4 modes (no program moves the article)")) << h.reason;

  ArticleScene slewed = loadDefaultScene();
  SlewSpec sl;
  const double d = 40 * M_PI / 180;
  sl.to = slewed.article.joints[1].angle - d;
  slewed.article.joints[1].slew = sl;
  const double T = std::max(2 * d / sl.max_rate, std::sqrt(2 * M_PI * d / sl.max_acceleration));
  const FidelityChoice s = resolveFidelity(slewed);
  EXPECT_TRUE(s.modal);
  EXPECT_NEAR(s.band_hz, 2 / T, 1e-9);
  EXPECT_EQ(s.band_from, "joint2's slew");
  // A named ODE method is kept.
  ArticleScene named = userTableScene(16);
  named.simulation.integrator = "arkode_dirk";
  EXPECT_TRUE(resolveFidelity(named).modal);
  EXPECT_EQ(named.simulation.integrator, "arkode_dirk");
}

TEST(Fidelity, TheSegmentModelStaysWhereModalLinksCannotCarryTheRun) {
  const auto segments = [](ArticleScene s, const std::string& why, const std::string& integrator) {
    const FidelityChoice c = resolveFidelity(s);
    EXPECT_FALSE(c.modal) << why;
    EXPECT_TRUE(has(c.reason, "every hinge its own coordinate")) << c.reason;
    EXPECT_TRUE(has(c.reason, why)) << c.reason;
    EXPECT_EQ(s.simulation.integrator, integrator) << why;
    for (const auto& l : s.article.links) EXPECT_FALSE(l.modal()) << why;
  };
  ArticleScene closed = loadArticleSceneFile(MMVLAB_SOURCE_DIR "/scenes/mmv-closed.yaml");
  closed.simulation.integrator.clear();
  segments(closed, "the closures close the tree", "cpodes");
  closed.simulation.absolute_tolerance = 1e-9;  // CPodes takes none; IDA holds the closures
  segments(closed, "the closures close the tree", "ida");

  ArticleScene trapezoid = loadDefaultScene();
  SlewSpec sl;
  sl.to = trapezoid.article.joints[1].angle - 0.5;
  sl.trapezoidal = true;
  trapezoid.article.joints[1].slew = sl;
  segments(trapezoid, "joint2's slew is a trapezoidal move", "cpodes");

  ArticleScene explicit_method = userTableScene(16);
  explicit_method.simulation.integrator = "rk_merson";
  segments(explicit_method, "the scene's integrator, rk_merson, cannot carry", "rk_merson");

  ArticleScene asked = userTableScene(16);
  asked.simulation.fidelity = SimulationSpec::Fidelity::Segments;
  segments(asked, "(the segment model)", "cpodes");
  asked.simulation.absolute_tolerance = 1e-9;
  segments(asked, "(the segment model)", "cvode_bdf");

  // A link's own `modes:` is the scene's choice, kept as written.
  ArticleScene own = userTableScene(16);
  own.article.links[0].modes = 2;
  const FidelityChoice c = resolveFidelity(own);
  EXPECT_TRUE(c.modal);
  EXPECT_FALSE(c.by_rule);
  EXPECT_EQ(own.article.links[0].modes, 2);
  EXPECT_FALSE(own.article.links[1].modal());
}

// A release's static shares two ways: (phi_j^T f)^2 / lambda_j, and the static response
// u = K^-1 f split into its modes (q_j = phi_j^T M u, energy lambda_j q_j^2 of u^T K u).
TEST(Fidelity, AReleasesStaticSharesAreTheStaticResponseSplitIntoModes) {
  const int h = 7;
  std::srand(7);
  const Eigen::MatrixXd A = Eigen::MatrixXd::Random(h, h), B = Eigen::MatrixXd::Random(h, h);
  const Eigen::MatrixXd K = A * A.transpose() + h * Eigen::MatrixXd::Identity(h, h);
  const Eigen::MatrixXd M = B * B.transpose() + Eigen::MatrixXd::Identity(h, h);
  const Eigen::VectorXd f = Eigen::VectorXd::Random(h);
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> eig(K, M);
  const Eigen::VectorXd shares = staticShares(eig.eigenvectors(), eig.eigenvalues(), f);
  const Eigen::VectorXd u = K.ldlt().solve(f);
  const Eigen::VectorXd q = eig.eigenvectors().transpose() * M * u;
  for (int j = 0; j < h; ++j)
    EXPECT_NEAR(shares[j], eig.eigenvalues()[j] * q[j] * q[j] / u.dot(K * u), 1e-12) << j;
  EXPECT_NEAR(shares.sum(), 1.0, 1e-12);
  EXPECT_EQ(staticShares(eig.eigenvectors(), eig.eigenvalues(), Eigen::VectorXd::Zero(h)).sum(), 0.0);
  // The rule at its bound: the modes left out may carry kReleaseStaticShare, not more.
  Eigen::VectorXd s(6);
  s << 0.9, 0.05, 0.03, 0.01, 0.009, kReleaseStaticShare;
  EXPECT_EQ(modesForRelease(s, 4), 5);
  s[5] = kReleaseStaticShare * (1 + 1e-6);
  EXPECT_EQ(modesForRelease(s, 4), 6);
  s[4] = 0, s[5] = 0;
  EXPECT_EQ(modesForRelease(s, 4), 4);  // at least the minimum
  EXPECT_EQ(modesForRelease(s, 9), 6);  // within the hinges
}

// A verification companion keeps each link's modes up to twice the frequency of the
// run's highest (a mode at exactly twice it, and none a part in 10^6 above), and at
// least one more; within the hinges; the run's own with a factor of 1.
TEST(Fidelity, TheCompanionKeepsTheNextOctaveOfModes) {
  Eigen::VectorXd lambda(6);  // omega^2: omega = 1, 2, 3, 4, 8, 9
  lambda << 1, 4, 9, 16, 64, 81;
  EXPECT_EQ(companionModes(lambda, 2, 2.0), 4);  // omega 3 and 4 within 2 x 2
  lambda[3] = 16 * (1 + 1e-6);
  EXPECT_EQ(companionModes(lambda, 2, 2.0), 3);
  EXPECT_EQ(companionModes(lambda, 4, 1.5), 5);  // none within 1.5 x: one more
  EXPECT_EQ(companionModes(lambda, 6, 2.0), 6);  // within the hinges
  EXPECT_EQ(companionModes(lambda, 2, 1.0), 2);  // no companion
}

ArticleScene freeSwing(int upper_segments, int lower_segments, double duration) {
  ArticleScene s = loadArticleSceneFile(MMVLAB_SOURCE_DIR "/bench/mujoco/free-swing.yaml");
  s.simulation.fidelity = SimulationSpec::Fidelity::Auto;
  s.simulation.duration = duration;
  s.article.links[0].segments = upper_segments;
  s.article.links[1].segments = lower_segments;
  return s;
}

// A start at rest (a release) is carried in modal coordinates: at least 4 modes, and
// more where the modes left out would carry more than kReleaseStaticShare of a link's
// static response to its load at the start. The free swing's links, loaded by their
// weight (the masses' own: the low modes, mass-weighted, carry it), keep 4; with a dead
// load of 800 N at the upper link's second hinge (12.5 cm from its root) it needs more.
TEST(Fidelity, AReleaseKeepsTheModesItsStepNeeds) {
  ArticleScene rest = loadDefaultScene();
  rest.simulation.from_equilibrium = false;
  const FidelityChoice c = resolveFidelity(rest);
  EXPECT_TRUE(c.modal && c.by_rule);
  EXPECT_TRUE(has(c.reason, "and those the release needs")) << c.reason;
  EXPECT_EQ(rest.simulation.integrator, "cvode_bdf");
  for (const auto& l : rest.article.links) EXPECT_EQ(l.modes_cover_release, !l.rigid) << l.name;

  const SimulationResult tip = simulate(freeSwing(16, 8, 0.01));
  ASSERT_EQ(tip.modal_links.size(), 2u);
  for (const auto& l : tip.modal_links) {
    EXPECT_EQ(l.modes, kFidelityMinModes) << l.link;
    ASSERT_TRUE(l.release_share_left.has_value()) << l.link;
    EXPECT_GT(*l.release_share_left, 0.0) << l.link;  // measured, not assumed
    EXPECT_LE(*l.release_share_left, kReleaseStaticShare) << l.link;
  }
  ArticleScene near_root = freeSwing(16, 8, 0.01);
  LoadSpec dead;  // a dead load, not a weight: the modes are not weighted by it
  dead.point = "upper.h2";
  dead.force = {0, -800, 0};
  near_root.article.loads.push_back(dead);
  const SimulationResult root = simulate(near_root);
  EXPECT_GT(root.modal_links[0].modes, kFidelityMinModes);
  EXPECT_LE(*root.modal_links[0].release_share_left, kReleaseStaticShare);
  // A link's own `modes:` is kept as written (no rule, no share); the verification
  // companion's modes up to twice the frequency leave less.
  ArticleScene own = near_root;
  own.article.links[0].modes = root.modal_links[0].modes - 1;
  const SimulationResult own_run = simulate(own);
  EXPECT_EQ(own_run.modal_links[0].modes, root.modal_links[0].modes - 1);
  EXPECT_FALSE(own_run.modal_links[0].release_share_left.has_value());
  near_root.simulation.modal_refinement = 1;
  const SimulationResult twice = simulate(near_root);
  EXPECT_GT(twice.modal_links[0].modes, root.modal_links[0].modes);
  EXPECT_LT(*twice.modal_links[0].release_share_left, *root.modal_links[0].release_share_left);
}

/// The run's kept modes for a table sine at f Hz (the modes are the start's: 10 ms do).
std::vector<ModalLinkSummary> keptFor(double f) {
  ArticleScene s = loadDefaultScene();
  s.article.base.type = BaseType::Table;
  s.article.base.motion = TableMotion::sine(1e-5, f);
  s.simulation.duration = 0.01;
  return simulate(s).modal_links;
}

// Each link keeps its modes up to the cutoff, and at least 4: at the bound (a mode at
// the cutoff) it is kept, one past (the cutoff a part in 10^6 below it) it is not.
TEST(Fidelity, EachLinkKeepsItsModesUpToTheCutoffAndAtLeastFour) {
  const std::vector<ModalLinkSummary> low = keptFor(1.0);  // cutoff 10 Hz: below every link's 4th mode
  ASSERT_EQ(low.size(), 4u);
  for (const auto& l : low) {
    EXPECT_EQ(l.modes, kFidelityMinModes) << l.link;
    EXPECT_GT(l.highest_kept_hz, 10.0) << l.link;
  }
  const std::vector<ModalLinkSummary> high = keptFor(25.0);  // cutoff 250 Hz
  int above_min = 0;
  for (const auto& l : high) {
    EXPECT_GE(l.modes, kFidelityMinModes) << l.link;
    if (l.modes > kFidelityMinModes) {
      EXPECT_LE(l.highest_kept_hz, 250.0) << l.link;
      ++above_min;
    }
    EXPECT_GT(l.first_dropped_hz, 250.0) << l.link;
  }
  EXPECT_GT(above_min, 0);
  const double f5 = low[0].first_dropped_hz;  // link1's 5th mode
  EXPECT_EQ(keptFor(f5 / kFidelityBandFactor * (1 + 1e-12))[0].modes, 5);
  EXPECT_EQ(keptFor(f5 / kFidelityBandFactor * (1 - 1e-6))[0].modes, 4);
}

/// A scene's default run against the segment model at 1e-8 (CVODE BDF), and `--verify`
/// of it with the companion `spec` asks for.
struct DefaultRunCheck {
  SimulationResult run;
  double error = 0, target = 0;
  std::function<RunVerification(const SimulationSpec&)> verify;
};

DefaultRunCheck checkDefaultRun(const ArticleScene& s) {
  DefaultRunCheck c;
  c.run = simulate(s);
  ArticleScene reference = s;
  reference.simulation.fidelity = SimulationSpec::Fidelity::Segments;
  reference.simulation.integrator = "cvode_bdf";
  reference.simulation.accuracy = 1e-8;
  const SimulationResult ref = simulate(reference);
  EXPECT_TRUE(ref.modal_links.empty());
  c.error = scoredDistance(c.run.record, ref.record, {}).distance_m;
  c.target = defaultErrorTarget(scoredAmplitude(ref.record, {}), scoredScale(ref.record, {}));
  c.verify = [s, run = c.run](const SimulationSpec& spec) {
    const auto rerun = [&](const SimulationSpec& companion) {
      ArticleScene t = s;
      t.simulation = companion;
      return simulate(t);
    };
    return verifyRun(run, spec, rerun, 0);
  };
  return c;
}

/// `--verify`'s companion (each link's modes up to twice the frequency) sees the run's actual error within a factor
/// of two, and calls it met.
void expectVerifySeesTheError(const DefaultRunCheck& c, const SimulationSpec& spec) {
  const RunVerification v = c.verify(spec);
  EXPECT_TRUE(v.companion_more_modes);
  EXPECT_GT(v.estimated_error_m, 0.5 * c.error);
  EXPECT_LT(v.estimated_error_m, 2 * c.error);
  EXPECT_TRUE(verificationMet(v));
}

// The user's scene at 8 segments per link: the default run (4 modes per link under
// CVODE BDF at 1e-6) is within 1 % of the tips' motion of the segment model at 1e-8
// (6.5e-5 m of 0.124 m measured), and `--verify`'s estimate, against a companion with
// the modes up to twice the frequency, is that error to within a factor of two
// (measured 5.7e-5 m). A
// companion with the run's own modes sees the tolerance only and misses most of it.
TEST(Fidelity, TheDefaultRunMeetsItsStatedAccuracyAndVerifySeesTheModesLeftOut) {
  const ArticleScene s = userTableScene(8);
  const DefaultRunCheck c = checkDefaultRun(s);
  ASSERT_EQ(c.run.modal_links.size(), 4u);
  for (const auto& l : c.run.modal_links) EXPECT_EQ(l.modes, 4) << l.link;
  EXPECT_GT(c.error, 1e-6);  // the modes left out are seen at all
  EXPECT_LT(c.error, c.target);
  expectVerifySeesTheError(c, s.simulation);
  SimulationSpec same_modes = s.simulation;
  same_modes.modal_refinement = -1;  // the companion then keeps the run's modes (-1 + 1 = 0)
  EXPECT_LT(c.verify(same_modes).estimated_error_m, 0.2 * c.error);
}

// A release's default run (the free swing at 8 + 4 segments, 0.5 s, 4 modes per link
// under CVODE BDF at the scene's tolerance) is within 1 % of the tips' motion of the
// segment model at 1e-8 (2.0e-6 m against 4.4e-3 m measured), and `--verify`'s
// companion with the modes up to twice the frequency sees that error (1.5e-6 m).
TEST(Fidelity, TheDefaultRunOfAReleaseMeetsItsStatedAccuracy) {
  const ArticleScene s = freeSwing(8, 4, 0.5);
  const DefaultRunCheck c = checkDefaultRun(s);
  ASSERT_EQ(c.run.modal_links.size(), 2u);
  EXPECT_TRUE(has(c.run.fidelity, "and those the release needs")) << c.run.fidelity;
  EXPECT_GT(c.error, 1e-7);  // the modes left out and the tolerance are seen at all
  EXPECT_LT(c.error, c.target);
  expectVerifySeesTheError(c, s.simulation);
}

}  // namespace
}  // namespace mmv
