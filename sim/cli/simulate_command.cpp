// mmvlab simulate: a time run of the scene (sim/time/simulation.hpp; the isolator's:
// sim/hamsas/hamsas_simulation.hpp), written by sim/io/simulation_report.hpp.

#include <cstdio>
#include <fstream>
#include <iostream>
#include <optional>

#include "facility/table_programs.hpp"
#include "sim/app/simulate_study.hpp"
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

}  // namespace

int runSimulateCommand(const SimulateArgs& args) {
  return guarded([&] {
    const Scene loaded = loadScene(args);
    std::unique_ptr<OutputDir> out;
    if (!args.out.empty()) out = std::make_unique<OutputDir>(args.out, args.force);
    // Warnings as soon as they are known; each run's progress line on stderr.
    std::unique_ptr<Progress> bar;
    std::string bar_what;
    app::SimulateHooks hooks;
    hooks.warn = [](const std::string& w) { std::cerr << "mmvlab: warning: " << w << '\n'; };
    hooks.progress = [&](const std::string& what, double done, double total, const std::string& detail) {
      if (what != bar_what) bar.reset(), bar = std::make_unique<Progress>(what), bar_what = what;
      bar->report(done, total, detail);
    };
    const app::SimulateStudy s = app::runSimulateStudy(loaded, declaredRequest<app::SimulateRequest>(args), hooks);
    bar.reset();  // the progress line ends before the run's report is written
    if (out) {
      const SimulationResult& r = s.result;
      out->write("history.csv", simulationHistoryCsv(r.record));
      out->write("summary.json", s.summary.dump(2) + "\n");
      out->write("scene.yaml", sceneText(loaded));
      out->write("run.json", runRecord(args, sceneSource(loaded), s.spec, s.segments_chosen ? s.segments_chosen : args.segments.value_or(0))
                                 .dump(2) + "\n");
      if (!r.states.rows.empty()) out->write("states.csv", simulationHistoryCsv(r.states));
      writeSimulationPlots(*out, r, sceneName(loaded) + strf(" (%s at %g)", r.integrator.c_str(), r.accuracy));
      out->commit();  // reported as written when the command succeeds
    }
    args.json ? emitResult(s.summary) : emitResult(s.text);
    return kOk;
  });
}

}  // namespace mmv::cli
