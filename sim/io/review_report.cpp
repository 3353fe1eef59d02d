#include "sim/io/review_report.hpp"

#include <cctype>
#include <cmath>
#include <map>

#include "sim/core/text.hpp"

namespace mmv {

using ReviewJson = nlohmann::ordered_json;

std::string reportLargestShare(const ReviewJson& shares) {
  std::string name;
  double best = -1;
  if (!shares.is_object()) return "-";
  for (const auto& [k, v] : shares.items())
    if (v.is_number() && v.get<double>() > best) best = v.get<double>(), name = k;
  return best < 0 ? "-" : strf("%s (%.0f %%)", name.c_str(), 100 * best);
}

std::string reportText(const ReviewJson& v) { return v.is_string() ? v.get<std::string>() : v.is_null() ? "-" : v.dump(); }

std::string reportPercent(double e) { return e < 1e-5 ? std::string("< 0.001 %") : strf("%.2g %%", 100 * e); }

std::string verdictClass(const std::string& verdict) {
  if (verdict == "n/a") return "na";
  std::string c;
  for (const char ch : verdict) c += static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  return c;  // pass, warn, fail (printed FAIL), info, advisory
}

std::string reportNumber(const ReviewJson& v, double scale) {
  if (!v.is_number()) return "-";
  const double x = v.get<double>() * scale;
  return std::isfinite(x) ? strf("%.4g", x) : "-";
}

html::Table checkTable(const ReviewJson& check) {
  html::Table t;
  t.header = {"verdict", "group", "requirement", "demand", "capacity", "unit", "margin (%)", "basis and notes"};
  for (const auto& l : check.at("lines")) {
    const std::string verdict = l.at("verdict").get<std::string>();
    t.rows.push_back({verdict, reportText(l.at("group")), reportText(l.at("requirement")), reportNumber(l.at("demand")),
                      reportNumber(l.at("capacity")), reportText(l.at("unit")), reportNumber(l.at("margin_pct")), reportText(l.at("note"))});
    t.row_classes.push_back(verdictClass(verdict));
  }
  return t;
}

html::Table modeTable(const ReviewJson& modes) {
  std::map<int, double> error;  // by mode number, as the estimate reports it
  const ReviewJson& de = modes.at("discretization_error");
  if (de.value("available", false))
    for (const auto& m : de.at("modes"))
      if (m.at("estimated_relative_error").is_number()) error[m.at("number").get<int>()] = m.at("estimated_relative_error");
  const ReviewJson& damping = modes.at("damping");  // {"model": "none"} for an undamped scene
  const bool damped = damping.is_object() && damping.value("model", "none") != "none";
  html::Table t;
  t.header = {"mode", "frequency (Hz)", "estimated error"};
  if (damped) t.header.push_back("damping ratio (%)");
  for (const char* h : {"strain energy mostly in", "kinetic energy mostly in", "effective mass x (kg)", "effective mass y (kg)",
                        "gravity's share of stiffness (%)"})
    t.header.push_back(h);
  for (const auto& m : modes.at("modes")) {
    const int n = m.at("number").get<int>();
    std::vector<std::string> row{std::to_string(n), reportNumber(m.at("frequency_hz")),
                                 error.count(n) ? reportPercent(error[n]) : std::string("-")};
    if (damped) row.push_back(reportNumber(m.value("damping_ratio", ReviewJson()), 100));
    row.push_back(reportLargestShare(m.value("strain_energy_share_by_link", ReviewJson())));
    row.push_back(reportLargestShare(m.value("kinetic_energy_share", ReviewJson())));
    row.push_back(reportNumber(m.value("effective_mass_x_kg", ReviewJson())));
    row.push_back(reportNumber(m.value("effective_mass_y_kg", ReviewJson())));
    row.push_back(reportNumber(m.value("geometric_stiffness_share", ReviewJson()), 100));
    t.rows.push_back(std::move(row));
    t.row_classes.push_back(m.value("stable", true) ? "" : "fail");
  }
  return t;
}

html::Table sensorTable(const ReviewJson& placement) {
  html::Table t;
  const bool efi = placement.value("method", "") == "effective independence";
  t.header = {"#", "station", "axis", "along the link (m)", "world x (m)", "world y (m)", "world z (m)",
              efi ? "EfI score" : "score", "kept from the scene"};
  int k = 0;
  for (const auto& c : placement.at("chosen"))
    t.rows.push_back({std::to_string(++k), reportText(c.at("station")), reportText(c.at("axis")), reportNumber(c.at("x_along_link_m")),
                      reportNumber(c.at("world_x_m")), reportNumber(c.at("world_y_m")), reportNumber(c.at("world_z_m")),
                      reportNumber(c.at("score")), c.value("fixed", 0) ? "yes" : "no"});
  return t;
}

html::Table frfTable(const ReviewJson& frf) {
  html::Table t;
  t.header = {"output", "input", "unit", "peak (Hz)", "peak (dB)", "half-power damping (%)", "at 10 Hz (dB)",
              "reduced model's error"};
  for (const auto& p : frf.at("pairs")) {
    const std::string unit = reportText(p.at("output_unit")) + " per " + reportText(p.at("input_unit"));
    const ReviewJson& e = p.at("rom_relative_error");
    t.rows.push_back({reportText(p.at("output")), reportText(p.at("input")), unit, reportNumber(p.at("peak_hz")),
                      reportNumber(p.at("peak_db")), reportNumber(p.at("peak_half_power_damping"), 100),
                      reportNumber(p.at("at_10_hz_db")), e.is_number() ? reportPercent(e.get<double>()) : "-"});
  }
  return t;
}

std::vector<std::string> checkAccuracy(const ReviewJson& check) {
  std::vector<std::string> out;
  out.push_back(strf("Each line states its basis in its notes (rigid links or the flexible model at %d segments per link, "
                     "the run or program it is worst over); a margin is (capacity - demand) / capacity.",
                     check.value("segments", 0)));
  const int unchecked = check.value("not_checked", 0);
  if (unchecked > 0)
    out.push_back(strf("%d line%s marked n/a: the scene gives no capacity to check against (add the hardware's rating "
                       "to the scene).", unchecked, unchecked == 1 ? " is" : "s are"));
  return out;
}

html::Table strengthTable(const ReviewJson& modes, const ReviewJson& check) {
  std::map<std::string, const ReviewJson*> lines;  // check's lines by id
  for (const auto& l : check.at("lines")) lines[l.at("id").get<std::string>()] = &l;
  const auto line = [&](const std::string& id) -> std::string {
    const auto it = lines.find(id);
    if (it == lines.end()) return "-";
    const ReviewJson& l = *it->second;
    return reportNumber(l.at("demand")) + " MPa (" + reportText(l.at("verdict")) + ")";
  };
  html::Table t;
  t.header = {"link", "material", "static peak (MPa)", "where", "allowable / factor (MPa)", "margin of safety", "verdict",
              "check: worst held", "check: the scene's run"};
  for (const auto& l : modes.at("equilibrium").at("static_stress").at("links")) {
    const std::string link = l.at("link").get<std::string>();
    const bool recovered = l.value("recovered", false), judged = recovered && l.value("judged", false);
    const std::string verdict = !recovered ? "n/a" : judged ? reportText(l.at("verdict")) : "not judged";
    t.rows.push_back({link, reportText(l.at("material")), recovered ? reportNumber(l.at("equivalent_pa"), 1e-6) : "-",
                      recovered ? strf("x = %s m, %s face", reportNumber(l.at("x_m")).c_str(), reportText(l.at("face")).c_str())
                                : reportText(l.value("why_not", ReviewJson())),
                      judged ? strf("%s / %s (%s)", reportNumber(l.at("allowable_pa"), 1e-6).c_str(), reportNumber(l.at("factor")).c_str(),
                                    reportText(l.at("criterion")).c_str())
                             : (recovered ? reportText(l.value("note", ReviewJson())) : std::string("-")),
                      judged ? reportNumber(l.at("margin_of_safety")) : "-", verdict, line("stress." + link + ".hold"),
                      line("stress." + link + ".run")});
    bool fail = verdict == "FAIL";
    for (const char* kind : {".hold", ".run"})
      if (const auto it = lines.find("stress." + link + kind); it != lines.end()) fail = fail || it->second->at("verdict") == "FAIL";
    t.row_classes.push_back(fail ? "fail" : judged ? "pass" : "na");
  }
  return t;
}

std::vector<std::string> strengthAccuracy(const ReviewJson& modes) {
  std::vector<std::string> out;
  const ReviewJson& de = modes.at("discretization_error");
  std::string worst;
  double largest = -1;
  if (de.value("available", false) && de.contains("static_stress"))
    for (const auto& s : de.at("static_stress")) {
      const ReviewJson error = s.value("estimated_relative_error", ReviewJson()), order = s.value("observed_order", ReviewJson());
      if (error.is_number() && error.get<double>() > largest)
        largest = error.get<double>(), worst = reportText(s.at("link")) + (order.is_number() ? ", observed order " + reportNumber(order) : "");
    }
  out.push_back(largest >= 0 ? "Static stress: each link's peak from its hinges' moments, interpolated to the root and tip (mesh-independent "
                               "stations); its largest estimated discretization error " + reportPercent(largest) + " (" + worst + ")."
                             : "Static stress: no discretization estimate (the model is too coarse for coarser runs).");
  out.push_back("Margins: MS = allowable / (factor x stress) - 1, the governing allowable and the scene's factors of safety; "
                "check's run line is the rigid-link run of the scene's programs at each link's root, without the flexible "
                "response (`mmvlab simulate` records each link's stress through the flexible run).");
  return out;
}

std::vector<std::string> modesAccuracy(const ReviewJson& modes) {
  std::vector<std::string> out;
  const ReviewJson& de = modes.at("discretization_error");
  if (de.value("available", false)) {
    std::string runs;
    for (const auto& d : de.at("segment_divisors")) runs += (runs.empty() ? "" : ", ") + std::string("/") + d.dump();
    out.push_back("Estimated error of each frequency: Richardson extrapolation from the model at segments " + runs +
                  " and the reported mesh (the 'estimated error' column; 'unchecked' modes have no observed order).");
  } else {
    out.push_back("No discretization estimate: the model is too coarse for coarser runs (the frequencies' mesh error "
                  "is not stated).");
  }
  const ReviewJson& c = modes.at("checks");
  out.push_back("Eigen residual " + reportNumber(c.at("eigen_residual")) + ", mass-orthogonality error " +
                reportNumber(c.at("orthogonality_error")) + " (relative; round-off level is below 1e-8).");
  const ReviewJson& d = modes.at("damping");
  if (d.is_object() && d.value("model", "none") == "none")
    out.push_back("The scene has no damping: these modes are undamped (the frequency responses below state the damping "
                  "they assume).");
  else if (d.is_object())
    out.push_back("Damping: " + reportText(d.at("model")) + (d.value("exact", false) ? " (damped modes exact)" : "") + ".");
  return out;
}

std::vector<std::string> placementAccuracy(const ReviewJson& placement) {
  std::vector<std::string> out;
  out.push_back(strf("%zu sensors chosen of %d candidates by %s for modes ", placement.at("chosen").size(),
                     placement.value("candidates", 0), placement.value("method", "").c_str()) +
                placement.at("target_modes").dump() + "; the shapes are the mode table's.");
  out.push_back("Fisher information condition number " + reportNumber(placement.at("fisher_condition")) +
                "; largest off-diagonal AutoMAC " + reportNumber(placement.at("max_offdiagonal_automac")) + ".");
  const ReviewJson& pairs = placement.value("indistinguishable_mode_pairs", ReviewJson::array());
  if (!pairs.empty())
    out.push_back("These target modes look alike to the chosen sensors (AutoMAC above 0.9): " + pairs.dump() +
                  ". Add sensors or choose them for those modes.");
  return out;
}

std::vector<std::string> frfAccuracy(const ReviewJson& frf) {
  std::vector<std::string> out;
  out.push_back(strf("Full model: %d states; reduced model: %d states (%zu modes kept).", frf.value("full_states", 0),
                     frf.value("reduced_states", 0), frf.at("kept_frequencies_hz").size()));
  const ReviewJson& band = frf.at("band_hz");
  out.push_back("Reduced model against the full one: largest error " +
                reportPercent(frf.value("max_relative_frf_error", 0.0)) + " of each pair's peak over " +
                reportNumber(band.at(0)) + "-" + reportNumber(band.at(1)) + " Hz.");
  const ReviewJson& need = frf.value("modes_for_target", ReviewJson());
  if (need.is_object() && need.value("reached", false))
    out.push_back(strf("A reduced model within %s of each pair's peak needs %d modes (%s); frf --rom-modes N keeps N.",
                       reportPercent(need.value("target", 0.0)).c_str(), need.value("modes", 0),
                       reportPercent(need.value("error", 0.0)).c_str()));
  else if (need.is_object())
    out.push_back("No reduced model of the modes tried is within " + reportPercent(need.value("target", 0.0)) +
                  " of each pair's peak.");
  if (frf.contains("mesh_frf_error_estimate") && frf.at("mesh_frf_error_estimate").is_number())
    out.push_back("The mesh's share of the error near the peaks, which the reduced model's error above cannot see: "
                  "about " + reportPercent(frf.at("mesh_frf_error_estimate").get<double>()) + " of the peak at mode " +
                  reportText(frf.at("mesh_frf_error_mode")) +
                  " (its frequency's estimated mesh error over its damping ratio; more segments per link lower it).");
  out.push_back("Damping: " + reportText(frf.value("damping_model", ReviewJson())) + ".");
  return out;
}

}  // namespace mmv
