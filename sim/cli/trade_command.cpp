// mmvlab trade: the speed-accuracy trade of a time run (sim/trade.hpp).
#include <algorithm>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>

#include "renders/plot.hpp"
#include "sim/cli/commands.hpp"
#include "sim/cli/output_dir.hpp"
#include "sim/report.hpp"
#include "sim/table.hpp"
#include "sim/trade.hpp"

namespace mmv::cli {
namespace {

const TradeRun* cheapestWithin(const TradeStudy& s, double target) {
  const TradeRun* best = nullptr;
  for (const auto& r : s.runs)
    if (r.ok && !r.segments && r.error_m <= target && (!best || r.seconds < best->seconds)) best = &r;
  return best;
}

std::string text(const TradeStudy& s, double target) {
  std::ostringstream os;
  os << s.scene_name << strf(": speed-accuracy trade of a %.4g s time run\n", s.duration);
  os << strf("Reference: %s at 1e-10 (%.2f s); its difference from %s at 1e-10 is %.2g m, below which errors "
             "cannot be told apart\n\n",
             s.reference_integrator.c_str(), s.reference_seconds, s.check_integrator.c_str(), s.reference_uncertainty_m);
  if (!s.points.empty()) {
    os << "Error scored at:";
    for (const auto& p : s.points) os << ' ' << p;
    os << "\n\n";
  }
  Table t({"integrator", "accuracy", "segments", "tip_error_m", "cpu_s", "evaluations", "pareto"});
  for (const auto& r : s.runs) {
    if (!r.ok) {
      t.add({r.integrator, strf("%.0e", r.accuracy), r.segments ? strf("%d", r.segments) : "scene", "FAILED: " + r.failure});
      continue;
    }
    t.add({r.integrator, strf("%.0e", r.accuracy), r.segments ? strf("%d", r.segments) : "scene", strf("%.3g", r.error_m),
           strf("%.3f", r.seconds), strf("%ld", r.evaluations), r.pareto ? "*" : ""});
  }
  os << t.text();
  const TradeRun* best = cheapestWithin(s, target);
  if (best)
    os << strf("\nCheapest run within %.3g m: %s at accuracy %.0e (%.3f s, error %.3g m)\n", target, best->integrator.c_str(),
               best->accuracy, best->seconds, best->error_m);
  else
    os << strf("\nNo run reached %.3g m: tighten the accuracies\n", target);
  return os.str();
}

nlohmann::ordered_json json(const TradeStudy& s, double target) {
  nlohmann::ordered_json j;
  j["mmvlab_version"] = mmvlabVersion();
  j["command"] = "trade";
  j["duration_s"] = s.duration;
  j["reference"] = {{"integrator", s.reference_integrator},
                    {"check_integrator", s.check_integrator},
                    {"accuracy", 1e-10},
                    {"uncertainty_m", s.reference_uncertainty_m}};
  j["points"] = s.points;  // empty: every link tip
  auto runs = nlohmann::ordered_json::array();
  for (const auto& r : s.runs) {
    nlohmann::ordered_json x = {{"integrator", r.integrator}, {"accuracy", r.accuracy}, {"segments", r.segments}, {"ok", r.ok}};
    if (r.ok) {
      x["tip_error_m"] = r.error_m;
      x["cpu_s"] = r.seconds;
      x["evaluations"] = r.evaluations;
      x["pareto"] = r.pareto;
    } else {
      x["failure"] = r.failure;
    }
    runs.push_back(x);
  }
  j["runs"] = runs;
  const TradeRun* best = cheapestWithin(s, target);
  j["target_error_m"] = target;
  j["cheapest_within_target"] = best ? nlohmann::ordered_json{{"integrator", best->integrator}, {"accuracy", best->accuracy}}
                                     : nlohmann::ordered_json(nullptr);
  return j;
}

}  // namespace

int runTradeCommand(const TradeArgs& args) {
  return guarded([&] {
    const Scene scene = loadScene(args);
        TradeOptions o;
    if (!args.integrators.empty()) o.integrators = args.integrators;
    if (!args.accuracies.empty()) o.accuracies = args.accuracies;
    if (!args.segments_ladder.empty()) o.segments = args.segments_ladder;
    o.duration = args.duration;
    o.points = args.points;
    std::unique_ptr<OutputDir> out;
    if (!args.out.empty()) out = std::make_unique<OutputDir>(args.out, args.force);
    const TradeStudy s = runTrade(scene, o);
    if (out) {
      std::ostringstream csv;
      csv << "integrator,accuracy,segments,ok,tip_error_m,cpu_s,evaluations,pareto\n";
      for (const auto& r : s.runs)
        csv << r.integrator << ',' << strf("%.3g", r.accuracy) << ',' << r.segments << ',' << r.ok << ','
            << (r.ok ? strf("%.6g,%.6g,%ld,%d", r.error_m, r.seconds, r.evaluations, r.pareto ? 1 : 0) : std::string(",,,")) << '\n';
      std::ofstream(out->stage("trade.csv"), std::ios::binary) << csv.str();
      std::ofstream(out->stage("trade.json"), std::ios::binary) << json(s, args.target_error).dump(2) << '\n';
      std::map<std::string, render::Series> by;
      render::Series front{"Pareto front"};
      front.dashed = true;
      std::vector<const TradeRun*> pareto;
      for (const auto& r : s.runs) {
        if (!r.ok || r.segments) continue;
        auto& series = by[r.integrator];
        series.label = r.integrator;
        series.markers_only = true;
        series.x.push_back(r.seconds);
        series.y.push_back(std::max(r.error_m, 1e-15));
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
        render::writeLinePlotPng(out->stage("trade.png"), all, "Error against cost: " + s.scene_name, "CPU time (s)",
                                 "tip position error (m)", true, true);
      } catch (const std::runtime_error& e) {
        throw OutputError(e.what());
      }
      for (const auto& path : out->commit()) std::cerr << "mmvlab: wrote " << path << '\n';
    }
    std::cout << (args.json ? json(s, args.target_error).dump(2) + "\n" : text(s, args.target_error)) << std::flush;
    return kOk;
  });
}

}  // namespace mmv::cli
