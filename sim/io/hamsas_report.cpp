#include "sim/io/hamsas_report.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "sim/core/text.hpp"
#include "sim/io/linear_report.hpp"
#include "sim/io/report.hpp"

namespace mmv {
namespace {

const char* kDof[6] = {"x", "y", "z", "rx", "ry", "rz"};
const char* kUnit[6] = {"m", "m", "m", "rad", "rad", "rad"};

/// The largest |force| carried by the elements of `group` whose name starts with `prefix`.
double preload(const HamsasModes& h, const std::string& prefix) {
  double v = 0;
  for (std::size_t e = 0; e < h.model.springs.size(); ++e)
    if (h.model.springs[e].name.rfind(prefix, 0) == 0) v = std::max(v, h.lin.spring_force[e].norm());
  return v;
}

}  // namespace

double decibels(std::complex<double> v) { return 20 * std::log10(std::abs(v) + 1e-300); }

const char* hamsasDofName(int k) { return kDof[k]; }

std::string hamsasDescription(const HamsasModes& h) {
  std::ostringstream os;
  const SpatialSpec& m = h.model;
  os << strf("%d bodies (the base's motion prescribed), %d coordinates", static_cast<int>(m.bodies.size()),
             h.lin.num_free);
  if (h.spec.ideal_joints)
    os << strf(", %d after the ideal joints' constraints (%d redundant)", static_cast<int>(h.lin.Z.cols()),
               h.lin.redundant_constraints);
  os << "; effective spherical joints: "
     << (h.spec.ideal_joints ? std::string("ideal ball joints (constraints)")
                             : strf("stiff springs of %.3g N/m", h.spec.joint_stiffness))
     << '\n';
  return os.str();
}

std::string hamsasModesText(const HamsasScene& scene, const HamsasModes& h, int max_modes) {
  std::ostringstream os;
  const ModalSolution& s = h.solution;
  os << scene.name << " [" << scene.source << "]: " << hamsasDescription(h);
  os << strf("Equilibrium at the design configuration (preloads balance gravity): residual %.2g of the weight\n",
             h.lin.equilibrium_residual);
  os << strf("  preloads: MGAS springs %.1f N each, little pendulums %.1f N tension, IP flex joints %.1f N\n",
             preload(h, "mgas"), preload(h, "lp_bottom"), preload(h, "flex_joint"));
  double wmin = 0, wmax = 0;
  for (int i = 0; i < s.omega2.size(); ++i)
    if (s.omega2[i] > 0) wmin = wmin > 0 ? std::min(wmin, s.omega2[i]) : s.omega2[i], wmax = std::max(wmax, s.omega2[i]);
  os << strf("Eigen solution: %d modes, eigenvalue span %.2g (stiffest / softest omega^2); max relative residual "
             "||K v - w^2 M v|| / (w^2 ||M v||) = %.2g; M-orthogonality %.2g\n\n",
             static_cast<int>(s.omega2.size()), wmin > 0 ? wmax / wmin : 0.0, h.max_relative_residual,
             s.orthogonality_error);
  int unstable = 0;
  for (int i = 0; i < s.omega2.size(); ++i) unstable += !s.isStable(i);
  if (unstable) os << strf("UNSTABLE: %d mode(s) with negative stiffness (listed with negative frequency)\n\n", unstable);
  os << "Measured (LASTI, in vacuum) vs model:\n";
  Table t({"feature", "measured_Hz", "model_Hz", "error_%", "mode", "shape_match", "identified_as"});
  for (const FeatureMatch& f : h.features)
    t.add({f.feature, strf("%.4g", f.measured_hz), f.mode ? strf("%.4g", f.model_hz) : "none",
           f.mode ? strf("%+.2f", 100 * (f.model_hz / f.measured_hz - 1)) : "-",
           f.mode ? std::to_string(f.mode->number()) : "-", strf("%.3f", f.shape_match), f.rule});
  os << t.text() << '\n';
  os << "Modes (kinetic energy by body group; elastic strain energy by element group; gravity_%: the preloads' work\n"
        "over the elastic energy, negative where gravity takes back what the elements store, as in an inverted pendulum):\n";
  Table m({"mode", "f_Hz", "label", "kinetic_energy", "elastic_strain_energy", "gravity_%"});
  const auto top = [](const nlohmann::ordered_json& shares) {  // the three largest, at least 0.5 %
    std::vector<std::pair<double, std::string>> v;
    for (const auto& [k, x] : shares.items()) v.push_back({-std::abs(x.get<double>()), k});
    std::sort(v.begin(), v.end());
    std::string out;
    for (std::size_t j = 0; j < v.size() && j < 3 && -v[j].first >= 0.005; ++j)
      out += (j ? " " : "") + v[j].second + strf("=%.0f%%", 100 * shares[v[j].second].get<double>());
    return out;
  };
  // The cells are the mode records' values (hamsasModeFields), as modes.json and modes.csv hold them.
  for (const auto& row : hamsasModeRows(h, max_modes)) {
    const auto rec = fieldsJson(hamsasModeFields(), row, [](const auto&) { return true; });
    const double gravity = rec["preload_over_elastic"].get<double>();
    m.add({std::to_string(rec["mode"].get<int>()), strf("%.5g", rec["frequency_hz"].get<double>()),
           rec["label"].get<std::string>(), top(rec["kinetic_share"]), top(rec["strain_share"]),
           std::abs(gravity) < 5e-4 ? "0.0" : strf("%+.1f", 100 * gravity)});
  }
  os << m.text();
  return os.str();
}

nlohmann::ordered_json hamsasModesJson(const HamsasScene& scene, const HamsasModes& h, int max_modes) {
  nlohmann::ordered_json j;
  j["mmvlab_version"] = mmvlabVersion();
  j["scene"] = scene.name;
  j["source"] = scene.source;
  j["model"] = "hamsas";
  j["bodies"] = h.model.bodies.size();
  j["coordinates"] = h.lin.Z.cols();
  j["spherical_joints"] = h.spec.ideal_joints ? "ideal" : "stiff";
  // The design configuration is the equilibrium by the preloads; the residual says how well.
  j["equilibrium"] = {{"converged", true}, {"residual_over_weight", h.lin.equilibrium_residual}};
  j["eigen"] = {{"max_relative_residual", h.max_relative_residual}, {"orthogonality_error", h.solution.orthogonality_error}};
  for (const FeatureMatch& f : h.features)
    j["features"].push_back({{"feature", f.feature},
                             {"measured_hz", f.measured_hz},
                             {"model_hz", f.mode ? nlohmann::ordered_json(f.model_hz) : nlohmann::ordered_json()},
                             {"mode", f.mode ? nlohmann::ordered_json(f.mode->number()) : nlohmann::ordered_json()},
                             {"shape_match", f.shape_match},
                             {"rule", f.rule}});
  j["modes"] = nlohmann::ordered_json::array();
  for (const auto& row : hamsasModeRows(h, max_modes))
    j["modes"].push_back(fieldsJson(hamsasModeFields(), row, [](const auto&) { return true; }));
  return j;
}

std::vector<HamsasModeRow> hamsasModeRows(const HamsasModes& h, int max_modes) {
  const int all = static_cast<int>(h.modes.size()), n = max_modes > 0 ? std::min(max_modes, all) : all;
  std::vector<HamsasModeRow> rows;
  for (int i = 0; i < n; ++i) rows.push_back({&h, i});
  return rows;
}

const std::vector<Field<HamsasModeRow>>& hamsasModeFields() {
  using json = nlohmann::ordered_json;
  using Opt = std::optional<json>;
  using Row = HamsasModeRow;
  // clang-format off
  static const std::vector<Field<Row>> fields{
      {"mode", "", "%d", "the mode (1: the lowest)", [](const Row& r) -> Opt { return json(r.i + 1); }},
      {"frequency_hz", "Hz", "%.8g", "its frequency (negative: unstable, sqrt(-omega^2) / 2 pi)",
       [](const Row& r) -> Opt { return json(r.h->modes[r.i].frequency_hz); }},
      {"stable", "", "%d", "a positive stiffness (omega^2 > 0)", [](const Row& r) -> Opt { return json(r.h->solution.isStable(r.i)); }},
      {"label", "", "%s", "the body group and direction with the most kinetic energy",
       [](const Row& r) -> Opt { return json(r.h->modes[r.i].label); }},
      {"kinetic_share", "1", nullptr, "the kinetic energy's share by body group",
       [](const Row& r) -> Opt {
         json shares = json::object();
         for (const auto& [k, v] : r.h->modes[r.i].kinetic_share)
           if (k.find('.') == std::string::npos) shares[k] = v;  // "group.direction" entries are the label's
         return shares;
       }},
      {"strain_share", "1", nullptr, "the elastic strain energy's share by element group",
       [](const Row& r) -> Opt { return json(r.h->modes[r.i].strain_share); }},
      {"preload_over_elastic", "1", "%.6g", "the preloads' work over the elastic strain energy (gravity_%)",
       [](const Row& r) -> Opt { return json(r.h->modes[r.i].preload_over_elastic); }},
      {"shape", "kg^-1/2", nullptr,
       "each moving body's translation (m) and small rotation (rad), world axes, per unit modal coordinate of the "
       "mass-normalised shape",
       [](const Row& r) -> Opt {
         json bodies = json::array();
         const auto& spec = r.h->model;
         for (std::size_t b = 1; b < spec.bodies.size(); ++b) {
           const int row = SpatialLinearization::row(static_cast<int>(b));
           const auto phi = r.h->solution.shapes.col(r.i);
           bodies.push_back({{"body", spec.bodies[b].name},
                             {"translation", {phi(row), phi(row + 1), phi(row + 2)}},
                             {"rotation", {phi(row + 3), phi(row + 4), phi(row + 5)}}});
         }
         return bodies;
       }},
  };
  // clang-format on
  return fields;
}

std::string hamsasModesCsv(const HamsasModes& h, int max_modes) {
  return fieldsCsv(hamsasModeFields(), hamsasModeRows(h, max_modes), [](const auto&) { return true; });
}

std::string hamsasTransmissibilityText(const HamsasScene& scene, const HamsasModes& h, const std::vector<double>& f,
                                       const std::vector<Eigen::MatrixXcd>& T, const Eigen::MatrixXcd& T10) {
  std::ostringstream os;
  os << scene.name << " [" << scene.source << "]: ground-to-optical-table transmissibility, " << hamsasDescription(h);
  os << strf("Ground motion at the base's reference point; table motion at its mass centre; %g-%g Hz, %zu points\n\n",
             f.front(), f.back(), f.size());
  Table t({"transmissibility", "unit", "at_f_min", "peak_Hz", "peak_dB", "at_10_Hz_dB", "goal_at_10_Hz"});
  for (int k = 0; k < 6; ++k) {
    std::size_t best = 0;
    for (std::size_t i = 0; i < f.size(); ++i)
      if (std::abs(T[i](k, k)) > std::abs(T[best](k, k))) best = i;
    const double at10 = decibels(T10(k, k));
    const std::string goal = k < 3 ? (at10 <= -80 ? "meets 80 dB" : at10 <= -70 ? "meets 70 dB" : "misses 70 dB") : "-";
    t.add({std::string(kDof[k]) + " <- ground " + kDof[k], std::string(kUnit[k]) + "/" + kUnit[k],
           strf("%.4g", std::abs(T.front()(k, k))), strf("%.4g", f[best]), strf("%.2f", decibels(T[best](k, k))),
           strf("%.1f", at10), goal});
  }
  os << t.text();
  double off = -1e300;
  int oi = 0, oj = 0;
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j)
      if (i != j && decibels(T10(i, j)) > off) off = decibels(T10(i, j)), oi = i, oj = j;
  os << strf("Largest cross-coupling at 10 Hz: %s <- ground %s, %.1f dB (%s/%s)\n", kDof[oi], kDof[oj], off, kUnit[oi], kUnit[oj]);
  os << "(the 70-80 dB goal is the slides' horizontal and vertical attenuation above 10 Hz)\n";
  return os.str();
}

