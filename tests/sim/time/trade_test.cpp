#include "sim/time/trade.hpp"
#include "sim/io/trade_report.hpp"
#include "support/stub_trade.hpp"
#include "sim/time/verify.hpp"
#include "sim/core/text.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <memory>
#include <cmath>
#include <thread>

namespace mmv {
namespace {

// The default article at 2 segments per link, joint 2 slewing 0 -> 45 deg, 50 Hz samples.
ArticleScene shortSlew(double duration) {
  ArticleScene s = loadDefaultScene();
  overrideSegments(s, 2);
  SlewSpec sl;
  sl.to = 45 * M_PI / 180;
  s.article.joints[1].slew = sl;
  s.simulation.duration = duration;
  s.simulation.sample_rate_hz = 50;
  return s;
}

// A short flexible slew: for each integrator the error against the reference falls as
// the accuracy tightens by 1e3, the reference is far more certain than the errors, and
// the Pareto front is the set of runs no other run dominates.
TEST(Trade, ErrorsFallWithAccuracyAndTheFrontIsNonDominated) {
  const ArticleScene s = shortSlew(0.8);
  TradeOptions o;
  o.integrators = {"rk_merson", "cpodes", "cvode_bdf"};
  o.accuracies = {1e-3, 1e-6};
  o.segments = {1};
  o.modes = {};             // (ModesLadder below)
  o.skip_costlier = false;  // every run: the whole trade-off is measured here
  const TradeStudy t = runTrade(articleTradeProblem(s), o);
  ASSERT_EQ(t.runs.size(), 7u);
  EXPECT_LT(t.reference_uncertainty_m, 1e-6);
  for (std::size_t i = 0; i < 6; i += 2) {
    ASSERT_TRUE(t.runs[i].ok && t.runs[i + 1].ok) << t.runs[i].failure << t.runs[i + 1].failure;
    EXPECT_LT(t.runs[i + 1].error_m, t.runs[i].error_m) << t.runs[i].integrator;
    EXPECT_GT(t.runs[i].error_m, t.reference_uncertainty_m);
  }
  // The front is exactly the set of runs that no other run dominates.
  for (const auto& a : t.runs) {
    if (!a.ok || a.segments) continue;
    bool dominated = false;
    for (const auto& b : t.runs)
      if (b.ok && !b.segments && &a != &b && b.seconds <= a.seconds && b.error_m <= a.error_m &&
          (b.seconds < a.seconds || b.error_m < a.error_m))
        dominated = true;
    EXPECT_EQ(a.pareto, !dominated) << a.integrator << " " << a.accuracy;
  }
  EXPECT_EQ(t.runs.back().segments, 1);  // the segment ladder: 1 segment against the scene's 2
  EXPECT_GT(t.runs.back().error_m, t.runs[1].error_m);
}

// The default target follows the motion: 1 % of the reference's largest scored
// distance from the start. Link 1's tip, on a held joint, only bends under the slew's
// reaction (1.6 cm measured); the tips beyond the slewing joint 2 swing (0.37 m).
TEST(Trade, TheDefaultTargetIsOnePercentOfTheScoredMotion) {
  const ArticleScene s = shortSlew(0.4);
  TradeOptions o;
  o.integrators = {"rk_merson"};
  o.accuracies = {1e-4};
  o.segments = {};
  o.modes = {};
  const TradeStudy all = runTrade(articleTradeProblem(s), o);
  EXPECT_GT(all.reference_amplitude_m, 0.01);  // metres of slew, not micrometres
  EXPECT_DOUBLE_EQ(defaultTradeTarget(all), 0.01 * all.reference_amplitude_m);
  TradeStudy still = all;
  still.reference_amplitude_m = 0;  // nothing moved: 1 % of a micrometre per metre of the points' distance
  EXPECT_GT(all.reference_scale_m, 1.0);
  EXPECT_DOUBLE_EQ(defaultTradeTarget(still), 0.01 * kMotionFloor * all.reference_scale_m);
  still.reference_scale_m = 0;
  EXPECT_DOUBLE_EQ(defaultTradeTarget(still), 1e-4);
  o.points = {"link1.tip"};
  const TradeStudy link1 = runTrade(articleTradeProblem(s), o);
  EXPECT_GT(link1.reference_amplitude_m, 0.0);
  EXPECT_LT(link1.reference_amplitude_m, 0.1 * all.reference_amplitude_m);
}

// Scored at link 1's tip only, each run's error is at most its error over every tip
// (a maximum over fewer points) and strictly less for at least one run (link 1 is the
// stiffest, shortest lever; measured several times smaller). A name that is not a tip
// is refused before anything runs.
TEST(Trade, ErrorAtChosenPoints) {
  const ArticleScene s = shortSlew(0.5);
  TradeOptions o;
  o.integrators = {"cpodes"};
  o.accuracies = {1e-3, 1e-5};
  o.segments = {};
  o.modes = {};  // runs compared index by index: none skipped by wall time
  const TradeStudy all = runTrade(articleTradeProblem(s), o);
  o.points = {"link1.tip"};
  const TradeStudy one = runTrade(articleTradeProblem(s), o);
  ASSERT_EQ(all.runs.size(), one.runs.size());
  bool smaller = false;
  for (std::size_t i = 0; i < all.runs.size(); ++i) {
    EXPECT_LE(one.runs[i].error_m, all.runs[i].error_m);
    smaller = smaller || one.runs[i].error_m < 0.9 * all.runs[i].error_m;
  }
  EXPECT_TRUE(smaller);
  o.points = {"link1.tip", "link9.tip"};
  try {
    runTrade(articleTradeProblem(s), o);
    ADD_FAILURE() << "no error";
  } catch (const UsageError& e) {  // options.points come from the command line
    EXPECT_NE(std::string(e.what()).find("--points: 'link9.tip' is not a link tip of the scene (known: link1.tip,"),
              std::string::npos)
        << e.what();
  }
  // The scene may name the scored outputs itself (simulation.score_points).
  ArticleScene named = s;
  named.simulation.score_points = {"link1.tip"};
  named.simulation.score_where = "s.yaml:30:17";
  o.points.clear();
  const TradeStudy from_scene = runTrade(articleTradeProblem(named), o);
  ASSERT_EQ(from_scene.points, std::vector<std::string>{"link1.tip"});
  for (std::size_t i = 0; i < one.runs.size(); ++i) EXPECT_NEAR(from_scene.runs[i].error_m, one.runs[i].error_m, 1e-15);
  named.simulation.score_points = {"link7.tip"};
  try {
    runTrade(articleTradeProblem(named), o);
    ADD_FAILURE() << "no error";
  } catch (const SceneError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("s.yaml:30:17: simulation.score_points: 'link7.tip' is not a link tip", 0), 0u)
        << e.what();
  }
}

// A trade scores stations too (the physical article, not the mesh): the station at
// link 1's far end is its tip, so its errors are the tip's; a station off the link is
// refused before anything runs, with the station's own message.
TEST(Trade, ScoresStations) {
  const ArticleScene s = shortSlew(0.3);
  TradeOptions o;
  o.integrators = {"cpodes"};
  o.accuracies = {1e-3, 1e-5};
  o.segments = {};
  o.modes = {};  // runs compared index by index: none skipped by wall time
  o.points = {"link1.tip"};
  const TradeStudy tip = runTrade(articleTradeProblem(s), o);
  o.points = {"link1@1"};
  const TradeStudy station = runTrade(articleTradeProblem(s), o);
  ASSERT_EQ(tip.runs.size(), station.runs.size());
  for (std::size_t i = 0; i < tip.runs.size(); ++i) {
    EXPECT_GT(station.runs[i].error_m, 0.0);
    EXPECT_NEAR(station.runs[i].error_m, tip.runs[i].error_m, 1e-12 + 1e-9 * tip.runs[i].error_m);
  }
  o.points = {"link1@3m"};
  try {
    runTrade(articleTradeProblem(s), o);
    ADD_FAILURE() << "no error";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("--points: 'link1@3m': "), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("outside link1"), std::string::npos) << e.what();
  }
}


