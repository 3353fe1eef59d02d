// mmvlab modes and converge: the system modes about the held equilibrium
// (sim/modes/system_modes.hpp; the isolator's: sim/cli/hamsas_command.cpp) and their
// convergence with segments per link (sim/modes/converge.hpp).
#include <iostream>

#include "sim/cli/commands.hpp"
#include "sim/io/report.hpp"
#include "sim/modes/converge.hpp"
#include "sim/modes/system_modes.hpp"
#include "sim/plan/check.hpp"

namespace mmv::cli {

int runModesCommand(const ModesArgs& args) {
  return guarded([&]() -> int {
    const Scene loaded = loadScene(args);
    if (const auto* h = std::get_if<HamsasScene>(&loaded)) return runHamsasModes(args, *h);
    const ArticleScene& scene = std::get<ArticleScene>(loaded);
    ModesOptions opt;
    opt.max_modes = args.modes;
    opt.with_shapes = args.json;
    opt.points = checkedPoints(args.points, scene.article, "--points");
    opt.damping = scene.damping;
    ModesReport rep = runModes(scene, opt);
    if (!args.no_error_estimate) rep.discretization = estimateDiscretization(scene, reportFrequencies(rep));
    for (const auto& w : plausibilityWarnings(scene, rep)) rep.warnings.push_back("likely a unit mistake: " + w);
    args.json ? emitResult(modesToJson(rep)) : emitResult(formatModesText(rep));
    return kOk;
  });
}

int runConvergeCommand(const ConvergeArgs& args) {
  return guarded([&] {
    const ArticleScene scene = loadArticleScene(args, "converge");
    const ConvergenceStudy c = runConvergence(scene, args.max_segments, args.modes);
    args.json ? emitResult(convergenceToJson(c)) : emitResult(formatConvergenceText(c));
    return kOk;
  });
}

}  // namespace mmv::cli
