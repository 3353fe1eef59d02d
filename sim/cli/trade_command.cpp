// mmvlab trade: the speed-accuracy trade of a time run (sim/time/trade.hpp).
#include <algorithm>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <type_traits>

#include "sim/cli/figures.hpp"
#include "sim/cli/commands.hpp"
#include "sim/cli/progress.hpp"
#include "sim/core/text.hpp"
#include "sim/io/output_dir.hpp"
#include "sim/core/integrators.hpp"
#include "sim/hamsas/hamsas_simulation.hpp"
#include "sim/io/trade_report.hpp"

namespace mmv::cli {
namespace {

/// Runs done of the trade's total (two references, the integrator grid, the segment
/// ladder), reported to `progress` as each run starts and ends.
void reportProgress(TradeProblem& problem, const TradeOptions& o, Progress& progress) {
  int rungs = 0;  // the modes ladder's
  for (int k : o.modes) rungs += problem.has_modes && k > 0 && k < problem.finest_segments;
  const double total = 2.0 + double(o.integrators.size() * o.accuracies.size()) +
                       (problem.has_segments ? double(o.segments.size()) : 0.0) + double(rungs * o.modes_accuracies.size());
  auto done = std::make_shared<int>(0);
  problem.run = [inner = problem.run, &progress, total, done](const SimulationSpec& spec, const RunFidelity& f,
                                                               const std::function<void(double)>& cut) {
    progress.report(*done, total,
                    strf("%s at %g", spec.integrator.c_str(), spec.accuracy) +
                        (f.segments > 0 ? strf(", %d segments", f.segments) : std::string()) +
                        (f.modes > 0 ? strf(", %d modes per link", f.modes) : std::string()));
    struct Count {  // a failed run (a trade records it) counts as done too
      int& n;
      ~Count() { ++n; }
    } count{*done};
    return inner(spec, f, cut);
  };
}

/// Error against cost, one series per integrator (and per modes-per-link rung), with
/// the Pareto front.
void writeTradePlot(const std::string& path, const TradeStudy& s) {
  std::map<std::string, render::Series> by;
  render::Series front{"Pareto front", {}, {}};
  front.dashed = true;
  front.colour_index = 0;  // black: never an integrator's colour
  // Each integrator's colour is its place in the integrator table (from 1), in every trade
  // plot; a modal rung's follows the table's (the palette's 13 colours after black repeat).
  auto colourOf = [](const TradeRun& r) {
    const auto& t = integratorTable();
    if (r.modes > 0) return 1 + (static_cast<int>(t.size()) + r.modes - 1) % 13;
    for (std::size_t k = 0; k < t.size(); ++k)
      if (r.integrator == t[k].name) return static_cast<int>(k) + 1;
    return -1;
  };
  std::vector<const TradeRun*> pareto;
  for (const auto& r : s.runs) {
    if (!r.ok || r.segments) continue;
    const std::string label = r.integrator + (r.modes ? strf(", %d modes per link", r.modes) : std::string());
    auto& series = by[label];
    series.label = label;
    series.markers_only = true;
    series.colour_index = colourOf(r);
    series.x.push_back(r.seconds);
    series.y.push_back(std::max(r.error_m, 1e-15));
    series.point_labels.push_back(strf("%.0e", r.accuracy));  // each point's tolerance
    if (r.pareto) pareto.push_back(&r);
  }
  std::sort(pareto.begin(), pareto.end(), [](const TradeRun* a, const TradeRun* b) { return a->seconds < b->seconds; });
  for (const TradeRun* r : pareto) {
    front.x.push_back(r->seconds);
    front.y.push_back(std::max(r->error_m, 1e-15));
  }
  std::vector<render::Series> all;
  for (auto& [name, series] : by) all.push_back(series);
  all.push_back(front);
  try {
    figures::linePlot(path, all, "Error against cost: " + s.scene_name + strf(" (%g s run; labels: tolerance)", s.duration),
                      "CPU time (s)", "largest tip position error (m)", true, true);
  } catch (const std::runtime_error& e) {
    throw OutputError(e.what());
  }
}

}  // namespace

int runTradeCommand(const TradeArgs& args) {
  return guarded([&] {
    const Scene scene = loadScene(args);
    TradeOptions o;
    if (!args.integrators.empty()) o.integrators = args.integrators;
    if (!args.accuracies.empty()) o.accuracies = args.accuracies;
    if (!args.segments_ladder.empty()) o.segments = args.segments_ladder;
    if (!args.modes_ladder.empty()) o.modes = args.modes_ladder;  // the ladder skips 0
    if (!args.modes_accuracies.empty()) o.modes_accuracies = args.modes_accuracies;
    o.duration = args.duration;
    o.points = args.points;
    o.target_m = args.target_error;
    o.skip_costlier = !args.all;
    o.cut_costlier = !args.all;  // a run past the cheapest within the target cannot be it either
    o.run_budget_s = args.run_budget;
    o.total_budget_s = args.time_budget;
    for (const auto* list : {&o.accuracies, &o.modes_accuracies})
      for (double a : *list)
        if (!(a > 0 && a < 1))
          throw UsageError(strf("%s: a relative accuracy must be in (0, 1) (got %g)",
                                list == &o.accuracies ? "--accuracies" : "--modes-accuracies", a));
    for (const auto& name : o.integrators)
      if (!findIntegrator(name))
        throw UsageError("--integrators: unknown integrator '" + name + "'" + integratorSuggestion(name) + " (known: " +
                         integratorNames() + ")");
    std::unique_ptr<OutputDir> out;
    if (!args.out.empty()) out = std::make_unique<OutputDir>(args.out, args.force);
    TradeProblem problem = std::visit(
        [&](const auto& sc) {
          if constexpr (std::is_same_v<std::decay_t<decltype(sc)>, HamsasScene>) return hamsasTradeProblem(sc, o.duration);
          else return articleTradeProblem(sc, o.duration);
        },
        scene);
    const TradeStudy s = [&] {
      Progress progress("trade, runs done");
      reportProgress(problem, o, progress);
      return runTrade(problem, o);
    }();
    const double target = s.target_m;
    checkResultFinite(tradeJson(s, target));  // before any file is committed
    if (out) {
      out->write("trade.csv", tradeCsv(s));
      out->write("trade.json", tradeJson(s, target).dump(2) + "\n");
      writeTradePlot(out->stage("trade.png"), s);
      out->commit();  // reported as written when the command succeeds
    }
    args.json ? emitResult(tradeJson(s, target)) : emitResult(tradeText(s, target));
    return kOk;
  });
}

}  // namespace mmv::cli
