#pragma once
/// `trade`: the speed-accuracy trade of a time run, either kind of scene
/// (sim/time/trade.hpp): integrators x tolerances, the segments ladder and the modes
/// ladder, each run's error against the reference and its cost.

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "sim/app/options.hpp"
#include "sim/app/study.hpp"
#include "sim/core/integrators.hpp"
#include "sim/time/trade.hpp"

namespace mmv::app {

/// `trade`'s options, declared once (sim/app/options.hpp). Empty lists and absent numbers
/// keep TradeOptions' defaults (the scene's duration, 1 % of the scored motion as the
/// target, no budgets); a number given must be above 0.
struct TradeParams {
  std::vector<std::string> integrators;  ///< names of the integrator table
  std::vector<double> accuracies;        ///< each in (0, 1)
  std::vector<int> segments;             ///< the segments ladder, each 1 .. limits::kMaxSegments
  std::vector<int> modes;                ///< the modes ladder, each 0 .. limits::kMaxSegments (0 alone: none)
  std::vector<double> modes_accuracies;  ///< each in (0, 1)
  std::vector<std::string> points;       ///< tips or stations scored; empty: every tip
  std::optional<double> duration;        ///< s
  std::optional<double> target_error;    ///< m
  bool all = false;                      ///< run every run (no skipping or cutting of costlier ones)
  std::optional<double> run_budget;      ///< s: a run over it is cut
  std::optional<double> time_budget;     ///< s: no run starts past it

  template <class S, class V>
  static void fields(S& s, V&& v) {
    v(s.integrators, Option("integrators", "Integrators compared").commaSeparated().whenAbsent(
                         "rk_merson, rk3, cpodes, cvode_bdf, cvode_adams, arkode_erk, arkode_dirk"));
    v(s.accuracies, Option("accuracies", "Relative accuracies each integrator runs at").above(0).below(1).commaSeparated()
                        .whenAbsent("1e-3, 1e-4, 1e-5, 1e-6, 1e-7"));
    v(s.segments, Option("segment_ladder", "Segments per link of the mesh runs").range(1, limits::kMaxSegments)
                      .commaSeparated().whenAbsent("2, 4, 8"));
    v(s.modes, Option("modes_ladder", "Modes per link of the runs with the links in modal coordinates (0 alone: none)")
                   .range(0, limits::kMaxSegments).commaSeparated().whenAbsent("1, 2, 3, 4"));
    v(s.modes_accuracies, Option("modes_accuracies", "Accuracies of the modal runs (CVODE BDF)").above(0).below(1)
                              .commaSeparated().whenAbsent("1e-5, 1e-6, 1e-7"));
    v(s.points, Option("points", "Link tips or stations the error is scored at, e.g. link3a.tip, link1@0.5")
                    .commaSeparated().whenAbsent("every tip"));
    v(s.duration, Option("duration", "Seconds simulated").unit("s").above(0).whenAbsent("the scene's"));
    v(s.target_error, Option("target_error", "Error to meet (the cheapest run within it is named)").unit("m").above(0)
                          .whenAbsent("1 % of the scored points' largest motion in the reference run"));
    v(s.all, Option("all", "Run every run; by default a tolerance is skipped when a looser one of its integrator already "
                           "cost more than the cheapest run within the target"));
    v(s.run_budget, Option("run_budget", "Wall seconds a run may take; a run over it is cut and listed (the reference runs "
                                         "excepted)").unit("s").above(0).whenAbsent("no limit"));
    v(s.time_budget, Option("time_budget", "Wall seconds for the whole trade: past it the run under way is cut and the rest "
                                           "are listed as not run").unit("s").above(0).whenAbsent("no limit"));
  }
};

struct TradeRequest : TradeParams {
  Front front = Front::Cli;
};

struct TradeStudyResult {
  TradeStudy study;
  double target_m = 0;  ///< the target the runs were judged against
  nlohmann::ordered_json json;
  std::string text, csv;
};

/// `progress(done, total, detail)`, when given, as each run starts ("rk3 at 1e-05, 4 segments").
using TradeProgress = std::function<void(double done, double total, const std::string& detail)>;

/// Checks every option (UsageError naming it) before any model is built, then runs the trade.
TradeStudyResult runTradeStudy(const Scene& scene, const TradeRequest& request, const TradeProgress& progress = {});

}  // namespace mmv::app
