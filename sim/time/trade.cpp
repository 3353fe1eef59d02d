#include "sim/time/trade.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>

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
  p.run = [scene](const SimulationSpec& spec, int segments, const std::function<void(double)>& progress) {
    ArticleScene s = scene;
    s.simulation = spec;
    if (segments > 0) overrideSegments(s, segments);
    return simulate(s, progress);
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
  const auto t0 = std::chrono::steady_clock::now();
  auto elapsed = [&t0] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(); };
  auto run = [&](int segments, const std::string& integrator, double accuracy, const std::function<void(double)>& progress) {
    SimulationSpec spec = spec0;
    spec.score_points = o.points;  // every run records the points scored (stations among them)
    spec.integrator = integrator;
    spec.accuracy = accuracy;
    // The scene's absolute tolerance applies to SUNDIALS' methods only.
    if (!isSundialsIntegrator(integrator)) spec.absolute_tolerance = 0;
    return problem.run(spec, segments, progress);
  };
  const SimulationResult ref = run(0, study.reference_integrator, 1e-10, {});
  const SimulationResult check = run(0, study.check_integrator, 1e-10, {});
  study.reference_uncertainty_m = scoredDistance(ref.record, check.record, o.points).distance_m;
  study.reference_amplitude_m = scoredAmplitude(ref.record, o.points);
  study.reference_seconds = ref.wall_seconds;
  study.target_m = o.target_m > 0 ? o.target_m : defaultTradeTarget(study);
  // One scored run: its error against the reference and its cost, or why it has none.
  auto measure = [&](int segments, const std::string& integrator, double accuracy) -> const TradeRun& {
    TradeRun r;
    r.integrator = integrator;
    r.accuracy = accuracy;
    r.segments = segments;
    const auto started = std::chrono::steady_clock::now();
    auto cut = [&](double fraction) {  // the per-run and the total budget, checked at every sample
      const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
      if (o.run_budget_s > 0 && s > o.run_budget_s) throw RunBudgetExceeded(fraction, s, false);
      if (o.total_budget_s > 0 && elapsed() > o.total_budget_s) throw RunBudgetExceeded(fraction, s, true);
    };
    if (o.total_budget_s > 0 && elapsed() > o.total_budget_s) {
      r.ok = false;
      r.status = "not_run";
      r.failure = strf("not run: the trade's %g s budget was spent", o.total_budget_s);
    } else {
      try {
        const SimulationResult res = run(segments, integrator, accuracy, cut);
        r.error_m = scoredDistance(res.record, ref.record, o.points).distance_m;
        r.seconds = res.wall_seconds;
        r.evaluations = res.realizations;
      } catch (const NumericalError& e) {
        r.ok = false;
        r.status = "failed";
        r.failure = e.what();
      } catch (const RunBudgetExceeded& e) {
        r.ok = false;
        r.status = e.total ? "not_run" : "over_budget";
        r.failure = e.total ? strf("cut after %.3g s at %.0f %% of the run: the trade's %g s budget was spent", e.seconds,
                                   100 * e.fraction, o.total_budget_s)
                            : strf("over its %g s budget: cut after %.3g s at %.0f %% of the run", o.run_budget_s,
                                   e.seconds, 100 * e.fraction);
      }
    }
    study.runs.push_back(r);
    return study.runs.back();
  };
  // The cheapest run within the target so far (seconds), or infinity.
  auto cheapestWithinTarget = [&]() {
    double best = INFINITY;
    for (const auto& r : study.runs)
      if (r.ok && !r.segments && r.error_m <= study.target_m) best = std::min(best, r.seconds);
    return best;
  };
  std::vector<double> loose_to_tight = o.accuracies;
  std::sort(loose_to_tight.begin(), loose_to_tight.end(), std::greater<double>());
  auto skipped = [&](const std::string& name, double acc, const std::string& status, const std::string& why) {
    TradeRun r;
    r.integrator = name;
    r.accuracy = acc;
    r.ok = false;
    r.status = status;
    r.failure = why;
    study.runs.push_back(r);
  };
  for (const auto& name : o.integrators) {
    double looser_cost = 0;  // the largest cost of this integrator's looser runs
    bool cut = false;        // a looser run was over the budget: a tighter one would be too
    for (double acc : loose_to_tight) {
      const double best = cheapestWithinTarget();
      if (cut) {
        skipped(name, acc, "not_run", strf("not run: a looser run was over the %g s budget", o.run_budget_s));
      } else if (o.skip_costlier && looser_cost > best) {
        skipped(name, acc, "costlier",
                strf("skipped: costlier (a looser run %.3g s, the cheapest within the target %.3g s)", looser_cost, best));
      } else {
        const TradeRun& r = measure(0, name, acc);
        if (r.ok) looser_cost = std::max(looser_cost, r.seconds);
        cut = r.status == "over_budget";
      }
    }
  }
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
  study.total_seconds = elapsed();
  return study;
}

}  // namespace mmv
