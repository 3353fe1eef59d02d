// mmvlab modes / frf / rom on a HAM-SAS isolator scene (sim/hamsas/), written by
// sim/io/hamsas_report.hpp; the figures by renders/.
#include <fstream>
#include <iostream>
#include <optional>

#include "sim/app/hamsas_linear_study.hpp"
#include "sim/cli/figures.hpp"
#include "sim/cli/commands.hpp"
#include "sim/core/text.hpp"
#include "sim/hamsas/hamsas_modes.hpp"
#include "sim/io/hamsas_report.hpp"
#include "sim/io/mat_file.hpp"
#include "sim/io/output_dir.hpp"

namespace mmv::cli {

void writeTransmissibilityPlots(const FigurePath& out, const std::string& name, const std::vector<double>& f,
                                const std::vector<Eigen::MatrixXcd>& T, const Eigen::MatrixXcd& T10,
                                const std::string& vary_key, const std::vector<HamsasVaryPoint>& varied,
                                const std::string& vary_unit) {
  // Each curve in its unit (m/m between translations, m/rad from a ground rotation to a
  // translation, rad/rad between rotations); one unit per figure. A DOF keeps its colour
  // and the second curve of a pair is dashed, so neither hides the other.
  auto series = [&](int i, int j, const char* unit, bool dashed) {
    render::Series s{std::string(hamsasDofName(i)) + " <- ground " + hamsasDofName(j) + " (" + unit + ")", f, {}};
    for (const auto& Tk : T) s.y.push_back(decibels(Tk(i, j)));
    s.dashed = dashed;
    s.colour_index = i + 1;
    return s;
  };
  try {
    figures::linePlot(out("transmissibility_horizontal.png"), {series(0, 0, "m/m", false), series(1, 1, "m/m", true)},
                      name + ": horizontal transmissibility (table / ground)", "frequency (Hz)", "magnitude (dB of m/m)",
                      false, true);
    figures::linePlot(out("transmissibility_tilt_to_horizontal.png"),
                      {series(0, 4, "m/rad", false), series(1, 3, "m/rad", true)},
                      name + ": ground tilt to table translation", "frequency (Hz)", "magnitude (dB of m/rad)", false, true);
    figures::linePlot(out("transmissibility_vertical.png"), {series(2, 2, "m/m", false)},
                      name + ": vertical transmissibility (table / ground)", "frequency (Hz)", "magnitude (dB of m/m)",
                      false, true);
    figures::linePlot(out("transmissibility_angular.png"),
                      {series(3, 3, "rad/rad", false), series(4, 4, "rad/rad", true), series(5, 5, "rad/rad", false)},
                      name + ": angular transmissibility (table / ground)", "frequency (Hz)", "magnitude (dB of rad/rad)",
                      false, true);
    Eigen::MatrixXd heat(6, 6);
    for (int i = 0; i < 6; ++i)
      for (int j = 0; j < 6; ++j) heat(i, j) = std::max(decibels(T10(i, j)), -250.0);  // zero by symmetry: the floor
    std::vector<std::string> names;
    for (int k = 0; k < 6; ++k) names.push_back(hamsasDofName(k));
    figures::heatmap(out("transmissibility_10hz.png"), heat, names, names,
                     name + ": |T| at 10 Hz (dB of m/m, m/rad, rad/m or rad/rad; floor -250)", "optical table",
                     "ground", -250, 0);
    if (!varied.empty()) {
      std::vector<render::Series> curves;
      for (const auto& p : varied) curves.push_back({strf("%g", p.value) + vary_unit, f, p.x_db});
      figures::linePlot(out("transmissibility_vary.png"), curves, name + ": x transmissibility vs " + vary_key,
                               "frequency (Hz)", "magnitude (dB)", false, true);
    }
  } catch (const std::runtime_error& e) {
    throw OutputError(e.what());
  }
}

int runHamsasFrf(const LinearArgs& args, const HamsasScene& scene) {
  if (args.vary.size() > 1) throw UsageError("--vary: give one parameter");
  const app::LinearRequest r = linearRequest(args);
  std::optional<OutputDir> out;  // lives until stdout has the result: a failure there puts --out back
  if (!args.out.empty()) out.emplace(args.out, args.force);  // a bad --out refused before the work
  const app::HamsasFrfStudy s = app::runHamsasFrfStudy(scene, r);
  if (out) {
    out->write("transmissibility.csv", s.csv);
    writeTransmissibilityPlots([&](const std::string& name) { return out->stage(name); }, scene.name, s.f, s.T, s.T10,
                               s.vary_key, s.varied, s.vary_unit);
    out->commit();  // reported as written when the command succeeds
  }
  args.json ? emitResult(s.json) : emitResult(s.text);
  return kOk;
}

int runHamsasRom(const LinearArgs& args, const HamsasScene& scene) {
  OutputDir out(args.out, args.force);
  const app::HamsasRomStudy s = app::runHamsasRomStudy(scene, linearRequest(args));
  try {
    const std::string rom_path = out.stage("rom.mat"), full_path = out.stage("full.mat");
    writeStateSpaceMats(rom_path, s.red.model, full_path, s.full);
  } catch (const std::runtime_error& e) {
    throw OutputError(e.what());
  }
  out.write("rom.json", s.json.dump(2) + "\n");
  out.commit();  // reported as written when the command succeeds
  args.json ? emitResult(s.json) : emitResult(s.text);
  return kOk;
}

}  // namespace mmv::cli
