// mmvlab simulate: a time run of the scene (sim/time/simulation.hpp; the isolator's:
// sim/hamsas/hamsas_simulation.hpp), written by sim/io/simulation_report.hpp.

#include <cstdio>
#include <fstream>
#include <iostream>
#include <optional>

#include "facility/table_programs.hpp"
#include "sim/cli/commands.hpp"
#include "sim/cli/progress.hpp"
#include "sim/core/integrators.hpp"
#include "sim/core/text.hpp"
#include "sim/hamsas/hamsas_simulation.hpp"
#include "sim/time/target.hpp"
#include "sim/time/verify.hpp"
#include "sim/io/output_dir.hpp"
#include "sim/io/simulation_report.hpp"
#include "sim/model/motions.hpp"

namespace mmv::cli {
namespace {

void applyOverrides(const SimulateArgs& args, SimulationSpec& spec) {
  if (args.target_error > 0) {
    if (args.accuracy > 0) throw UsageError("--target-error chooses the accuracy: drop --accuracy");
    if (args.verify || args.verify_target > 0)
      throw UsageError("--target-error verifies its run itself: drop --verify and --verify-target");
  } else if (!args.points.empty() || args.time_budget > 0) {
    throw UsageError(std::string(args.points.empty() ? "--time-budget" : "--points") + " applies to --target-error only");
  }
  if (!args.integrator.empty()) spec.integrator = args.integrator;
  if (args.accuracy > 0) spec.accuracy = args.accuracy;
  if (args.absolute_tolerance > 0) spec.absolute_tolerance = args.absolute_tolerance;
  if (args.duration > 0) spec.duration = args.duration;
  if (args.sample_rate > 0) spec.sample_rate_hz = args.sample_rate;
  if (spec.duration * spec.sample_rate_hz > limits::kMaxSamples)
    throw UsageError(strf("--duration %g s at --sample-rate %g Hz is %.3g samples, above the limit of %.0f", spec.duration,
                          spec.sample_rate_hz, spec.duration * spec.sample_rate_hz, limits::kMaxSamples));
  if (spec.absolute_tolerance > 0 && !isSundialsIntegrator(spec.integrator))
    throw UsageError("--absolute-tolerance applies to the SUNDIALS integrators only (got integrator " + spec.integrator + ")");
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

/// A time run with its progress on standard error (seconds simulated); the progress
/// line ends before the run's report is written.
template <class SceneT>
SimulationResult simulateWithProgress(const SceneT& scene) {
  Progress progress("time run, seconds simulated");
  const double duration = scene.simulation.duration;
  return simulate(scene, [&progress, duration](double f) { progress.report(f * duration, duration); });
}

/// `--verify`: the companion run (with its own progress line) and the estimate.
template <class SceneT>
void verify(const SimulateArgs& args, const SceneT& scene, SimulationResult& r) {
  if (!args.verify && !(args.verify_target > 0)) return;
  r.verification = verifyRun(r, scene.simulation, [&](const SimulationSpec& spec) {
    SceneT tight = scene;
    tight.simulation = spec;
    Progress progress("verification run at a 10x tighter tolerance, seconds simulated");
    const double duration = spec.duration;
    return simulate(tight, [&progress, duration](double f) { progress.report(f * duration, duration); });
  }, args.verify_target);
}

/// `--target-error`: the run chosen, run and verified (sim/time/target.hpp), with a
/// progress line naming the stage.
TargetOutcome runTarget(const SimulateArgs& args, const TradeProblem& problem) {
  TargetOptions o;
  o.target_m = args.target_error;
  o.points = args.points;
  o.time_budget_s = args.time_budget;
  if (!args.integrator.empty()) o.integrators = {args.integrator};
  Progress progress("target error: pilot, then whole runs");
  return runToTarget(problem, o, [&](const std::string& stage, double f) { progress.report(f, 1.0, stage); });
}

/// The run asked for: the scene's settings, or the contract's choice (`target` set).
template <class SceneT>
SimulationResult runOrTarget(const SimulateArgs& args, SceneT& scene, const TradeProblem& problem,
                             std::optional<TargetOutcome>& target) {
  if (!(args.target_error > 0)) return simulateWithProgress(scene);
  target = runTarget(args, problem);
  SimulationResult r = std::move(target->result);
  target->result = {};
  scene.simulation.integrator = r.integrator;
  scene.simulation.accuracy = r.accuracy;
  return r;
}

/// run.json: what a run was made from, so that `render --history` can rebuild its model.
nlohmann::ordered_json runRecord(const SimulateArgs& args, const std::string& source, const SimulationSpec& spec,
                                 int segments) {
  nlohmann::ordered_json j;
  j["scene_source"] = source;
  j["scene_copy"] = "scene.yaml";
  j["overrides"] = args.sets;  // --set KEY=VALUE, applied to scene.yaml
  j["segments_override"] = segments;  // 0: the scene's own
  j["no_gravity"] = args.no_gravity;
  j["integrator"] = spec.integrator;
  j["accuracy"] = spec.accuracy;
  j["duration_s"] = spec.duration;
  j["sample_rate_hz"] = spec.sample_rate_hz;
  return j;
}

int report(const SimulateArgs& args, const std::string& name, const std::string& source, const SimulationResult& r,
           std::vector<std::string> warnings, double size_m, OutputDir* out, const std::string& scene_text,
           const SimulationSpec& spec, const std::optional<TargetOutcome>& target) {
  for (const auto& w : simulationWarnings(r, size_m)) warnings.push_back(w);
  nlohmann::ordered_json summary = simulationJson(r, warnings);
  int segments = args.segments;
  if (target) {
    summary["target_error"] = targetJson(*target);
    if (target->attempts.back().segments) segments = target->attempts.back().segments;
  }
  checkResultFinite(summary);  // before anything is committed: no NaN reaches a file either
  if (out) {
    out->write("history.csv", simulationHistoryCsv(r.record));
    out->write("summary.json", summary.dump(2) + "\n");
    out->write("scene.yaml", scene_text);
    out->write("run.json", runRecord(args, source, spec, segments).dump(2) + "\n");
    if (!r.states.rows.empty()) out->write("states.csv", simulationHistoryCsv(r.states));
    writeSimulationPlots(*out, r, name + strf(" (%s at %g)", r.integrator.c_str(), r.accuracy));
    out->commit();  // reported as written when the command succeeds
  }
  args.json ? emitResult(summary)
            : emitResult(simulationText(name, source, r, warnings) + (target ? "\n" + targetText(*target) : std::string()));
  return kOk;
}

}  // namespace

int runSimulateCommand(const SimulateArgs& args) {
  return guarded([&] {
    Scene loaded = loadScene(args);
    std::unique_ptr<OutputDir> out;
    if (auto* h = std::get_if<HamsasScene>(&loaded)) {
      applyOverrides(args, h->simulation);
      if (!args.out.empty()) out = std::make_unique<OutputDir>(args.out, args.force);
      std::optional<TargetOutcome> target;
      SimulationResult r = runOrTarget(args, *h, hamsasTradeProblem(*h), target);
      verify(args, *h, r);
      return report(args, h->name, h->source, r, {}, 0.0, out.get(), h->text, h->simulation, target);
    }
    ArticleScene& scene = std::get<ArticleScene>(loaded);
    applyOverrides(args, scene.simulation);
    std::vector<std::string> warnings = checkTableProgram(scene);
    for (const auto& w : warnings) std::cerr << "mmvlab: warning: " << w << '\n';
    if (!args.out.empty()) out = std::make_unique<OutputDir>(args.out, args.force);
    SimulationResult r;
    std::optional<TargetOutcome> target;
    try {
      r = runOrTarget(args, scene, articleTradeProblem(scene), target);
    } catch (const std::invalid_argument& e) {  // a facility model refused its command
      throw SceneError(scene.positions.where("base") + ": " + e.what());
    }
    warnings.insert(warnings.end(), r.warnings.begin(), r.warnings.end());
    for (const auto& w : r.warnings) std::cerr << "mmvlab: warning: " << w << '\n';
    verify(args, scene, r);
    double size = 0;
    for (const auto& l : scene.article.links) size += l.length;
    return report(args, scene.name, scene.source, r, warnings, size, out.get(), scene.text, scene.simulation, target);
  });
}

}  // namespace mmv::cli