// The trade's budget policy on a stub problem with known costs and errors, so what it
// skips or cuts does not depend on this machine's speed: "cheap" costs 0.1 s at every
// tolerance, "dear" 5 s (an explicit method at its stability limit); a run's error is
// its accuracy in metres; the point moves 1 m, so the default target is 1 cm.
TradeProblem stubProblem(double sleep_per_sample_s = 0) {
  return testing::stubTradeProblem(
      [](const SimulationSpec& s, double t) { return t + (s.accuracy < 1e-9 ? 0.0 : s.accuracy); },  // the references are exact
      [](const SimulationSpec& s, SimulationResult& r) {
        r.wall_seconds = s.integrator == "rk_merson" ? 5.0 : 0.1;  // "dear" and "cheap"
        r.realizations = 100;
      },
      sleep_per_sample_s);
}

TEST(Trade, SkipsTheRunsThatCannotBeTheCheapestWithinTheTarget) {
  TradeOptions o;
  o.integrators = {"cpodes", "rk_merson"};  // cheap first, then dear
  o.accuracies = {1e-6, 1e-3, 1e-4};        // run loosest first whatever the order given
  const TradeStudy t = runTrade(stubProblem(), o);
  EXPECT_NEAR(t.target_m, 0.01, 1e-12);
  ASSERT_EQ(t.runs.size(), 6u);
  EXPECT_EQ(t.runs[0].accuracy, 1e-3);
  for (int k = 0; k < 3; ++k) EXPECT_EQ(t.runs[k].status, "ok") << k;  // cheap: never dearer than the best
  EXPECT_EQ(t.runs[3].status, "ok");     // dear at 1e-3: nothing of its own says it cannot win
  EXPECT_EQ(t.runs[4].status, "costlier");  // dear at 1e-4 and 1e-6: 5 s already, against 0.1 s within 1 cm
  EXPECT_EQ(t.runs[5].status, "costlier");
  EXPECT_FALSE(t.runs[4].ok);
  o.skip_costlier = false;  // --all
  for (const auto& r : runTrade(stubProblem(), o).runs) EXPECT_EQ(r.status, "ok");
}

