// mmvlab frf and mmvlab rom: linear models for control design (app::runLinearStudy; the
// isolator's: hamsas_command.cpp), written as CSV, Bode plots, UFF and .mat.
#include <cmath>
#include <algorithm>
#include <complex>
#include <iostream>

#include "facility/table_programs.hpp"
#include "sim/app/linear_study.hpp"
#include "sim/cli/commands.hpp"
#include "sim/cli/figures.hpp"
#include "sim/core/text.hpp"
#include "sim/io/linear_report.hpp"
#include "sim/io/mat_file.hpp"
#include "sim/io/output_dir.hpp"

namespace mmv::cli {

app::LinearRequest linearRequest(const LinearArgs& args) {
  app::LinearRequest r;
  r.inputs = args.inputs;
  r.outputs = args.outputs;
  r.f_min = args.f_min;
  r.f_max = args.f_max;
  r.range_given = args.range_given;
  r.points = args.points;
  r.rom_modes = args.rom_modes;
  if (!args.band.empty()) r.band = parseBand(args.band);
  r.residualize = !args.no_residualize;
  r.damping_ratio = args.damping_ratio;
  r.damping_given = args.damping_given;
  r.rom_target = args.rom_target;
  r.target_error = args.target_error;
  r.time_budget = args.time_budget;
  r.segments_given = args.segments.has_value();
  if (!args.vary.empty()) r.vary = args.vary.front();
  return r;
}

namespace {

/// The CSV of every input-output pair, full and reduced, and frf.uff.
void writeFrfFiles(const app::LinearStudy& a, OutputDir& out) {
  const StateSpace& s = a.lm.full;
  std::vector<Eigen::MatrixXcd> hr;
  for (double x : a.w) hr.push_back(a.red.model.response(x));
  for (Eigen::Index o = 0; o < s.C.rows(); ++o)
    for (Eigen::Index i = 0; i < s.B.cols(); ++i)
      out.write("frf_" + bodeFileBase(s, o, i) + ".csv", frfCsv(s, o, i, a.f, a.hf, hr));
  out.write("frf.uff", frfUff(a.lm, a.geometry, a.scene, a.f, a.hf));
}

}  // namespace

std::string bodeFileBase(const StateSpace& s, Eigen::Index output, Eigen::Index input) {
  return safeFileName(s.output_names[output]) + "__" + safeFileName(s.input_names[input]);
}

void writeBodePlots(const FigurePath& out, const app::LinearStudy& a, bool rad) {
  const StateSpace& s = a.lm.full;
  const ReducedModel& red = a.red;
  std::vector<Eigen::MatrixXcd> hr;
  for (double x : a.w) hr.push_back(red.model.response(x));
  std::vector<double> markers;  // the kept modes, on the plot's frequency axis
  for (double fk : red.kept_frequencies_hz) markers.push_back(rad ? 2 * M_PI * fk : fk);
  for (Eigen::Index o = 0; o < s.C.rows(); ++o)
    for (Eigen::Index i = 0; i < s.B.cols(); ++i) {
      render::BodeTrace full{"full model (" + std::to_string(s.numStates()) + " states)"}, rom{
          "reduced (" + std::to_string(red.model.numStates()) + " states)"};
      rom.dashed = true;
      for (std::size_t k = 0; k < a.f.size(); ++k) {
        const std::complex<double> h = a.hf[k](o, i), b = hr[k](o, i);
        const double x = rad ? a.w[k] : a.f[k];
        full.frequency.push_back(x);
        full.magnitude_db.push_back(20 * std::log10(std::abs(h) + 1e-300));
        full.phase_deg.push_back(std::arg(h) * 180 / M_PI);
        rom.frequency.push_back(x);
        rom.magnitude_db.push_back(20 * std::log10(std::abs(b) + 1e-300));
        rom.phase_deg.push_back(std::arg(b) * 180 / M_PI);
      }
      std::vector<render::BodeTrace> traces{full, rom};
      // The table cannot drive the article above its servo bandwidth: the response there is
      // the model's, not a test's (issue 36: the Bode plots did not show the limit).
      if (s.input_names[i].rfind("table_", 0) == 0 && !full.magnitude_db.empty()) {
        const double f = facility::TableSpec{}.bandwidth_hz, x = rad ? 2 * M_PI * f : f;
        const auto [mlo, mhi] = std::minmax_element(full.magnitude_db.begin(), full.magnitude_db.end());
        // On the magnitude panel only (NaN: no line on the phase panel's unwrapped scale).
        // A dB beyond the response both ways: a flat one (rigid translation, 0 dB) still shows it.
        render::BodeTrace limit{strf("table bandwidth %g Hz", f), {x, x}, {*mlo - 1, *mhi + 1}, {NAN, NAN}};
        limit.dashed = true;
        traces.push_back(limit);
      }
      try {
        figures::bode(out("bode_" + bodeFileBase(s, o, i) + ".png"), traces,
                      s.output_names[o] + " / " + s.input_names[i] + " (" + s.output_units[o] + " per " + s.input_units[i] +
                          "): " + a.scene.name,
                      rad ? "frequency (rad/s)" : "frequency (Hz)", markers);
      } catch (const std::runtime_error& e) {
        throw OutputError(e.what());
      }
    }
}

int runFrfCommand(const LinearArgs& args) {
  return guarded([&]() -> int {
    const Scene loaded = loadScene(args);
    const app::LinearRequest request = linearRequest(args);
    if (const auto* h = std::get_if<HamsasScene>(&loaded)) return runHamsasFrf(args, *h);
    std::unique_ptr<OutputDir> out;
    if (!args.out.empty()) out = std::make_unique<OutputDir>(args.out, args.force);
    const app::LinearStudy a = app::runLinearStudy(std::get<ArticleScene>(loaded), request);
    if (out) {
      writeFrfFiles(a, *out);
      writeBodePlots([&](const std::string& name) { return out->stage(name); }, a, args.rad);
    }
    const std::string text = args.json ? "" : a.summaryText();
    const nlohmann::ordered_json json = args.json ? a.frfJson() : nlohmann::ordered_json();
    if (out) {
      args.json ? checkResultFinite(json) : checkResultFinite(text);  // before any file is committed
      out->commit();  // reported as written when the command succeeds
    }
    args.json ? emitResult(json) : emitResult(text);
    return kOk;
  });
}

int runRomCommand(const LinearArgs& args) {
  return guarded([&]() -> int {
    if (args.out.empty()) throw UsageError("rom: --out DIR is required (it writes rom.mat and full.mat)");
    const Scene loaded = loadScene(args);
    const app::LinearRequest request = linearRequest(args);
    if (const auto* h = std::get_if<HamsasScene>(&loaded)) return runHamsasRom(args, *h);
    OutputDir out(args.out, args.force);
    const app::LinearStudy a = app::runLinearStudy(std::get<ArticleScene>(loaded), request);
    try {
      const std::string rom_path = out.stage("rom.mat"), full_path = out.stage("full.mat");
      writeStateSpaceMats(rom_path, a.red.model, full_path, a.lm.full);
    } catch (const std::runtime_error& e) {
      throw OutputError(e.what());
    }
    const nlohmann::ordered_json rom_json = a.romJson();
    checkResultFinite(rom_json);  // before any file is committed
    out.write("rom.json", rom_json.dump(2) + "\n");
    // The text for stdout is made before --out is committed: nothing long runs after it.
    const std::string text = args.json ? "" : a.summaryText();
    out.commit();  // reported as written when the command succeeds
    args.json ? emitResult(rom_json) : emitResult(text);
    return kOk;
  });
}

}  // namespace mmv::cli
