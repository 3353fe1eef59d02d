// mmvlab report's HAM-SAS tables (sim/io/review_report.hpp), made from `modes --json` and
// `frf --json` of an isolator scene, so the page and those commands cannot disagree.
#include <cmath>
#include <string>

#include "sim/core/text.hpp"
#include "sim/io/review_report.hpp"

namespace mmv {

html::Table hamsasFeatureTable(const ReviewJson& modes) {
  html::Table t;
  t.header = {"feature (LASTI, in vacuum)", "measured (Hz)", "model (Hz)", "error (%)", "mode", "shape match", "identified as"};
  for (const auto& f : modes.at("features")) {
    const ReviewJson& model = f.at("model_hz");
    const double measured = f.at("measured_hz").get<double>();
    const bool shown = model.is_number();
    t.rows.push_back({reportText(f.at("feature")), reportNumber(f.at("measured_hz")), shown ? reportNumber(model) : "none",
                      shown ? strf("%+.2f", 100 * (model.get<double>() / measured - 1)) : "-", reportText(f.at("mode")),
                      strf("%.3f", f.at("shape_match").get<double>()), reportText(f.at("rule"))});
    t.row_classes.push_back(shown ? "" : "warn");
  }
  return t;
}

namespace {

/// As `modes` prints its gravity_% column: "0.0" below 0.05 %, else signed to 0.1 %.
std::string gravityPercent(double ratio) { return std::abs(ratio) < 5e-4 ? std::string("0.0") : strf("%+.1f", 100 * ratio); }

}  // namespace

html::Table hamsasModeTable(const ReviewJson& modes) {
  html::Table t;
  t.header = {"mode", "frequency (Hz)", "most kinetic energy in", "kinetic energy mostly in", "strain energy mostly in",
              "gravity's work over the elastic energy (%)"};
  for (const auto& m : modes.at("modes")) {
    t.rows.push_back({reportText(m.at("mode")), reportNumber(m.at("frequency_hz")), reportText(m.at("label")),
                      reportLargestShare(m.at("kinetic_share")), reportLargestShare(m.at("strain_share")),
                      gravityPercent(m.at("preload_over_elastic").get<double>())});
    t.row_classes.push_back(m.value("stable", true) ? "" : "fail");
  }
  return t;
}

html::Table transmissibilityTable(const ReviewJson& frf) {
  const ReviewJson& f = frf.at("frequency_hz");
  const ReviewJson& at10 = frf.at("at_10_hz_db");
  html::Table t;
  t.header = {"optical table from ground", "unit", "peak (Hz)", "peak (dB)", "at 10 Hz (dB)", "goal above 10 Hz"};
  const ReviewJson& dofs = frf.at("dofs");
  for (std::size_t k = 0; k < dofs.size(); ++k) {
    const ReviewJson* pair = nullptr;
    for (const auto& p : frf.at("pairs"))
      if (p.at("table") == dofs[k] && p.at("ground") == dofs[k]) pair = &p;
    if (!pair) continue;
    const ReviewJson& db = pair->at("magnitude_db");
    std::size_t best = 0;
    for (std::size_t i = 0; i < db.size(); ++i)
      if (db[i].get<double>() > db[best].get<double>()) best = i;
    const double level = at10.at(k).at(k).get<double>();
    const std::string goal = k >= 3 ? "-" : level <= -80 ? "meets 80 dB" : level <= -70 ? "meets 70 dB" : "misses 70 dB";
    t.rows.push_back({reportText(dofs[k]) + " from " + reportText(dofs[k]), reportText(pair->at("unit")), reportNumber(f.at(best)),
                      reportNumber(db.at(best)), strf("%.1f", level), goal});
    t.row_classes.push_back(goal == "misses 70 dB" ? "fail" : goal == "-" ? "" : "pass");
  }
  return t;
}

std::vector<std::string> hamsasModesAccuracy(const ReviewJson& modes) {
  std::vector<std::string> out;
  out.push_back(strf("Rigid bodies and linear springs, linearized at the design configuration (%d coordinates, ",
                     modes.value("coordinates", 0)) +
                "spherical joints " + reportText(modes.at("spherical_joints")) +
                "): no mesh, so no discretization error; the model's error is its parameters', which the measured "
                "features above show.");
  const ReviewJson& e = modes.at("eigen");
  out.push_back("Eigen residual " + reportNumber(e.at("max_relative_residual")) + ", mass-orthogonality error " +
                reportNumber(e.at("orthogonality_error")) + "; the design configuration's force residual " +
                reportNumber(modes.at("equilibrium").at("residual_over_weight")) + " of the weight.");
  return out;
}

std::vector<std::string> transmissibilityAccuracy(const ReviewJson& frf) {
  const ReviewJson& f = frf.at("frequency_hz");
  return {strf("The full linear model's responses (no reduction) at %zu frequencies from ", f.size()) + reportNumber(f.front()) +
              " to " + reportNumber(f.back()) + " Hz, log-spaced: a peak is the grid's largest value, within a grid step "
              "of the resonance.",
          "Levels below about -200 dB are round-off: a zero by symmetry (the 10 Hz heat map floors them at -250 dB)."};
}

}  // namespace mmv
