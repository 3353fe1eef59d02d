#include "sim/time/trade.hpp"

#include <algorithm>
#include <cmath>

#include "article/article_spec.hpp"
#include "sim/core/integrators.hpp"
#include "sim/core/text.hpp"
#include "sim/scene/stations.hpp"
#include "sim/time/verify.hpp"

namespace mmv {

double defaultTradeTarget(const TradeStudy& s) { return defaultErrorTarget(s.reference_amplitude_m); }

TradeProblem tradeProblemBase(const std::string& scene_name, SimulationSpec simulation, double duration) {
  TradeProblem p;
  if (duration > 0) simulation.duration = duration;
  if (simulation.duration * simulation.sample_rate_hz > limits::kMaxSamples)
    throw UsageError(strf("--duration %g s at the scene's %g Hz is %.3g samples, above the limit of %.0f a run",
                          simulation.duration, simulation.sample_rate_hz, simulation.duration * simulation.sample_rate_hz,
                          limits::kMaxSamples));
  p.scene_name = scene_name;
  p.duration = simulation.duration;
  p.simulation = simulation;
  return p;
}

TradeProblem articleTradeProblem(const ArticleScene& base, double duration) {
  TradeProblem p = tradeProblemBase(base.name, base.simulation, duration);
  ArticleScene scene = base;
  scene.simulation = p.simulation;
  for (const auto& name : articlePointNames(scene.article))
    if (name.size() > 4 && name.compare(name.size() - 4, 4, ".tip") == 0) p.scorable.push_back(name);
  p.scorable_kind = "link tip";
  const ArticleSpec article = scene.article;
  p.also_scores = [article](const std::string& name, std::string& error) {
    return isStationName(name) && parseStation(name, article, error).has_value();
  };
  p.run = [scene](const SimulationSpec& spec, int segments) {
    ArticleScene s = scene;
    s.simulation = spec;
    if (segments > 0) overrideSegments(s, segments);
    return simulate(s);
  };
  return p;
}

TradeStudy runTrade(const TradeProblem& problem, const TradeOptions& options) {
  TradeOptions o = options;
  const SimulationSpec& spec0 = problem.simulation;
  const bool from_scene = o.points.empty() && !spec0.score_points.empty();
  if (from_scene) o.points = spec0.score_points;
  for (const auto& p : o.points) {
    if (std::find(problem.scorable.begin(), problem.scorable.end(), p) != problem.scorable.end()) continue;
    std::string error;
    if (problem.also_scores && problem.also_scores(p, error)) continue;
    std::string known;
    for (const auto& t : problem.scorable) known += (known.empty() ? "" : ", ") + t;
    if (problem.also_scores) known += ", or a station <link>@<m>m or <link>@<fraction>";
    const std::string what = error.empty() ? "'" + p + "' is not a " + problem.scorable_kind + " of the scene (known: " + known + ")"
                                           : "'" + p + "': " + error;
    if (from_scene) throw SceneError(spec0.score_where + ": simulation.score_points: " + what);
    throw UsageError("--points: " + what);
  }
  TradeStudy study;
  study.scene_name = problem.scene_name;
  study.points = o.points;
  study.duration = problem.duration;
  study.reference_integrator = problem.reference_integrator;
  study.check_integrator = problem.check_integrator;
  auto run = [&](int segments, const std::string& integrator, double accuracy) {
    SimulationSpec spec = spec0;
    spec.score_points = o.points;  // every run records the points scored (stations among them)
    spec.integrator = integrator;
    spec.accuracy = accuracy;
    // The scene's absolute tolerance applies to SUNDIALS' methods only.
    if (!isSundialsIntegrator(integrator)) spec.absolute_tolerance = 0;
    return problem.run(spec, segments);
  };
  const SimulationResult ref = run(0, study.reference_integrator, 1e-10);
  const SimulationResult check = run(0, study.check_integrator, 1e-10);
  study.reference_uncertainty_m = scoredDistance(ref.record, check.record, o.points).distance_m;
  study.reference_amplitude_m = scoredAmplitude(ref.record, o.points);
  study.reference_seconds = ref.wall_seconds;
  // One scored run: its error against the reference and its cost, or its diagnostic.
  auto measure = [&](int segments, const std::string& integrator, double accuracy) {
    TradeRun r;
    r.integrator = integrator;
    r.accuracy = accuracy;
    r.segments = segments;
    try {
      const SimulationResult res = run(segments, integrator, accuracy);
      r.error_m = scoredDistance(res.record, ref.record, o.points).distance_m;
      r.seconds = res.wall_seconds;
      r.evaluations = res.realizations;
    } catch (const NumericalError& e) {
      r.ok = false;
      r.failure = e.what();
    }
    study.runs.push_back(r);
  };
  for (const auto& name : o.integrators)
    for (double acc : o.accuracies) measure(0, name, acc);
  if (problem.has_segments)  // rigid bodies: no segments
    for (int n : o.segments) measure(n, "cpodes", 1e-8);
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
