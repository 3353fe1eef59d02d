#include "sim/time/verify.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "support/scenes.hpp"

namespace mmv {
namespace {

ArticleScene pendulumFrom170Degrees(const std::string& integrator) {
  ArticleScene s = testing::chainScene(1, 1.0, 1e-9, 9.81, 0.0, 2.0);
  s.article.joints[0].angle = 170 * M_PI / 180;
  s.simulation.from_equilibrium = false;
  s.simulation.duration = 6.0;
  s.simulation.sample_rate_hz = 100;
  s.simulation.integrator = integrator;
  return s;
}

SimulationResult verified(ArticleScene s, double accuracy, double target_m = 0.0) {
  s.simulation.accuracy = accuracy;
  SimulationResult r = simulate(s);
  r.verification = verifyRun(r, s.simulation, [&](const SimulationSpec& spec) {
    ArticleScene t = s;
    t.simulation = spec;
    return simulate(t);
  }, target_m);
  return r;
}

// The pendulum from 170 deg (a 2 m swing of its tip): CVODE BDF at 1e-3 is far off
// and the companion run says so; at 1e-7 it is within its target. The estimate is
// checked against the true error (a run at 1e-11): for these orders it is within a
// factor of two of it.
TEST(Verify, FlagsALooseRunAndEstimatesTheTrueError) {
  ArticleScene s = pendulumFrom170Degrees("cvode_bdf");
  const SimulationResult loose = verified(s, 1e-3);
  EXPECT_TRUE(loose.verification.done);
  EXPECT_EQ(loose.verification.point, "l1.tip");
  EXPECT_GT(loose.verification.estimated_error_m, loose.verification.target_m);
  EXPECT_FALSE(verificationWarning(loose.verification).empty());
  EXPECT_NEAR(loose.verification.amplitude_m, 2.0, 1e-3);  // the tip passes the opposite side of its circle
  const SimulationResult tight = verified(s, 1e-7);
  EXPECT_LT(tight.verification.estimated_error_m, tight.verification.target_m);
  EXPECT_TRUE(verificationWarning(tight.verification).empty());

  s.simulation.accuracy = 1e-11;
  const SimulationResult truth = simulate(s);
  for (double accuracy : {1e-5, 1e-6}) {
    const SimulationResult r = verified(s, accuracy);
    const double actual = scoredDistance(r.record, truth.record, {}).distance_m;
    EXPECT_GT(r.verification.estimated_error_m, 0.5 * actual) << accuracy;
    EXPECT_LT(r.verification.estimated_error_m, 2.0 * actual) << accuracy;
  }
}

// "met" has a margin (kVerifySafetyFactor). The case: the pendulum from 170 deg
// under CVODE Adams at 1e-7 against a 1e-4 m target has a true error above the target
// (1.15e-4 m) while the bare estimate was below it, and was called "met". Over the
// integrators and tolerances here the true error stays within the safety factor times
// the estimate, and no run is called met whose true error exceeds its target.
TEST(Verify, MetHoldsTheTrueErrorWithinTheTarget) {
  const double target = 1e-4;
  for (const char* integrator : {"cvode_adams", "cvode_bdf", "rk_merson"}) {
    ArticleScene s = pendulumFrom170Degrees(integrator);
    s.simulation.accuracy = 1e-11;
    const SimulationResult truth = simulate(s);
    for (double accuracy : {1e-6, 1e-7, 1e-8}) {
      SCOPED_TRACE(std::string(integrator) + " at " + std::to_string(accuracy));
      const SimulationResult r = verified(s, accuracy, target);
      const double actual = scoredDistance(r.record, truth.record, {}).distance_m;
      EXPECT_LE(actual, kVerifySafetyFactor * r.verification.estimated_error_m);
      if (verificationMet(r.verification)) EXPECT_LE(actual, target) << "estimate " << r.verification.estimated_error_m;
      if (std::string(integrator) == "cvode_adams" && accuracy == 1e-7) {
        EXPECT_GT(actual, target);  // the case: truly over the target ...
        EXPECT_FALSE(verificationMet(r.verification));  // ... and no longer called met
        EXPECT_FALSE(verificationWarning(r.verification).empty());
      }
    }
  }
}

TEST(Verify, AGivenTargetIsUsed) {
  const ArticleScene s = pendulumFrom170Degrees("rk_merson");
  SimulationResult r = simulate(s);
  r.verification = verifyRun(r, s.simulation, [&](const SimulationSpec& spec) {
    ArticleScene t = s;
    t.simulation = spec;
    return simulate(t);
  }, 1e-12);
  EXPECT_FALSE(r.verification.target_is_default);
  EXPECT_EQ(r.verification.target_m, 1e-12);
  EXPECT_FALSE(verificationWarning(r.verification).empty());
}

}  // namespace
}  // namespace mmv

