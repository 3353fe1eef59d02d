#include "sim/time/trade.hpp"

#include <gtest/gtest.h>

#include <cmath>

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
  const TradeStudy all = runTrade(articleTradeProblem(s), o);
  EXPECT_GT(all.reference_amplitude_m, 0.01);  // metres of slew, not micrometres
  EXPECT_DOUBLE_EQ(defaultTradeTarget(all), 0.01 * all.reference_amplitude_m);
  TradeStudy still = all;
  still.reference_amplitude_m = 0;
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

}  // namespace
}  // namespace mmv
