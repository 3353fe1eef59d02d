// mmvlab modes and converge: the system modes about the held equilibrium
// (sim/modes/system_modes.hpp; the isolator's: sim/cli/hamsas_command.cpp) and their
// convergence with segments per link (sim/modes/converge.hpp).
#include <cmath>
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>

#include "sim/cli/commands.hpp"
#include "sim/cli/figures.hpp"
#include "sim/core/text.hpp"
#include "sim/io/output_dir.hpp"
#include "sim/io/report.hpp"
#include "sim/modes/converge.hpp"
#include "sim/modes/system_modes.hpp"
#include "sim/plan/check.hpp"

namespace mmv::cli {
namespace {

/// convergence.png: each mode's |f_N / Richardson - 1| against segments per link, log-log
/// (a straight line of slope -2 where the observed order is 2).
void convergencePlot(OutputDir& out, const ConvergenceStudy& c) {
  std::vector<render::Series> all;
  for (const auto& m : c.modes) {
    if (!m.has_estimate) continue;
    render::Series s{strf("mode %d (%.4g Hz, %s)", m.number, m.extrapolated_hz, m.check.c_str()), {}, {}};
    s.colour_index = (m.number - 1) % 13 + 1;
    for (std::size_t k = 0; k < c.runs.size() && k < m.frequency_hz.size(); ++k) {
      const double e = std::abs(m.frequency_hz[k] / m.extrapolated_hz - 1);
      if (std::isfinite(e) && e > 0) s.x.push_back(c.runs[k].segments), s.y.push_back(e);
    }
    all.push_back(s);
  }
  if (all.empty()) return;
  try {
    figures::linePlot(out.stage("convergence.png"), all, "Frequency error against segments per link: " + c.scene_name,
                      "segments per flexible link", "|f / Richardson - 1|", true, true);
  } catch (const std::runtime_error& e) {
    throw OutputError(e.what());
  }
}

}  // namespace

int runModesCommand(const ModesArgs& args) {
  return guarded([&]() -> int {
    const Scene loaded = loadScene(args);
    if (const auto* h = std::get_if<HamsasScene>(&loaded)) {
      if (args.target_error > 0 || args.time_budget > 0)
        throw UsageError("--target-error applies to the article's scenes (HAM-SAS has no segments)");
      return runHamsasModes(args, *h);
    }
    ArticleScene scene = std::get<ArticleScene>(loaded);
    std::optional<SegmentsChoice> choice;
    if (args.target_error > 0) {
      if (args.segments > 0) throw UsageError("--target-error chooses the segments per link: drop --segments");
      if (args.modes == 0) throw UsageError("--target-error holds the modes shown to it: give --modes N (N >= 1), not 0");
      if (args.no_error_estimate) throw UsageError("--target-error needs the error estimate: drop --no-error-estimate");
      choice = segmentsForTarget(scene, args.modes, args.target_error, kMaxTargetSegments, args.time_budget);
      overrideSegments(scene, choice->segments);
    } else if (args.time_budget > 0) {
      throw UsageError("--time-budget applies to --target-error only");
    }
    ModesOptions opt;
    opt.max_modes = args.modes;
    opt.with_shapes = true;  // the JSON on stdout and in --out is one object: shapes in both
    opt.points = checkedPoints(args.points, scene.article, "--points");
    opt.damping = scene.damping;
    ModesReport rep = runModes(scene, opt);
    if (!args.no_error_estimate) rep.discretization = estimateDiscretization(scene, rep);
    rep.segments_choice = choice;
    for (const auto& w : plausibilityWarnings(scene, rep)) rep.warnings.push_back("likely a unit mistake: " + w);
    const nlohmann::ordered_json json = modesToJson(rep);
    const std::string text = formatModesText(rep);
    std::optional<OutputDir> out;  // lives until stdout has the result: a failure there puts --out back
    if (!args.out.empty()) {
      out.emplace(args.out, args.force);
      checkResultFinite(json);  // before any file is committed
      checkResultFinite(text);
      out->write("modes.txt", text);
      out->write("modes.json", json.dump(2) + "\n");
      out->write("modes.csv", modesCsv(rep));
      out->commit();  // reported as written when the command succeeds
    }
    args.json ? emitResult(json) : emitResult(text);
    return kOk;
  });
}

int runConvergeCommand(const ConvergeArgs& args) {
  return guarded([&] {
    const ArticleScene scene = loadArticleScene(args, "converge");
    std::unique_ptr<OutputDir> out;
    if (!args.out.empty()) out = std::make_unique<OutputDir>(args.out, args.force);
    const ConvergenceStudy c = runConvergence(scene, args.max_segments, args.modes);
    const nlohmann::ordered_json json = convergenceToJson(c);
    const std::string text = formatConvergenceText(c);
    if (out) {
      checkResultFinite(json);  // before any file is committed
      checkResultFinite(text);
      out->write("converge.txt", text);
      out->write("converge.json", json.dump(2) + "\n");
      out->write("converge.csv", convergenceCsv(c));
      convergencePlot(*out, c);
      out->commit();  // reported as written when the command succeeds
    }
    args.json ? emitResult(json) : emitResult(text);
    return kOk;
  });
}

}  // namespace mmv::cli
