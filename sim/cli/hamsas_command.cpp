// mmvlab modes / frf / rom on a HAM-SAS isolator scene (sim/hamsas/), written by
// sim/io/hamsas_report.hpp; the figures by renders/.
#include <fstream>
#include <iostream>
#include <sstream>

#include "sim/cli/figures.hpp"
#include "sim/cli/commands.hpp"
#include "sim/core/text.hpp"
#include "sim/hamsas/hamsas_modes.hpp"
#include "sim/io/hamsas_report.hpp"
#include "sim/io/mat_file.hpp"
#include "sim/io/output_dir.hpp"

namespace mmv::cli {
namespace {

std::pair<std::string, std::vector<double>> parseVary(const std::string& text) {
  const auto eq = text.find('=');
  if (eq == std::string::npos || eq == 0) throw UsageError("--vary " + text + ": expected KEY=V1,V2,...");
  std::vector<double> values;
  std::stringstream ss(text.substr(eq + 1));
  for (std::string v; std::getline(ss, v, ',');) {
    char* end = nullptr;
    const double x = std::strtod(v.c_str(), &end);
    if (v.empty() || *end || !std::isfinite(x)) throw UsageError("--vary " + text + ": '" + v + "' is not a number");
    values.push_back(x);
  }
  if (values.empty()) throw UsageError("--vary " + text + ": no values");
  return {text.substr(0, eq), values};
}

/// The transmissibility figures: horizontal, vertical, angular, the 10 Hz heat map and
/// the varied parameter's curves.
void writeTransmissibilityPlots(OutputDir& out, const std::string& name, const std::vector<double>& f,
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
    figures::linePlot(out.stage("transmissibility_horizontal.png"), {series(0, 0, "m/m", false), series(1, 1, "m/m", true)},
                      name + ": horizontal transmissibility (table / ground)", "frequency (Hz)", "magnitude (dB of m/m)",
                      false, true);
    figures::linePlot(out.stage("transmissibility_tilt_to_horizontal.png"),
                      {series(0, 4, "m/rad", false), series(1, 3, "m/rad", true)},
                      name + ": ground tilt to table translation", "frequency (Hz)", "magnitude (dB of m/rad)", false, true);
    figures::linePlot(out.stage("transmissibility_vertical.png"), {series(2, 2, "m/m", false)},
                      name + ": vertical transmissibility (table / ground)", "frequency (Hz)", "magnitude (dB of m/m)",
                      false, true);
    figures::linePlot(out.stage("transmissibility_angular.png"),
                      {series(3, 3, "rad/rad", false), series(4, 4, "rad/rad", true), series(5, 5, "rad/rad", false)},
                      name + ": angular transmissibility (table / ground)", "frequency (Hz)", "magnitude (dB of rad/rad)",
                      false, true);
    Eigen::MatrixXd heat(6, 6);
    for (int i = 0; i < 6; ++i)
      for (int j = 0; j < 6; ++j) heat(i, j) = std::max(decibels(T10(i, j)), -250.0);  // zero by symmetry: the floor
    std::vector<std::string> names;
    for (int k = 0; k < 6; ++k) names.push_back(hamsasDofName(k));
    figures::heatmap(out.stage("transmissibility_10hz.png"), heat, names, names,
                     name + ": |T| at 10 Hz (dB of m/m, m/rad, rad/m or rad/rad; floor -250)", "optical table",
                     "ground", -250, 0);
    if (!varied.empty()) {
      std::vector<render::Series> curves;
      for (const auto& p : varied) curves.push_back({strf("%g", p.value) + vary_unit, f, p.x_db});
      figures::linePlot(out.stage("transmissibility_vary.png"), curves, name + ": x transmissibility vs " + vary_key,
                               "frequency (Hz)", "magnitude (dB)", false, true);
    }
  } catch (const std::runtime_error& e) {
    throw OutputError(e.what());
  }
}

}  // namespace

