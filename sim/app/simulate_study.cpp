#include "sim/app/simulate_study.hpp"

#include <memory>

#include "facility/table_programs.hpp"
#include "sim/core/integrators.hpp"
#include "sim/core/progress.hpp"
#include "sim/core/text.hpp"
#include "sim/hamsas/hamsas_simulation.hpp"
#include "sim/io/simulation_report.hpp"
#include "sim/model/motions.hpp"
#include "sim/scene/programs.hpp"
#include "sim/time/verify.hpp"

namespace mmv::app {
namespace {

void checkRequest(const SimulateRequest& r) {
  checkOptions<SimulateParams>(r, r.front);
  const auto opt = [&](const char* key) { return declaredName<SimulateParams>(key, r.front); };
  if (r.integrator && !findIntegrator(*r.integrator))
    throw UsageError(opt("integrator") + ": unknown integrator '" + *r.integrator + "'" + integratorSuggestion(*r.integrator) +
                     " (known: " + integratorNames() + ")");
  if (r.target_error) {
    if (r.accuracy) throw UsageError(opt("target_error") + " chooses the accuracy: drop " + opt("accuracy"));
    if (r.verify || r.verify_target)
      throw UsageError(opt("target_error") + " verifies its run itself: drop " + opt("verify") + " and " +
                       opt("verify_target"));
  } else if (!r.points.empty() || r.time_budget) {
    throw UsageError(opt(r.points.empty() ? "time_budget" : "points") + " applies to " + opt("target_error") + " only");
  }
}

void applyOverrides(const SimulateRequest& r, SimulationSpec& spec) {
  if (r.integrator) spec.integrator = *r.integrator;
  if (r.accuracy) spec.accuracy = *r.accuracy;
  if (r.absolute_tolerance) spec.absolute_tolerance = *r.absolute_tolerance;
  if (r.duration) spec.duration = *r.duration;
  if (r.sample_rate) spec.sample_rate_hz = *r.sample_rate;
  if (spec.duration * spec.sample_rate_hz > limits::kMaxSamples)
    throw UsageError(strf("%s %g s at %s %g Hz is %.3g samples, above the limit of %.0f",
                          declaredName<SimulateParams>("duration", r.front).c_str(), spec.duration,
                          declaredName<SimulateParams>("sample_rate", r.front).c_str(), spec.sample_rate_hz,
                          spec.duration * spec.sample_rate_hz, limits::kMaxSamples));
  if (spec.absolute_tolerance > 0 && !spec.integrator.empty() && !isSundialsIntegrator(spec.integrator))
    throw UsageError(declaredName<SimulateParams>("absolute_tolerance", r.front) +
                     " applies to the SUNDIALS integrators only (got integrator " + spec.integrator + ")");
}

/// The table program's stroke (an error) and bandwidth (warnings) over the run.
std::vector<std::string> checkTableProgram(const ArticleScene& scene) {
  std::vector<std::string> warnings;
  if (scene.article.base.type != BaseType::Table || !scene.article.base.motion) return warnings;
  std::shared_ptr<const facility::TableProgram> program;
  try {
    program = makeTableProgram(*scene.article.base.motion);
  } catch (const std::invalid_argument& e) {
    throw SceneError(e.what());
  }
  const facility::ProgramCheck check = facility::checkProgram(*program, {}, scene.simulation.duration);
  if (!check.within_stroke) throw SceneError(scene.positions.where("base.motion") + ": base.motion: " + check.messages.front());
  for (const auto& m : check.messages) warnings.push_back(m);
  return warnings;
}

/// One run, its progress reported as `what` in simulated seconds (and counted for the
/// checkpoint in permille).
template <class SceneT>
SimulationResult runWithProgress(const SceneT& scene, const std::string& what, const SimulateHooks& hooks) {
  const ProgressStage ps(what);
  const double duration = scene.simulation.duration;
  return simulate(scene, [&](double f) {
    progressCount(static_cast<long>(f * 1000), 1000, "permille");
    if (hooks.progress) hooks.progress(what, f * duration, duration, "");
  });
}

/// The run asked for: the scene's settings, or the contract's choice (then verified by it).
template <class SceneT>
SimulationResult runOrTarget(const SimulateRequest& r, SceneT& scene, const TradeProblem& problem, SimulateStudy& s,
                             const SimulateHooks& hooks) {
  if (!r.target_error) return runWithProgress(scene, "time run, seconds simulated", hooks);
  TargetOptions o;
  o.target_m = *r.target_error;
  o.points = r.points;
  o.time_budget_s = r.time_budget.value_or(0);
  if (r.integrator) o.integrators = {*r.integrator};
  const std::string what = "target error: pilot, then whole runs";
  const ProgressStage ps(what);
  s.target = runToTarget(problem, o, [&](const std::string& stage, double f) {
    progressCount(static_cast<long>(f * 1000), 1000, "permille");
    if (hooks.progress) hooks.progress(what, f, 1.0, stage);
  });
  SimulationResult result = std::move(s.target->result);
  s.target->result = {};
  scene.simulation.integrator = result.integrator;
  scene.simulation.accuracy = result.accuracy;
  if (s.target->attempts.back().segments) s.segments_chosen = s.target->attempts.back().segments;
  return result;
}

template <class SceneT>
void verify(const SimulateRequest& r, const SceneT& scene, SimulationResult& result, const SimulateHooks& hooks) {
  if (!r.verify && !r.verify_target) return;
  result.verification = verifyRun(result, scene.simulation, [&](const SimulationSpec& spec) {
    SceneT tight = scene;
    tight.simulation = spec;
    return runWithProgress(tight, "verification run at a 10x tighter tolerance, seconds simulated", hooks);
  }, r.verify_target.value_or(0));
}

/// Runs `scene` (a copy the request's settings are applied to) and fills the study.
template <class SceneT>
SimulateStudy run(SceneT scene, const SimulateRequest& r, const SimulateHooks& hooks, const TradeProblem& problem,
                  std::vector<std::string> warnings, double size_m) {
  SimulateStudy s;
  s.result = runOrTarget(r, scene, problem, s, hooks);
  scene.simulation.integrator = s.result.integrator;  // the one the run used (the default fidelity may choose it)
  for (const auto& w : s.result.warnings) {
    warnings.push_back(w);
    if (hooks.warn) hooks.warn(w);
  }
  verify(r, scene, s.result, hooks);
  for (const auto& w : simulationWarnings(s.result, size_m)) warnings.push_back(w);
  s.spec = scene.simulation;
  s.summary = simulationJson(s.result, warnings);
  if (s.target) s.summary["target_error"] = targetJson(*s.target);
  checkResultFinite(s.summary);  // before anything is committed: no NaN reaches a file either
  s.text = simulationText(scene.name, scene.source, s.result, warnings) + (s.target ? "\n" + targetText(*s.target) : std::string());
  s.warnings = std::move(warnings);
  return s;
}

}  // namespace

SimulateStudy runSimulateStudy(const Scene& scene, const SimulateRequest& r, const SimulateHooks& hooks) {
  checkRequest(r);
  if (const auto* h = std::get_if<HamsasScene>(&scene)) {
    HamsasScene hs = *h;
    applyOverrides(r, hs.simulation);
    return run(hs, r, hooks, hamsasTradeProblem(hs), {}, 0.0);
  }
  ArticleScene a = std::get<ArticleScene>(scene);
  applyOverrides(r, a.simulation);
  std::vector<std::string> warnings = checkTableProgram(a);
  for (const SlewTiming& t : slewTimings(a.article))  // before: accepted silently
    if (const std::string outside = slewOutsideRun(t, a.simulation.duration); !outside.empty())
      warnings.push_back(t.axis + "'s slew: " + outside);
  if (hooks.warn)
    for (const auto& w : warnings) hooks.warn(w);
  double size = 0;
  for (const auto& l : a.article.links) size += l.length;
  try {
    return run(a, r, hooks, articleTradeProblem(a), warnings, size);
  } catch (const std::invalid_argument& e) {  // a facility model refused its command
    throw SceneError(a.positions.where("base") + ": " + e.what());
  }
}

}  // namespace mmv::app