// The implicit methods' ladders run first: a cheap implicit method sets the bar before
// a dear explicit one listed first starts, and the explicit one's tighter runs are
// skipped. Before, the ladders ran in the order given (on the slew scene 51 of 58 s went
// to RK-Merson and RK3 before CPodes set a 0.37 s bar). The runs are still listed in
// the options' order.
TEST(Trade, TheImplicitMethodsSetTheBarWhateverTheOrderGiven) {
  TradeProblem p = stubProblem();  // rk_merson dear (5 s), the others cheap (0.1 s)
  const auto inner = p.run;
  auto order = std::make_shared<std::vector<std::string>>();
  p.run = [inner, order](const SimulationSpec& s, const RunFidelity& n, const std::function<void(double)>& progress) {
    if (s.accuracy > 1e-9) order->push_back(s.integrator + strf(" %g", s.accuracy));
    return inner(s, n, progress);
  };
  TradeOptions o;
  o.integrators = {"rk_merson", "cpodes"};  // dear and explicit first
  o.accuracies = {1e-3, 1e-4, 1e-6};
  const TradeStudy t = runTrade(p, o);
  EXPECT_EQ(*order, (std::vector<std::string>{"cpodes 0.001", "cpodes 0.0001", "cpodes 1e-06", "rk_merson 0.001"}));
  ASSERT_EQ(t.runs.size(), 6u);
  EXPECT_EQ(t.runs[0].integrator, "rk_merson");
  EXPECT_EQ(t.runs[0].status, "ok");  // nothing of its own said it could not win
  for (int k = 1; k < 3; ++k) {
    EXPECT_EQ(t.runs[k].integrator, "rk_merson");
    EXPECT_EQ(t.runs[k].status, "costlier") << k;
  }
  for (int k = 3; k < 6; ++k) {
    EXPECT_EQ(t.runs[k].integrator, "cpodes");
    EXPECT_EQ(t.runs[k].status, "ok") << k;
  }
  EXPECT_EQ(t.runs[4].accuracy, 1e-4);
}