namespace mmv {
namespace {

// The closed article held at rest for 10 s: its tips drift a few nanometres under CPodes
// at 1e-6, integration noise. The default target counts motion from a micrometre per
// metre of the tips' extent, so the run meets it, and the energy balance (8e-8 J of 157 J) is within the
// run's accuracy: no warning. 1 % of the 2 nm drift (the old target) would fail it.
TEST(Verify, ARunAtRestMeetsItsDefaultTargetWithoutAWarning) {
  const ArticleScene s = loadArticleSceneFile(MMVLAB_SOURCE_DIR "/scenes/mmv-closed.yaml");
  const SimulationResult r = verified(s, s.simulation.accuracy);
  EXPECT_LT(r.verification.amplitude_m, 1e-7);
  EXPECT_GT(r.verification.estimated_error_m, 0.01 * r.verification.amplitude_m);  // the old target: missed
  EXPECT_LE(r.verification.estimated_error_m, r.verification.target_m);
  EXPECT_TRUE(verificationWarning(r.verification).empty());
  EXPECT_TRUE(energyBalanceWarning(r).empty()) << energyBalanceWarning(r);
  // The target does not depend on where the scene puts its origin: the same article
  // 40 m up is held to the same target (the points' extent, not their distance from 0).
  ArticleScene moved = s;
  moved.article.base.position[1] += 40;
  EXPECT_NEAR(verified(moved, moved.simulation.accuracy).verification.target_m, r.verification.target_m,
              1e-6 * r.verification.target_m);
  EXPECT_GT(std::abs(r.max_energy_balance_error_j), 0.0);
}

// A companion records the time and the scored points only (SimulationSpec::scored_only):
// the same steps, so the same positions, bit for bit, as the run recorded in full, for
// Simbody's integrators, SUNDIALS' through the plugin, and links in modal coordinates
// (the default fidelity of the template on the table, a station scored beside the tips).
TEST(Verify, ACompanionRecordsTheScoredPointsAsTheFullRunDoes) {
  ArticleScene table = testing::templateOnTheTable(8, 0.4);
  table.simulation.score_points = {"link2@0.5"};
  const std::vector<std::pair<ArticleScene, std::string>> runs = {
      {pendulumFrom170Degrees("cpodes"), "cpodes"},         {pendulumFrom170Degrees("rk_merson"), "rk_merson"},
      {pendulumFrom170Degrees("cvode_bdf"), "cvode_bdf"},   {pendulumFrom170Degrees("arkode_erk"), "arkode_erk"},
      {table, "the template on the table, modal links"}};
  for (const auto& [scene, what] : runs) {
    ArticleScene s = scene;
    s.simulation.duration = std::min(s.simulation.duration, 2.0);
    const SimulationResult full = simulate(s);
    s.simulation.scored_only = true;
    const SimulationResult scored = simulate(s);
    ASSERT_EQ(scored.record.rows.size(), full.record.rows.size()) << what;
    ASSERT_EQ(scored.record.scored.size(), full.record.scored.size()) << what;
    EXPECT_LT(scored.record.columns.size(), full.record.columns.size()) << what;
    EXPECT_TRUE(scored.states.rows.empty()) << what;
    EXPECT_EQ(scored.steps, full.steps) << what;
    if (what.rfind("the template", 0) == 0) EXPECT_FALSE(full.modal_links.empty());
    for (std::size_t i = 0; i < full.record.scored.size(); ++i) {
      const auto& [name, cf] = full.record.scored[i];
      const auto& [name_s, cs] = scored.record.scored[i];
      ASSERT_EQ(name_s, name) << what;
      for (std::size_t k = 0; k < full.record.rows.size(); ++k)
        for (std::size_t c = 0; c < cf.size(); ++c)
          ASSERT_EQ(scored.record.rows[k][cs[c]], full.record.rows[k][cf[c]]) << what << " " << name << " row " << k;
    }
    EXPECT_EQ(scoredDistance(full.record, scored.record, {}).distance_m, 0.0) << what;
  }
}

}  // namespace
}  // namespace mmv