int runHamsasFrf(const LinearArgs& args, const HamsasScene& scene, const std::vector<double>& f) {
  if (!args.inputs.empty() || !args.outputs.empty())
    throw UsageError("frf on a HAM-SAS scene computes the 6 x 6 ground-to-optical-table transmissibility; "
                     "--input/--output do not apply (the actuator-to-sensor model is `mmvlab rom`)");
  if (args.vary.size() > 1) throw UsageError("--vary: give one parameter");
  std::string vary_key, vary_unit;
  std::vector<double> vary_values;
  if (!args.vary.empty()) std::tie(vary_key, vary_values) = parseVary(args.vary.front());
  std::unique_ptr<OutputDir> out;
  if (!args.out.empty()) out = std::make_unique<OutputDir>(args.out, args.force);
  const HamsasModes h = analyseHamsas(scene.isolator);
  const std::vector<Eigen::MatrixXcd> T = hamsasTransmissibility(h, f);
  const Eigen::MatrixXcd T10 = spatialTransmissibility(h.model, h.lin, 2 * M_PI * 10.0);
  std::string text = hamsasTransmissibilityText(scene, h, f, T, T10);
  std::vector<HamsasVaryPoint> varied;
  if (!vary_key.empty()) {
    try {
      varied = varyHamsas(scene.isolator, vary_key, vary_values, f);
    } catch (const std::invalid_argument& e) {
      throw UsageError("--vary " + args.vary.front() + ": " + e.what());
    }
    for (const HamsasParameter& p : hamsasParameters())
      if (vary_key == p.key) vary_unit = p.unit;
    text += hamsasVaryText(vary_key, varied);
  }
  if (out) {
    out->write("transmissibility.csv", hamsasTransmissibilityCsv(f, T));
    writeTransmissibilityPlots(*out, scene.name, f, T, T10, vary_key, varied, vary_unit);
    out->commit();  // reported as written when the command succeeds
  }
  if (args.json) {
    nlohmann::ordered_json j = hamsasTransmissibilityJson(scene, f, T, T10);
    if (!varied.empty()) {
      nlohmann::ordered_json v = nlohmann::ordered_json::array();
      for (const auto& p : varied) v.push_back({{"value", p.value}, {"x_at_10_hz_db", p.x_at_10hz_db}, {"z_at_10_hz_db", p.z_at_10hz_db}});
      j["varied"] = {{"key", vary_key}, {"unit", vary_unit}, {"points", v}};
    }
    emitResult(j);
  } else {
    emitResult(text);
  }
  return kOk;
}

int runHamsasRom(const LinearArgs& args, const HamsasScene& scene, const std::vector<double>& f) {
  if (!args.inputs.empty() || !args.outputs.empty())
    throw UsageError("rom on a HAM-SAS scene is the 8 x 8 model from the spring box's actuators to its sensors; "
                     "--input/--output do not apply");
  OutputDir out(args.out, args.force);
  const HamsasModes h = analyseHamsas(scene.isolator);
  const StateSpace full = hamsasControlModel(h);
  ReductionOptions options = app::reductionOptions(linearRequest(args));
  options.drop_unseen = true;
  const ReducedModel red = reduceModal(full, options);
  std::vector<double> w(f);
  for (double& x : w) x *= 2 * M_PI;
  const ModelError err = compareResponses(full, red.model, w);
  try {
    writeStateSpaceMat(out.stage("rom.mat"), red.model);
    writeStateSpaceMat(out.stage("full.mat"), full);
  } catch (const std::runtime_error& e) {
    throw OutputError(e.what());
  }
  const nlohmann::ordered_json rom_json = hamsasRomJson(full, red, err, f);
  out.write("rom.json", rom_json.dump(2) + "\n");
  out.commit();  // reported as written when the command succeeds
  args.json ? emitResult(rom_json) : emitResult(hamsasRomText(scene, h, full, red, err, f));
  return kOk;
}

}  // namespace mmv::cli
