#include "sim/trade.hpp"

#include <algorithm>
#include <cmath>

#include "article/article_spec.hpp"
#include "sim/run_integrator.hpp"
#include "sim/simulation.hpp"
#include "sim/statics.hpp"

namespace mmv {
namespace {

/// The largest distance between the two runs' scored points (every one when `points`
/// is empty) over their common samples.
double distance(const SimulationRecord& a, const SimulationRecord& b, const std::vector<std::string>& points) {
  double worst = 0;
  const std::size_t rows = std::min(a.rows.size(), b.rows.size());
  for (const auto& [name, ca] : a.scored) {
    if (!points.empty() && std::find(points.begin(), points.end(), name) == points.end()) continue;
    for (const auto& [other, cb] : b.scored) {
      if (other != name) continue;
      for (std::size_t k = 0; k < rows; ++k) {
        double d2 = 0;
        for (std::size_t c = 0; c < ca.size(); ++c) d2 += std::pow(a.rows[k][ca[c]] - b.rows[k][cb[c]], 2);
        worst = std::max(worst, std::sqrt(d2));
      }
    }
  }
  return worst;
}

}  // namespace

TradeStudy runTrade(const Scene& base, const TradeOptions& options) {
  Scene scene = base;
  TradeOptions o = options;
  const bool from_scene = o.points.empty() && !scene.simulation.score_points.empty();
  if (from_scene) o.points = scene.simulation.score_points;
  if (o.duration > 0) scene.simulation.duration = o.duration;
  if (!o.points.empty()) {
    std::vector<std::string> tips;
    if (scene.hamsas)  // the bodies simulateHamsas scores: the optical table and the spring box
      for (int b : {1, 2}) tips.push_back(buildHamsas(*scene.hamsas).bodies[b].name);
    for (const auto& p : articlePointNames(scene.article))
      if (p.size() > 4 && p.compare(p.size() - 4, 4, ".tip") == 0) tips.push_back(p);
    for (const auto& p : o.points)
      if (std::find(tips.begin(), tips.end(), p) == tips.end()) {
        std::string known;
        for (const auto& t : tips) known += (known.empty() ? "" : ", ") + t;
        throw SceneError((from_scene ? scene.simulation.score_where + ": simulation.score_points" : scene.source + ": trade") + ": '" + p + (scene.hamsas ? "' is not a scored body" : "' is not a link tip") + " of the scene (known: " + known + ")");
      }
  }
  TradeStudy study;
  study.scene_name = scene.name;
  study.points = o.points;
  study.duration = scene.simulation.duration;
  auto run = [&](Scene s, const std::string& integrator, double accuracy) {
    s.simulation.integrator = integrator;
    s.simulation.accuracy = accuracy;
    // The scene's absolute tolerance applies to SUNDIALS' methods only.
    if (!isSundialsIntegrator(integrator)) s.simulation.absolute_tolerance = 0;
    return simulate(s);
  };
  if (scene.hamsas) study.reference_integrator = "rk_merson", study.check_integrator = "arkode_erk";
  const SimulationResult ref = run(scene, study.reference_integrator, 1e-10);
  const SimulationResult check = run(scene, study.check_integrator, 1e-10);
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
  for (int n : scene.hamsas ? std::vector<int>{} : o.segments) {  // rigid bodies: no segments
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
