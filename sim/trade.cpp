#include "sim/trade.hpp"

#include <algorithm>
#include <cmath>

#include "sim/simulation.hpp"
#include "sim/statics.hpp"

namespace mmv {
namespace {

/// Column indices of the link tips' x and y.
std::vector<std::pair<int, int>> tipColumns(const SimulationRecord& r) {
  std::vector<std::pair<int, int>> out;
  for (std::size_t c = 0; c + 1 < r.columns.size(); ++c)
    if (r.columns[c].size() > 8 && r.columns[c].compare(r.columns[c].size() - 8, 8, ".tip_x_m") == 0)
      out.push_back({static_cast<int>(c), static_cast<int>(c + 1)});
  return out;
}

double distance(const SimulationRecord& a, const SimulationRecord& b) {
  const auto ca = tipColumns(a), cb = tipColumns(b);
  double worst = 0;
  const std::size_t rows = std::min(a.rows.size(), b.rows.size());
  for (std::size_t k = 0; k < rows; ++k)
    for (std::size_t t = 0; t < std::min(ca.size(), cb.size()); ++t)
      worst = std::max(worst, std::hypot(a.rows[k][ca[t].first] - b.rows[k][cb[t].first],
                                         a.rows[k][ca[t].second] - b.rows[k][cb[t].second]));
  return worst;
}

}  // namespace

TradeStudy runTrade(const Scene& base, const TradeOptions& o) {
  Scene scene = base;
  if (o.duration > 0) scene.simulation.duration = o.duration;
  TradeStudy study;
  study.scene_name = scene.name;
  study.duration = scene.simulation.duration;
  auto run = [&](Scene s, const std::string& integrator, double accuracy) {
    s.simulation.integrator = integrator;
    s.simulation.accuracy = accuracy;
    return simulate(s);
  };
  const SimulationResult ref = run(scene, "cpodes", 1e-10);
  const SimulationResult check = run(scene, "cvode_bdf", 1e-10);
  study.reference_uncertainty_m = distance(ref.record, check.record);
  study.reference_seconds = ref.wall_seconds;
  for (const auto& name : o.integrators)
    for (double acc : o.accuracies) {
      TradeRun r;
      r.integrator = name;
      r.accuracy = acc;
      try {
        const SimulationResult s = run(scene, name, acc);
        r.error_m = distance(s.record, ref.record);
        r.seconds = s.wall_seconds;
        r.evaluations = s.realizations;
      } catch (const NumericalError& e) {
        r.ok = false;
        r.failure = e.what();
      }
      study.runs.push_back(r);
    }
  for (int n : o.segments) {
    TradeRun r;
    r.integrator = "cpodes";
    r.accuracy = 1e-8;
    r.segments = n;
    Scene s = scene;
    overrideSegments(s, n);
    try {
      const SimulationResult res = run(s, "cpodes", 1e-8);
      r.error_m = distance(res.record, ref.record);
      r.seconds = res.wall_seconds;
      r.evaluations = res.realizations;
    } catch (const NumericalError& e) {
      r.ok = false;
      r.failure = e.what();
    }
    study.runs.push_back(r);
  }
  // Pareto front among the integrator runs at the scene's segments.
  for (auto& a : study.runs) {
    if (!a.ok || a.segments) continue;
    a.pareto = true;
    for (const auto& b : study.runs)
      if (b.ok && !b.segments && &a != &b && b.seconds <= a.seconds && b.error_m <= a.error_m &&
          (b.seconds < a.seconds || b.error_m < a.error_m))
        a.pareto = false;
  }
  return study;
}

}  // namespace mmv
