#pragma once
/// `trade`: the speed-accuracy trade of a time run, either kind of scene
/// (sim/time/trade.hpp): integrators x tolerances, the segments ladder and the modes
/// ladder, each run's error against the reference and its cost.

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "sim/app/study.hpp"
#include "sim/time/trade.hpp"

namespace mmv::app {

/// Empty lists and absent numbers keep TradeOptions' defaults (the scene's duration, 1 %
/// of the scored motion as the target, no budgets); a number given must be above 0.
struct TradeRequest {
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