std::string hamsasVaryText(const std::string& key, const std::vector<HamsasVaryPoint>& points) {
  std::ostringstream os;
  os << "\nVarying " << key << ":\n";
  Table v({key, "IP_Hz", "x_at_1_Hz_dB", "x_at_3_Hz_dB", "x_at_10_Hz_dB", "z_at_10_Hz_dB"});
  for (const auto& p : points)
    v.add({strf("%g", p.value), strf("%.4g", p.ip_hz), strf("%.1f", p.x_at_1hz_db), strf("%.1f", p.x_at_3hz_db),
           strf("%.1f", p.x_at_10hz_db), strf("%.1f", p.z_at_10hz_db)});
  os << v.text();
  return os.str();
}

nlohmann::ordered_json hamsasTransmissibilityJson(const HamsasScene& scene, const std::vector<double>& f,
                                                  const std::vector<Eigen::MatrixXcd>& T, const Eigen::MatrixXcd& T10) {
  using json = nlohmann::ordered_json;
  json j;
  j["mmvlab_version"] = mmvlabVersion();
  j["command"] = "frf";
  j["scene"] = scene.name;
  j["dofs"] = std::vector<std::string>(std::begin(kDof), std::end(kDof));
  j["frequency_hz"] = f;
  json at10 = json::array(), pairs = json::array();
  for (int i = 0; i < 6; ++i) {
    std::vector<double> row;
    for (int k = 0; k < 6; ++k) row.push_back(decibels(T10(i, k)));
    at10.push_back(row);
    for (int k = 0; k < 6; ++k) {
      std::vector<double> db, ph;
      for (const auto& Tk : T) db.push_back(decibels(Tk(i, k))), ph.push_back(std::arg(Tk(i, k)) * 180 / M_PI);
      pairs.push_back({{"table", kDof[i]}, {"ground", kDof[k]},
                       {"unit", std::string(i < 3 ? "m" : "rad") + "/" + (k < 3 ? "m" : "rad")},
                       {"magnitude_db", db}, {"phase_deg", ph}});
    }
  }
  j["at_10_hz_db"] = at10;
  j["pairs"] = pairs;
  return j;
}