// `cut_costlier` (the choice of `simulate --target-error`): the dear integrator's
// loosest run is cut once it has cost more than the cheapest run within the target,
// and its tighter tolerances are then skipped without starting (a cut run used to
// leave them to start and be cut in turn: 30 s of a 32 s pilot on the table scene).
TEST(Trade, ARunCutAsCostlierSkipsItsTighterTolerances) {
  TradeProblem p = stubProblem();
  const auto inner = p.run;
  p.run = [inner](const SimulationSpec& s, const RunFidelity& n, const std::function<void(double)>& progress) {
    if (s.integrator == "rk_merson" && s.accuracy > 1e-9)  // dear: 11 samples of 50 ms against the cheap run's 0.1 s
      return inner(s, n, [&](double f) {
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
        progress(f);
      });
    return inner(s, n, progress);
  };
  TradeOptions o;
  o.integrators = {"cpodes", "rk_merson"};
  o.accuracies = {1e-3, 1e-4, 1e-6};
  o.cut_costlier = true;
  const TradeStudy t = runTrade(p, o);
  ASSERT_EQ(t.runs.size(), 6u);
  EXPECT_EQ(t.runs[3].status, "costlier");
  EXPECT_NE(t.runs[3].failure.find("cut after"), std::string::npos) << t.runs[3].failure;
  EXPECT_GT(t.runs[3].seconds, 0.1);  // what it cost before the cut
  for (int k = 4; k < 6; ++k) {
    EXPECT_EQ(t.runs[k].status, "costlier");
    EXPECT_NE(t.runs[k].failure.find("skipped"), std::string::npos) << t.runs[k].failure;
  }
}

// A run within the target whose energy balance fails (the stub's cheap run at 1e-3
// drifts half its peak kinetic energy) is not the cheapest run named: the report names
// the next one and says why the cheaper one was passed over.
TEST(Trade, ARunWhoseEnergyBalanceFailsIsNotNamedTheCheapest) {
  TradeProblem p = stubProblem();
  const auto inner = p.run;
  p.run = [inner](const SimulationSpec& s, const RunFidelity& n, const std::function<void(double)>& progress) {
    SimulationResult r = inner(s, n, progress);
    if (s.integrator == "cpodes" && s.accuracy == 1e-3)  // cheaper than the 1e-4 run, and unbalanced
      r.wall_seconds = 0.05, r.peak_kinetic_energy_j = 1, r.max_energy_balance_error_j = 0.5;
    return r;
  };
  TradeOptions o;
  o.integrators = {"cpodes"};
  o.accuracies = {1e-3, 1e-4};
  const TradeStudy t = runTrade(p, o);
  ASSERT_EQ(t.runs.size(), 2u);
  EXPECT_FALSE(t.runs[0].energy_ok);
  EXPECT_TRUE(t.runs[1].energy_ok);
  const std::string text = tradeText(t, t.target_m);
  EXPECT_NE(text.find("Cheapest run within 0.01 m: cpodes at accuracy 1e-04"), std::string::npos) << text;
  EXPECT_NE(text.find("cpodes at accuracy 1e-03 is cheaper within 0.01 m"), std::string::npos) << text;
  EXPECT_NE(text.find("energy balance fails"), std::string::npos) << text;
  EXPECT_EQ(tradeJson(t, t.target_m)["cheapest_within_target"]["accuracy"].get<double>(), 1e-4);
}

