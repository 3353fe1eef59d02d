// mmvlab trade: the speed-accuracy trade of a time run (sim/time/trade.hpp).
#include <algorithm>
#include <cmath>
#include <fstream>
#include <iostream>
#include <map>
#include <optional>

#include "sim/app/trade_study.hpp"
#include "sim/cli/figures.hpp"
#include "sim/cli/commands.hpp"
#include "sim/cli/progress.hpp"
#include "sim/core/text.hpp"
#include "sim/io/output_dir.hpp"
#include "sim/core/integrators.hpp"
#include "sim/io/trade_report.hpp"

namespace mmv::cli {
namespace {

/// Error against cost, one series per integrator (and per modes-per-link rung), with
/// the Pareto front.
void writeTradePlot(const std::string& path, const TradeStudy& s) {
  std::map<std::string, render::Series> by;
  // The front: a black ring on each of its runs (the legend's entry), joined by a dashed
  // line when it has two or more. A dashed line alone drew nothing when one run dominated
  // every other (CI's layout check caught the empty legend entry on a 0.3 s trade).
  render::Series front{"Pareto front", {}, {}}, front_line{"", {}, {}};
  front.markers_only = front.hollow = true;
  front.colour_index = front_line.colour_index = 0;  // black: never an integrator's colour
  front_line.dashed = true;
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
    series.hollow = r.modes > 0;  // a modal rung is a ring: never mistaken for an integrator of the same colour
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
  front_line.x = front.x, front_line.y = front.y;
  std::vector<render::Series> all;
  double t0 = INFINITY, t1 = -INFINITY;
  for (auto& [name, series] : by) {
    all.push_back(series);
    for (double x : series.x) t0 = std::min(t0, x), t1 = std::max(t1, x);
  }
  if (front.x.size() > 1) all.push_back(front_line);
  all.push_back(front);
  if (s.target_m > 0 && t1 >= t0) {  // the error the cheapest run was named for (issue 36: no target line)
    render::Series target{strf("target %.2g m", s.target_m), {t0, t1}, {s.target_m, s.target_m}};
    target.dashed = true;
    target.colour_index = 13;  // grey
    all.push_back(target);
  }
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
    const auto r = declaredRequest<app::TradeRequest>(args);
    std::optional<OutputDir> out;  // lives until stdout has the result: a failure there puts --out back
    if (!args.out.empty()) out.emplace(args.out, args.force);  // a bad --out refused before the work
    const app::TradeStudyResult s = [&] {
      Progress progress("trade, runs done");
      return app::runTradeStudy(scene, r, [&](double done, double total, const std::string& detail) {
        progress.report(done, total, detail);
      });
    }();
    if (out) {
      out->write("trade.csv", s.csv);
      out->write("trade.json", s.json.dump(2) + "\n");
      writeTradePlot(out->stage("trade.png"), s.study);
      out->commit();  // reported as written when the command succeeds
    }
    args.json ? emitResult(s.json) : emitResult(s.text);
    return kOk;
  });
}

}  // namespace mmv::cli
