#include "sim/app/hamsas_linear_study.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "sim/core/text.hpp"
#include "sim/hamsas/spatial_linear.hpp"
#include "sim/io/hamsas_report.hpp"

namespace mmv::app {
namespace {

/// What frf and rom on the isolator do not take, refused by name; returns the grid.
std::vector<double> checkedGrid(const LinearRequest& r, const std::string& verb, const std::string& what) {
  const std::vector<double> grid = checkLinearRequest(r);
  if (!r.inputs.empty() || !r.outputs.empty())
    throw UsageError(verb + " on a HAM-SAS scene " + what + "; " + optionName(r.front, "--input") + "/" +
                     optionName(r.front, "--output") + " do not apply");
  if (r.target_error > 0)
    throw UsageError(optionName(r.front, "--target-error") + " applies to the article's scenes (HAM-SAS has no segments)");
  return grid;
}

std::pair<std::string, std::vector<double>> parseVary(const std::string& text, Front front) {
  const std::string option = optionName(front, "--vary") + " " + text;
  const auto eq = text.find('=');
  if (eq == std::string::npos || eq == 0) throw UsageError(option + ": expected KEY=V1,V2,...");
  std::vector<double> values;
  std::stringstream ss(text.substr(eq + 1));
  for (std::string v; std::getline(ss, v, ',');) {
    const std::optional<double> x = finiteNumber(v);
    if (!x) throw UsageError(option + ": '" + v + "' is not a number");
    values.push_back(*x);
  }
  if (values.empty()) throw UsageError(option + ": no values");
  return {text.substr(0, eq), values};
}

}  // namespace

HamsasFrfStudy runHamsasFrfStudy(const HamsasScene& scene, const LinearRequest& r) {
  HamsasFrfStudy s;
  s.f = checkedGrid(r, "frf", "computes the 6 x 6 ground-to-optical-table transmissibility (the actuator-to-sensor "
                              "model is rom)");
  std::vector<double> vary_values;
  if (!r.vary.empty()) std::tie(s.vary_key, vary_values) = parseVary(r.vary, r.front);
  const HamsasModes h = analyseHamsas(scene.isolator);
  s.T = hamsasTransmissibility(h, s.f);
  s.T10 = spatialTransmissibility(h.model, h.lin, 2 * M_PI * 10.0);
  s.text = hamsasTransmissibilityText(scene, h, s.f, s.T, s.T10);
  s.json = hamsasTransmissibilityJson(scene, s.f, s.T, s.T10);
  if (!s.vary_key.empty()) {
    try {
      s.varied = varyHamsas(scene.isolator, s.vary_key, vary_values, s.f);
    } catch (const std::invalid_argument& e) {
      throw UsageError(optionName(r.front, "--vary") + " " + r.vary + ": " + e.what());
    }
    for (const HamsasParameter& p : hamsasParameters())
      if (s.vary_key == p.key) s.vary_unit = p.unit;
    s.text += hamsasVaryText(s.vary_key, s.varied);
    nlohmann::ordered_json v = nlohmann::ordered_json::array();
    for (const auto& p : s.varied)
      v.push_back({{"value", p.value}, {"x_at_10_hz_db", p.x_at_10hz_db}, {"z_at_10_hz_db", p.z_at_10hz_db}});
    s.json["varied"] = {{"key", s.vary_key}, {"unit", s.vary_unit}, {"points", v}};
  }
  s.csv = hamsasTransmissibilityCsv(s.f, s.T);
  checkResultFinite(s.json);
  return s;
}

HamsasRomStudy runHamsasRomStudy(const HamsasScene& scene, const LinearRequest& r) {
  HamsasRomStudy s;
  s.f = checkedGrid(r, "rom", "is the 8 x 8 model from the spring box's actuators to its sensors");
  const std::vector<double>& f = s.f;
  if (!r.vary.empty()) throw UsageError(optionName(r.front, "--vary") + " applies to frf on a HAM-SAS scene");
  const HamsasModes h = analyseHamsas(scene.isolator);
  s.full = hamsasControlModel(h);
  ReductionOptions options = reductionOptions(r);
  options.drop_unseen = true;
  s.red = reduceModal(s.full, options);
  std::vector<double> w(f);
  for (double& x : w) x *= 2 * M_PI;
  s.err = compareResponses(s.full, s.red.model, w);
  s.json = hamsasRomJson(s.full, s.red, s.err, f);
  s.text = hamsasRomText(scene, h, s.full, s.red, s.err, f);
  checkResultFinite(s.json);
  return s;
}

}  // namespace mmv::app