TEST(Trade, BudgetsCutARunAndStopTheTrade) {
  TradeOptions o;
  o.integrators = {"cpodes", "cvode_bdf"};
  o.accuracies = {1e-3, 1e-4};
  o.run_budget_s = 0.05;  // each stub run sleeps 11 x 20 ms = 0.22 s: cut at its 3rd or 4th sample
  const TradeStudy cut = runTrade(stubProblem(0.02), o);
  ASSERT_EQ(cut.runs.size(), 4u);
  EXPECT_EQ(cut.runs[0].status, "over_budget");
  EXPECT_NE(cut.runs[0].failure.find("over its 0.05 s budget"), std::string::npos) << cut.runs[0].failure;
  EXPECT_EQ(cut.runs[1].status, "not_run");  // a tighter run of a cut integrator is not started
  EXPECT_EQ(cut.runs[2].status, "over_budget");
  o.run_budget_s = 0;
  o.total_budget_s = 0.3;  // the two references (0.44 s) already spend it: nothing else starts
  const TradeStudy stopped = runTrade(stubProblem(0.02), o);
  for (const auto& r : stopped.runs) EXPECT_EQ(r.status, "not_run") << r.integrator << " " << r.accuracy;
  EXPECT_GT(stopped.total_seconds, 0.3);
}


// The modes ladder: the slew scene's links in 1, 2 and 3 modes each (CVODE BDF at 1e-7)
// beside the segment model; the error falls as modes are added, the runs say their
// modes, and a rung of 8 or more (every hinge of the scene's 8 segments) is not run.
TEST(Trade, TheModesLadderRunsTheLinksInModalCoordinates) {
  ArticleScene s = loadArticleSceneFile(MMVLAB_SOURCE_DIR "/scenes/mmv-slew.yaml");
  TradeOptions o;
  o.integrators = {"cvode_bdf"};
  o.accuracies = {1e-7};
  o.segments = {};
  o.modes = {1, 2, 3, 8, 9};
  o.modes_accuracies = {1e-7};
  o.duration = 1.5;
  o.points = {"link3a.tip"};
  o.skip_costlier = false;
  const TradeStudy t = runTrade(articleTradeProblem(s, 1.5), o);
  ASSERT_EQ(t.runs.size(), 4u);
  EXPECT_EQ(t.runs[0].modes, 0);
  for (int k = 1; k <= 3; ++k) {
    const TradeRun& r = t.runs[k];
    ASSERT_TRUE(r.ok) << r.failure;
    EXPECT_EQ(r.modes, k);
    EXPECT_EQ(r.integrator, "cvode_bdf");
    if (k > 1) EXPECT_LT(r.error_m, 0.5 * t.runs[k - 1].error_m) << k;
  }
  EXPECT_LT(t.runs[3].error_m, 1e-4);
  EXPECT_GT(t.runs[1].error_m, t.runs[0].error_m);  // one mode per link is far from the segment model
}

// A real run cut mid-way by the budget (Simbody's RK-Merson and CVODE in the SUNDIALS
// plugin): the run is abandoned between samples and listed, and the next run is
// unaffected (the sanitized suite checks that nothing leaks).
TEST(Trade, ARealRunIsCutCleanly) {
  const ArticleScene s = shortSlew(0.8);
  TradeOptions o;
  o.integrators = {"rk_merson", "cvode_bdf"};
  o.accuracies = {1e-4};
  o.segments = {};
  o.modes = {};
  o.run_budget_s = 1e-9;  // over at its first sample after the start
  const TradeStudy t = runTrade(articleTradeProblem(s), o);
  ASSERT_EQ(t.runs.size(), 2u);
  for (const auto& r : t.runs) {
    EXPECT_EQ(r.status, "over_budget") << r.integrator << ": " << r.failure;
    EXPECT_FALSE(r.ok);
  }
  o.run_budget_s = 0;
  const TradeStudy again = runTrade(articleTradeProblem(s), o);
  for (const auto& r : again.runs) EXPECT_TRUE(r.ok) << r.integrator << ": " << r.failure;
}

}  // namespace
}  // namespace mmv
