#include "sim/app/trade_study.hpp"

#include <memory>
#include <type_traits>

#include "sim/core/integrators.hpp"
#include "sim/core/text.hpp"
#include "sim/hamsas/hamsas_simulation.hpp"
#include "sim/io/trade_report.hpp"

namespace mmv::app {
namespace {

TradeOptions checkedOptions(const TradeRequest& r) {
  checkOptions<TradeParams>(r, r.front);
  for (const auto& name : r.integrators)
    if (!findIntegrator(name))
      throw UsageError(declaredName<TradeParams>("integrators", r.front) + ": unknown integrator '" + name + "'" +
                       integratorSuggestion(name) + " (known: " + integratorNames() + ")");
  TradeOptions o;
  if (!r.integrators.empty()) o.integrators = r.integrators;
  if (!r.accuracies.empty()) o.accuracies = r.accuracies;
  if (!r.segments.empty()) o.segments = r.segments;
  if (!r.modes.empty()) o.modes = r.modes;  // the ladder skips 0
  if (!r.modes_accuracies.empty()) o.modes_accuracies = r.modes_accuracies;
  o.duration = r.duration.value_or(0);
  o.points = r.points;
  o.target_m = r.target_error.value_or(0);
  o.skip_costlier = !r.all;
  o.cut_costlier = !r.all;  // a run past the cheapest within the target cannot be it either
  o.run_budget_s = r.run_budget.value_or(0);
  o.total_budget_s = r.time_budget.value_or(0);
  return o;
}

/// Runs done of the trade's total (two references, the integrator grid, the segment
/// ladder, the modes ladder), reported as each run starts.
void reportProgress(TradeProblem& problem, const TradeOptions& o, const TradeProgress& progress) {
  int rungs = 0;  // the modes ladder's
  for (int k : o.modes) rungs += problem.has_modes && k > 0 && k < problem.finest_segments;
  const double total = 2.0 + double(o.integrators.size() * o.accuracies.size()) +
                       (problem.has_segments ? double(o.segments.size()) : 0.0) + double(rungs * o.modes_accuracies.size());
  auto done = std::make_shared<int>(0);
  problem.run = [inner = problem.run, progress, total, done](const SimulationSpec& spec, const RunFidelity& f,
                                                              const std::function<void(double)>& cut) {
    progress(*done, total,
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

}  // namespace

TradeStudyResult runTradeStudy(const Scene& scene, const TradeRequest& r, const TradeProgress& progress) {
  const TradeOptions o = checkedOptions(r);
  TradeProblem problem = std::visit(
      [&](const auto& sc) {
        if constexpr (std::is_same_v<std::decay_t<decltype(sc)>, HamsasScene>) return hamsasTradeProblem(sc, o.duration);
        else return articleTradeProblem(sc, o.duration);
      },
      scene);
  if (progress) reportProgress(problem, o, progress);
  TradeStudyResult s;
  s.study = runTrade(problem, o);
  s.target_m = s.study.target_m;
  s.json = tradeJson(s.study, s.target_m);
  s.text = tradeText(s.study, s.target_m);
  s.csv = tradeCsv(s.study);
  checkResultFinite(s.json);  // before any file is committed
  return s;
}

}  // namespace mmv::app