std::string hamsasTransmissibilityCsv(const std::vector<double>& f, const std::vector<Eigen::MatrixXcd>& T) {
  std::ostringstream csv;
  csv << "frequency_hz";
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j) {
      // The unit of each ratio in its name: table DOF i per ground DOF j, "x_from_rx_db_m_per_rad".
      const std::string unit = std::string(i < 3 ? "m" : "rad") + "_per_" + (j < 3 ? "m" : "rad");
      csv << "," << kDof[i] << "_from_" << kDof[j] << "_db_" << unit << "," << kDof[i] << "_from_" << kDof[j] << "_phase_deg";
    }
  csv << '\n';
  for (std::size_t k = 0; k < f.size(); ++k) {
    csv << strf("%.8g", f[k]);
    for (int i = 0; i < 6; ++i)
      for (int j = 0; j < 6; ++j) csv << strf(",%.8g,%.8g", decibels(T[k](i, j)), std::arg(T[k](i, j)) * 180 / M_PI);
    csv << '\n';
  }
  return csv.str();
}

nlohmann::ordered_json hamsasRomJson(const StateSpace& full, const ReducedModel& red, const ModelError& err,
                                     const std::vector<double>& f) {
  nlohmann::ordered_json j;
  j["mmvlab_version"] = mmvlabVersion();
  j["command"] = "rom";
  j["model"] = "hamsas actuators to sensors";
  j["full_states"] = full.numStates();
  j["reduced_states"] = red.model.numStates();
  j["kept_modes"] = red.kept_modes;
  j["kept_frequencies_hz"] = red.kept_frequencies_hz;
  j["residualized"] = red.residualized;
  j["unseen_modes_dropped"] = red.unseen_modes;
  j["band_hz"] = {f.front(), f.back()};
  j["max_relative_frf_error"] = err.max_relative;
  addLocalError(j, err, full.output_names, full.input_names);
  j["inputs"] = full.input_names;
  j["input_units"] = full.input_units;
  j["outputs"] = full.output_names;
  j["output_units"] = full.output_units;
  return j;
}

