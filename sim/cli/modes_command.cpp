// mmvlab modes and converge: the system modes about the held equilibrium
// (sim/modes/system_modes.hpp; the isolator's: sim/cli/hamsas_command.cpp) and their
// convergence with segments per link (sim/modes/converge.hpp).
#include <cmath>
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>

#include "sim/app/component_studies.hpp"
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
    render::Series s{strf("mode %d (%.4g Hz, %s)", m.number.number(), m.extrapolated_hz, m.check.c_str()), {}, {}};
    s.colour_index = m.number.index() % 13 + 1;
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
    const Scene scene = loadScene(args);
    auto r = declaredRequest<app::ModesRequest>(args);
    r.segments_given = args.segments.has_value();
    std::optional<OutputDir> out;  // lives until stdout has the result: a failure there puts --out back
    if (!args.out.empty()) out.emplace(args.out, args.force);  // a bad --out refused before the work
    const app::ModesStudy s = app::runModesStudy(scene, r);
    if (out) {
      out->write("modes.txt", s.text);
      out->write("modes.json", s.json.dump(2) + "\n");
      if (!s.csv.empty()) out->write("modes.csv", s.csv);
      if (!s.vtp.empty()) out->write("modes.vtp", s.vtp);
      out->commit();  // reported as written when the command succeeds
    }
    args.json ? emitResult(s.json) : emitResult(s.text);
    return kOk;
  });
}

int runConvergeCommand(const ConvergeArgs& args) {
  return guarded([&] {
    const Scene scene = loadScene(args);
    const auto r = declaredRequest<app::ConvergeRequest>(args);
    std::unique_ptr<OutputDir> out;
    if (!args.out.empty()) out = std::make_unique<OutputDir>(args.out, args.force);
    const app::ConvergeStudy s = app::runConvergeStudy(scene, r);
    if (out) {
      out->write("converge.txt", s.text);
      out->write("converge.json", s.json.dump(2) + "\n");
      out->write("converge.csv", s.csv);
      convergencePlot(*out, s.study);
      out->commit();  // reported as written when the command succeeds
    }
    args.json ? emitResult(s.json) : emitResult(s.text);
    return kOk;
  });
}

}  // namespace mmv::cli
