// mmvlab correlate: a measured modal test (UFF 58 FRFs, 55 mode shapes, 15/2411 nodes)
// against the scene's model (sim/linear/correlation.hpp).
#include <cmath>
#include <iostream>
#include <optional>

#include "sim/app/correlate_study.hpp"
#include "sim/cli/commands.hpp"
#include "sim/cli/figures.hpp"
#include "sim/core/text.hpp"
#include "sim/io/correlation_report.hpp"
#include "sim/io/linear_report.hpp"
#include "sim/io/output_dir.hpp"

namespace mmv::cli {
namespace {

void writeFigures(const CorrelationResult& r, const ArticleScene& scene, OutputDir& out) {
  std::vector<std::string> rows, cols;
  for (std::size_t i = 0; i < r.test_modes.size(); ++i) rows.push_back(modeLabel('T', static_cast<int>(i + 1), r.test_modes[i].frequency_hz));
  for (const auto& m : r.model_modes) cols.push_back(modeLabel('M', m.number.number(), m.frequency_hz));
  std::vector<double> model_hz;
  for (const auto& m : r.model_modes)
    if (m.stable && !m.rigid_body) model_hz.push_back(m.frequency_hz);
  if (r.mac.size() > 0)
    figures::heatmap(out.stage("mac.png"), r.mac, rows, cols, "MAC, test against model: " + scene.name, "test mode",
                     "model mode");
  for (const auto& f : r.frfs) {
    if (!f.skipped.empty()) continue;
    render::BodeTrace test{"test (function " + std::to_string(f.index + 1) + ")"}, model{"model"};
    model.dashed = true;
    for (std::size_t k = 0; k < f.frequency_hz.size(); ++k) {
      for (auto* t : {&test, &model}) t->frequency.push_back(f.frequency_hz[k]);
      test.magnitude_db.push_back(20 * std::log10(std::abs(f.test[k]) + 1e-300));
      test.phase_deg.push_back(std::arg(f.test[k]) * 180 / M_PI);
      model.magnitude_db.push_back(20 * std::log10(std::abs(f.model[k]) + 1e-300));
      model.phase_deg.push_back(std::arg(f.model[k]) * 180 / M_PI);
    }
    const std::string name = strf("frf_%02d_", f.index + 1) + safeFileName(f.output) + "__" + safeFileName(f.input);
    figures::bode(out.stage(name + ".png"), {test, model},
                  strf("%s / %s: FRAC %.3f (%s)", f.output.c_str(), f.input.c_str(), f.frac, scene.name.c_str()),
                  "frequency (Hz)", model_hz);
  }
}

}  // namespace

int runCorrelateCommand(const CorrelateArgs& args) {
  return guarded([&] {
    const Scene scene = loadScene(args);
    app::CorrelateRequest r;
    r.measured = args.measured;
    r.tam = args.tam;
    r.pair_distance_m = args.pair_distance;
    r.pairs = args.pairs;
    r.modes = args.modes;
    r.mac_threshold = args.mac_threshold;
    r.max_frequency_error = args.max_frequency_error;
    if (args.damping_given) r.damping_ratio = args.damping_ratio;
    std::optional<OutputDir> out;  // lives until stdout has the result: a failure there puts --out back
    if (!args.out.empty()) out.emplace(args.out, args.force);  // a bad --out refused before the work
    const app::CorrelateStudy s = app::runCorrelateStudy(scene, r);
    if (out) {
      out->write("correlation.json", s.json.dump(2) + "\n");
      out->write("mac.csv", s.mac_csv);
      out->write("pairs.csv", s.pairs_csv);
      try {
        writeFigures(s.result, app::articleOf(scene, "correlate"), *out);
      } catch (const std::runtime_error& e) {
        throw OutputError(e.what());
      }
      out->commit();  // reported as written when the command succeeds
    }
    args.json ? emitResult(s.json) : emitResult(s.text);
    return kOk;
  });
}

}  // namespace mmv::cli