std::string hamsasRomText(const HamsasScene& scene, const HamsasModes& h, const StateSpace& full, const ReducedModel& red,
                          const ModelError& err, const std::vector<double>& f) {
  std::ostringstream os;
  os << scene.name << " [" << scene.source << "]: actuators to sensors on the spring box, " << hamsasDescription(h);
  os << strf("Full model: %d states, %d inputs (N), %d outputs (m); reduced: %d modes (%d states), %s\n", full.numStates(),
             static_cast<int>(full.B.cols()), static_cast<int>(full.C.rows()), red.kept_modes, red.model.numStates(),
             red.residualized ? "statically residualized (every DC gain exact)" : "truncated");
  os << strf("Modes no actuator-sensor pair sees (dropped first): %d\n", red.unseen_modes);
  os << "Kept modes (Hz):";
  for (double x : red.kept_frequencies_hz) os << strf(" %.4g", x);
  os << strf("\nLargest FRF error of the reduced model over %g-%g Hz, relative to each pair's peak: %.3g %%\n", f.front(),
             f.back(), 100 * err.max_relative);
  os << localErrorLine(err, full.output_names, full.input_names) << "\n";
  Table t({"sensor", "actuator", "DC_compliance_m_per_N", "rom_error_%", "rom_local_%", "local_at_Hz"});
  const Eigen::MatrixXcd h0 = full.response(0.0);
  for (Eigen::Index i = 0; i < full.C.rows(); ++i)
    t.add({full.output_names[i], full.input_names[i], strf("%.4g", h0(i, i).real()), strf("%.3g", 100 * err.relative(i, i)),
           strf("%.3g", 100 * err.local(i, i)), strf("%.4g", err.local_hz(i, i))});
  os << t.text();
  return os.str();
}

}  // namespace mmv
