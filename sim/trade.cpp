#include "sim/trade.hpp"

#include <algorithm>
#include <cmath>

#include "article/article_spec.hpp"
#include "sim/simulation.hpp"
#include "sim/statics.hpp"

namespace mmv {
namespace {

/// Column indices of the scored tips' x and y (every tip when `points` is empty).
std::vector<std::pair<int, int>> tipColumns(const SimulationRecord& r, const std::vector<std::string>& points) {
  std::vector<std::pair<int, int>> out;
  for (std::size_t c = 0; c + 1 < r.columns.size(); ++c) {
    const std::string& name = r.columns[c];
    if (name.size() <= 8 || name.compare(name.size() - 8, 8, ".tip_x_m") != 0) continue;
    const std::string point = name.substr(0, name.size() - 5);  // "link3a.tip"
    if (points.empty() || std::find(points.begin(), points.end(), point) != points.end())
      out.push_back({static_cast<int>(c), static_cast<int>(c + 1)});
  }
  return out;
}

double distance(const SimulationRecord& a, const SimulationRecord& b, const std::vector<std::string>& points) {
  const auto ca = tipColumns(a, points), cb = tipColumns(b, points);
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
  if (!o.points.empty()) {
    std::vector<std::string> tips;
    for (const auto& p : articlePointNames(scene.article))
      if (p.size() > 4 && p.compare(p.size() - 4, 4, ".tip") == 0) tips.push_back(p);
    for (const auto& p : o.points)
      if (std::find(tips.begin(), tips.end(), p) == tips.end()) {
        std::string known;
        for (const auto& t : tips) known += (known.empty() ? "" : ", ") + t;
        throw SceneError(scene.source + ": trade: '" + p + "' is not a link tip of the scene (known: " + known + ")");
      }
  }
  TradeStudy study;
  study.scene_name = scene.name;
  study.points = o.points;
  study.duration = scene.simulation.duration;
  auto run = [&](Scene s, const std::string& integrator, double accuracy) {
    s.simulation.integrator = integrator;
    s.simulation.accuracy = accuracy;
    return simulate(s);
  };
  const SimulationResult ref = run(scene, "cpodes", 1e-10);
  const SimulationResult check = run(scene, "cvode_bdf", 1e-10);
  study.reference_uncertainty_m = distance(ref.record, check.record, o.points);
  study.reference_seconds = ref.wall_seconds;
  // One scored run: its error against the reference and its cost, or its diagnostic.
  auto measure = [&](const Scene& s, const std::string& integrator, double accuracy, int segments) {
    TradeRun r;
    r.integrator = integrator;
    r.accuracy = accuracy;
    r.segments = segments;
    try {
      const SimulationResult res = run(s, integrator, accuracy);
      r.error_m = distance(res.record, ref.record, o.points);
      r.seconds = res.wall_seconds;
      r.evaluations = res.realizations;
    } catch (const NumericalError& e) {
      r.ok = false;
      r.failure = e.what();
    }
    study.runs.push_back(r);
  };
  for (const auto& name : o.integrators)
    for (double acc : o.accuracies) measure(scene, name, acc, 0);
  for (int n : o.segments) {
    Scene s = scene;
    overrideSegments(s, n);
    measure(s, "cpodes", 1e-8, n);
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
