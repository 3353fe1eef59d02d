#include "sim/io/simulation_report.hpp"

#include <charconv>
#include <cmath>
#include <sstream>

#include "facility/table_programs.hpp"
#include "sim/core/errors.hpp"
#include "sim/core/integrators.hpp"
#include "sim/core/text.hpp"
#include "sim/io/report.hpp"
#include "sim/time/verify.hpp"

namespace mmv {
namespace {

/// The largest distance of each scored point from its start (link tips; the isolator's
/// table and spring box), m.
std::vector<std::pair<std::string, double>> peakDisplacements(const SimulationRecord& rec) {
  std::vector<std::pair<std::string, double>> out;
  for (const auto& [name, cols] : rec.scored) {
    double peak = 0;
    for (const auto& row : rec.rows) {
      double d2 = 0;
      for (int c : cols) d2 += std::pow(row[c] - rec.rows.front()[c], 2);
      peak = std::max(peak, std::sqrt(d2));
    }
    out.push_back({name, peak});
  }
  return out;
}

/// Each link's peak stress over the run against its allowable (docs/strength.md); the
/// cells are the records' values (linkRunStressFields).
std::string runStressText(const std::vector<LinkRunStress>& links) {
  if (links.empty()) return "";
  Table t({"link", "peak_MPa", "t_s", "x_m", "face", "axial_N", "moment_N*m", "limit_MPa", "MS", "verdict", "first_exceeded_s"});
  std::vector<std::string> notes;
  const auto all = [](const auto&) { return true; };
  for (const auto& l : links) {
    const auto rec = fieldsJson(linkRunStressFields(), l, all);
    if (!l.recovered) {
      notes.push_back(l.link + ": " + l.why_not);
      continue;
    }
    const auto num = [&](const char* key, const char* format, double scale = 1) {
      return rec[key].is_number() ? strf(format, scale * rec[key].get<double>()) : std::string("-");
    };
    t.add({l.link, num("peak_stress_pa", "%.4g", 1e-6), num("at_s", "%.4g"), l.root_only ? "root" : num("x_m", "%.4f"),
           rec["face"].get<std::string>(), num("axial_n", "%.4g"), num("moment_n_m", "%.4g"), num("limit_pa", "%.4g", 1e-6),
           num("margin_of_safety", "%.3f"), rec["verdict"].get<std::string>(), num("first_exceeded_s", "%.4g")});
    if (!l.judgement.judged) notes.push_back(l.link + ": " + l.judgement.note);
    if (l.root_only) notes.push_back(l.link + ": a rigid link: its root's loads from the run's reactions; along it not recovered");
  }
  std::string out = "\nStress (peak per link over the run; limit = allowable / factor, MS = allowable / (factor * stress) - 1;\n"
                    "docs/strength.md)\n" + t.text();
  for (const auto& n : notes) out += "  " + n + "\n";
  return out;
}

}  // namespace

nlohmann::ordered_json simulationJson(const SimulationResult& r, const std::vector<std::string>& warnings) {
  nlohmann::ordered_json j;
  j["mmvlab_version"] = mmvlabVersion();
  j["command"] = "simulate";
  j["integrator"] = r.integrator;
  j["accuracy"] = r.accuracy;
  if (!r.damping.empty()) j["damping"] = r.damping;
  if (!r.fidelity.empty()) j["fidelity"] = r.fidelity;
  j["duration_s"] = r.record.rows.empty() ? 0.0 : r.record.rows.back()[0];
  j["samples"] = r.record.rows.size();
  if (!r.modal_links.empty()) {
    auto links = nlohmann::ordered_json::array();
    for (const auto& m : r.modal_links) {
      links.push_back({{"link", m.link}, {"modes", m.modes}, {"hinges", m.hinges}, {"highest_kept_hz", m.highest_kept_hz},
                       {"first_dropped_hz", m.first_dropped_hz > 0 ? nlohmann::ordered_json(m.first_dropped_hz) : nlohmann::ordered_json(nullptr)}});
      if (m.release_share_left) links.back()["release_share_left"] = *m.release_share_left;
    }
    j["modal_links"] = links;
  }
  const auto all = [](const auto&) { return true; };
  auto torques = nlohmann::ordered_json::array();
  for (const auto& t : r.torques) torques.push_back(fieldsJson(jointTorqueFields(), t, all));
  j["torques"] = torques;
  for (const auto& [name, peak] : peakDisplacements(r.record)) j["peak_displacement_m"][name] = peak;
  auto sensors = nlohmann::ordered_json::array();
  for (const auto& s : r.sensors) sensors.push_back(fieldsJson(sensorSummaryFields(), s, all));
  j["sensors"] = sensors;
  if (!r.stresses.empty()) {
    auto stress = nlohmann::ordered_json::array();
    for (const auto& l : r.stresses) stress.push_back(fieldsJson(linkRunStressFields(), l, all));
    j["stress"] = stress;
  }
  j["energy"] = {{"initial_j", r.initial_energy_j},
                 {"final_j", r.final_energy_j},
                 {"motion_work_j", r.motion_work_j},
                 {"dissipated_j", r.dissipated_j},
                 {"balance_error_j", r.energy_balance_error_j},
                 {"max_balance_error_j", r.max_energy_balance_error_j},
                 {"max_balance_error_at_s", r.max_energy_balance_error_at_s},
                 {"peak_kinetic_j", r.peak_kinetic_energy_j}};
  if (r.carried_weight_n > 0)
    j["table"] = {{"peak_force_n", r.peak_table_force_n}, {"carried_weight_n", r.carried_weight_n},
                  {"payload_n", facility::TableSpec{}.payload_n}};
  if (r.shaker)
    j["shaker"] = {{"at", r.shaker->at},
                   {"peak_force_n", r.shaker->peak_force_n},
                   {"force_limit_n", r.shaker->force_limit_n},
                   {"peak_stroke_m", r.shaker->peak_stroke_m},
                   {"stroke_m", r.shaker->stroke_m},
                   {"peak_stinger_force_n", r.shaker->peak_stinger_force_n},
                   {"stroke_exceeded", r.shaker->stroke_exceeded}};
  if (r.constraint_drift_m > 0) j["constraint_drift_m"] = r.constraint_drift_m;
  j["steps"] = r.steps;
  j["realizations"] = r.realizations;
  j["rejected_steps"] = r.rejected_steps;
  if (r.jacobians >= 0) j["jacobians"] = r.jacobians;
  j["wall_time_s"] = r.wall_seconds;
  j["stepping_time_s"] = r.stepping_seconds;
  j["output_time_s"] = r.output_seconds;
  if (const RunVerification& v = r.verification; v.done)
    j["verification"] = {{"companion_accuracy", v.companion_accuracy},
                         {"estimated_error_m", v.estimated_error_m},
                         {"at_s", v.at_s},
                         {"point", v.point},
                         {"scored_amplitude_m", v.amplitude_m},
                         {"target_m", v.target_m},
                         {"target", v.target_is_default ? "1 % of the scored amplitude" : "given"},
                         {"safety_factor", kVerifySafetyFactor},
                         {"met", verificationMet(v)},
                         {"companion_wall_time_s", v.companion_seconds},
                         {"companion_modes", v.companion_more_modes ? "twice the run's per link" : "the run's"}};
  j["warnings"] = warnings;
  return j;
}

std::string simulationText(const std::string& scene_name, const std::string& scene_source, const SimulationResult& r,
                           const std::vector<std::string>& warnings) {
  std::ostringstream os;
  os << scene_name << "  (scene: " << scene_source << ")\n";
  os << strf("Time run: %.4g s with %s (accuracy %.1e), %zu samples; %.2f s wall time\n",
             r.record.rows.empty() ? 0.0 : r.record.rows.back()[0], r.integrator.c_str(), r.accuracy, r.record.rows.size(),
             r.wall_seconds);
  if (!r.fidelity.empty()) os << "Model: " << r.fidelity << "\n";
  if (!r.damping.empty()) os << "Damping: " << r.damping << "\n";
  os << strf("Cost: %d steps (%ld rejected), %d %s, %s; stepping %.3g s, sampling %.3g s\n\n", r.steps, r.rejected_steps,
             r.realizations, isSundialsIntegrator(r.integrator) ? "right-hand sides" : "realizations",
             r.jacobians < 0 ? "Jacobians not reported" : strf("%ld Jacobians", r.jacobians).c_str(), r.stepping_seconds,
             r.output_seconds);
  if (!r.modal_links.empty()) {
    os << "Links in modal coordinates (root held, the rest rigid, at the start):\n";
    for (const auto& m : r.modal_links)
      os << strf("  %s: %d of %d modes, up to %.4g Hz%s%s\n", m.link.c_str(), m.modes, m.hinges, m.highest_kept_hz,
                 m.first_dropped_hz > 0 ? strf("; the first left out %.4g Hz", m.first_dropped_hz).c_str() : " (all kept)",
                 m.release_share_left
                     ? strf("; the modes left out carry %.2g of the release's static response", *m.release_share_left).c_str()
                     : "");
    os << "\n";
  }
  Table t({"joint", "peak_torque_N*m", "capacity_N*m", "within"});
  const auto all = [](const auto&) { return true; };
  for (const auto& q : r.torques) {  // the cells are the records' values (jointTorqueFields)
    const auto rec = fieldsJson(jointTorqueFields(), q, all);
    const bool rated = rec["capacity_n_m"].is_number();
    t.add({rec["joint"].get<std::string>(), strf("%.4f", rec["peak_torque_n_m"].get<double>()),
           rated ? strf("%.4g", rec["capacity_n_m"].get<double>()) : "-",
           rated ? (rec["exceeded"].get<bool>() ? "EXCEEDED" : "yes") : "-"});
  }
  if (!r.torques.empty()) os << "Torques the torquers must give\n" << t.text();
  os << runStressText(r.stresses);
  Table d({"point", "peak_displacement_m"});
  for (const auto& [name, peak] : peakDisplacements(r.record)) d.add({name, strf("%.4g", peak)});
  if (!d.empty()) os << (r.torques.empty() ? "" : "\n") << "Largest displacement from the start\n" << d.text();
  if (r.carried_weight_n > 0)
    os << strf("\nTable: peak actuator force %.4g N; carries %.4g N of its %.4g N payload\n", r.peak_table_force_n,
               r.carried_weight_n, facility::TableSpec{}.payload_n);
  if (const auto& sh = r.shaker)
    os << strf("\nShaker at %s: peak force %.4g N of its %.4g N; armature travel %.4g mm of its +-%.4g mm stroke%s; "
               "the stinger passes up to %.4g N\n",
               sh->at.c_str(), sh->peak_force_n, sh->force_limit_n, sh->peak_stroke_m * 1e3, sh->stroke_m * 1e3,
               sh->stroke_exceeded ? " (EXCEEDED)" : "", sh->peak_stinger_force_n);
  if (!r.sensors.empty()) {
    Table st({"sensor", "type", "unit", "saturated_samples"});
    for (const auto& s : r.sensors) {  // the cells are the records' values (sensorSummaryFields)
      const auto rec = fieldsJson(sensorSummaryFields(), s, all);
      st.add({rec["name"].get<std::string>(), rec["type"].get<std::string>(), rec["unit"].get<std::string>(),
              strf("%d of %d", rec["saturated_samples"].get<int>(), rec["samples"].get<int>())});
    }
    os << "\nSensors\n" << st.text();
  }
  os << strf("\nEnergy: E(0) %.6g J, E(end) %.6g J, work of the commanded motions %.6g J, dissipated %.6g J;\n"
             "balance error %.3g J at the end (E(end) - E(0) - work + dissipated), largest %.3g J at t = %.4g s\n",
             r.initial_energy_j, r.final_energy_j, r.motion_work_j, r.dissipated_j, r.energy_balance_error_j,
             r.max_energy_balance_error_j, r.max_energy_balance_error_at_s);
  if (r.constraint_drift_m > 0) os << strf("Closures: largest drift %.3g m over the run\n", r.constraint_drift_m);
  if (const RunVerification& v = r.verification; v.done)
    os << strf("Verification: estimated error %.3g m (%s at t = %.4g s, against accuracy %.1e%s, %.2f s); target %.3g m%s, "
               "held with a safety factor %g: %s\n",
               v.estimated_error_m, v.point.c_str(), v.at_s, v.companion_accuracy,
               v.companion_more_modes ? " and the modes up to twice the frequency" : "", v.companion_seconds, v.target_m,
               !v.target_is_default                    ? ""
               : v.target_m > 0.01 * v.amplitude_m * (1 + 1e-9) ? " (nothing moved beyond a micrometre per metre: 1 % of that)"
                                                               : " (1 % of the scored motion)",
               kVerifySafetyFactor, verificationMet(v) ? "met" : "NOT MET");
  for (const auto& w : warnings) os << "warning: " << w << '\n';
  return os.str();
}

namespace {

std::string fidelityName(const TargetOutcome& t, const TargetAttempt& a) {
  if (!a.model.empty()) return strf("%s at %g, the scene's own run", a.integrator.c_str(), a.accuracy);
  const std::string segments = a.segments ? strf(", %d segments per link", a.segments) : std::string(", the scene's segments");
  return strf("%s at %g", a.integrator.c_str(), a.accuracy) + (t.has_segments ? segments : std::string()) +
         (a.modes ? strf(" in %d modes per link", a.modes) : std::string());
}

}  // namespace

std::string targetText(const TargetOutcome& t) {
  std::ostringstream os;
  int measured = 0;
  for (const auto& r : t.pilot.runs) measured += r.ok;
  const TargetAttempt& first = t.attempts.front();
  if (!first.model.empty())
    os << strf("Target error %.3g m: the scene's own run first (%s)%s\n", t.target_m, first.model.c_str(),
               first.met ? ": met, no pilot" : ": missed, then the pilot");
  if (t.window_s > 0)
    os << strf("Target error %.3g m: pilot over the first %g s (target there %.3g m), %d runs measured of %zu, %.2f s\n",
               t.target_m, t.window_s, t.window_target_m, measured, t.pilot.runs.size(), t.pilot.total_seconds);
  Table a({"whole_run", "run_s", "estimated_error_m", "where", "verified_against", "verification_s", "target"});
  for (const auto& r : t.attempts)
    a.add({fidelityName(t, r), strf("%.3g", r.run_seconds), strf("%.3g", r.estimated_error_m),
           strf("%s at %.4g s", r.point.c_str(), r.at_s),
           strf("accuracy %g", r.accuracy / 10) +
               (r.companion_more_modes ? ", modes to twice the frequency" : !r.model.empty() ? ", the same model" : t.has_segments ? ", the scene's segments, every hinge" : ""),
           r.companion_reused ? std::string("(the same)") : strf("%.3g", r.companion_seconds),
           r.met ? "met" : r.failed ? "failed" : !r.energy_ok ? "missed: energy balance" : "missed"});
  os << a.text();
  const TargetAttempt& last = t.attempts.back();
  os << strf("Chosen: %s; estimated error %.3g m within half the %.3g m target (the estimate's margin), energy balance held; cost %.2f s in "
             "all (pilot %.2f s), %.1f x the run chosen\n",
             fidelityName(t, last).c_str(), last.estimated_error_m, t.target_m,
             t.total_seconds, t.pilot.total_seconds, last.run_seconds > 0 ? t.total_seconds / last.run_seconds : 0.0);
  return os.str();
}

nlohmann::ordered_json targetJson(const TargetOutcome& t) {
  nlohmann::ordered_json j;
  j["target_m"] = t.target_m;
  nlohmann::ordered_json runs = nlohmann::ordered_json::array();
  for (const auto& r : t.pilot.runs) {
    nlohmann::ordered_json one = {{"integrator", r.integrator}, {"accuracy", r.accuracy}, {"segments", r.segments},
                                  {"modes", r.modes},           {"status", r.status}};
    if (r.ok) one.update({{"error_m", r.error_m}, {"wall_time_s", r.seconds}, {"energy_balance_ok", r.energy_ok}});
    runs.push_back(one);
  }
  if (t.window_s > 0) j["pilot"] = {{"window_s", t.window_s},
                {"window_target_m", t.window_target_m},
                {"reference_uncertainty_m", t.pilot.reference_uncertainty_m},
                {"reference_wall_time_s", t.pilot.reference_seconds},
                {"wall_time_s", t.pilot.total_seconds},
                {"runs", runs}};
  else j["pilot"] = nullptr;  // the scene's own model met the target first
  nlohmann::ordered_json attempts = nlohmann::ordered_json::array();
  for (const auto& r : t.attempts)
    attempts.push_back({{"integrator", r.integrator},
                        {"accuracy", r.accuracy},
                        {"segments", r.segments},  // 0: the scene's
                        {"modes", r.modes},        // 0: every hinge
                        {"run_wall_time_s", r.run_seconds},
                        {"estimated_error_m", r.estimated_error_m},
                        {"at_s", r.at_s},
                        {"point", r.point},
                        {"companion_accuracy", r.accuracy / 10},
                        {"companion_wall_time_s", r.companion_seconds},
                        {"energy_balance_ok", r.energy_ok},
                        {"met", r.met},
                        {"failed", r.failed},
                        {"model", r.model.empty() ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(r.model)}});
  j["attempts"] = attempts;
  j["total_wall_time_s"] = t.total_seconds;
  j["cost_over_chosen_run"] = t.attempts.back().run_seconds > 0 ? t.total_seconds / t.attempts.back().run_seconds : 0.0;
  return j;
}

const std::vector<Field<JointTorqueSummary>>& jointTorqueFields() {
  using json = nlohmann::ordered_json;
  using Opt = std::optional<json>;
  using T = JointTorqueSummary;
  // clang-format off
  static const std::vector<Field<T>> fields{
      {"joint", "", nullptr, "the joint (a torquer, or a gimbal axis)", [](const T& t) -> Opt { return json(t.joint); }},
      {"peak_torque_n_m", "N*m", nullptr, "the largest torque it had to give over the run",
       [](const T& t) -> Opt { return json(t.peak_torque_nm); }},
      {"capacity_n_m", "N*m", nullptr, "its torquer's rating (null: none given)",
       [](const T& t) -> Opt { return t.capacity_nm > 0 ? json(t.capacity_nm) : json(nullptr); }},
      {"exceeded", "", nullptr, "the peak is above the rating", [](const T& t) -> Opt { return json(t.exceeded); }},
  };
  // clang-format on
  return fields;
}

const std::vector<Field<LinkRunStress>>& linkRunStressFields() {
  using json = nlohmann::ordered_json;
  using Opt = std::optional<json>;
  using L = LinkRunStress;
  // clang-format off
  static const std::vector<Field<L>> fields{
      {"link", "", nullptr, "the link (a branch by its own name)", [](const L& l) -> Opt { return json(l.link); }},
      {"material", "", nullptr, "its material", [](const L& l) -> Opt { return json(l.material); }},
      {"recovered", "", nullptr, "its stress was recovered (false: why_not says why)", [](const L& l) -> Opt { return json(l.recovered); }},
      {"why_not", "", nullptr, "why it was not", [](const L& l) -> Opt { return l.recovered ? Opt() : json(l.why_not); }},
      {"where", "", nullptr, "\"along the link\" (root, hinges, tip) or \"root\" (a rigid link)",
       [](const L& l) -> Opt { return json(l.root_only ? "root" : "along the link"); }},
      {"peak_stress_pa", "Pa", nullptr, "the largest equivalent (von Mises) stress at a sample",
       [](const L& l) -> Opt { return l.recovered ? json(l.peak_pa) : json(nullptr); }},
      {"at_s", "s", nullptr, "the time of that sample", [](const L& l) -> Opt { return l.recovered ? json(l.at_s) : json(nullptr); }},
      {"x_m", "m", nullptr, "where, from the link's root", [](const L& l) -> Opt { return l.recovered ? json(l.loads.x) : json(nullptr); }},
      {"face", "", nullptr, "the face where it peaks (+y, -y, +z, -z, a corner; axis: no bending)",
       [](const L& l) -> Opt { return json(l.recovered ? l.face : std::string("-")); }},
      {"axial_n", "N", nullptr, "the axial force there, tension +", [](const L& l) -> Opt { return l.recovered ? json(l.loads.axial) : json(nullptr); }},
      {"moment_n_m", "N*m", nullptr, "the in-plane bending moment there", [](const L& l) -> Opt { return l.recovered ? json(l.loads.moment) : json(nullptr); }},
      {"moment_out_n_m", "N*m", nullptr, "the out-of-plane bending moment there", [](const L& l) -> Opt { return l.recovered ? json(l.loads.moment_out) : json(nullptr); }},
      {"torsion_n_m", "N*m", nullptr, "the torsion there", [](const L& l) -> Opt { return l.recovered ? json(l.loads.torsion) : json(nullptr); }},
      {"criterion", "", nullptr, "the governing allowable: yield or ultimate (null: none given)",
       [](const L& l) -> Opt { return l.judgement.judged ? json(l.judgement.criterion) : json(nullptr); }},
      {"allowable_pa", "Pa", nullptr, "the material's governing allowable", [](const L& l) -> Opt { return l.judgement.judged ? json(l.judgement.allowable) : json(nullptr); }},
      {"factor", "1", nullptr, "the scene's factor on it", [](const L& l) -> Opt { return l.judgement.judged ? json(l.judgement.factor) : json(nullptr); }},
      {"limit_pa", "Pa", nullptr, "the smallest allowable / factor: the stress the run must stay under",
       [](const L& l) -> Opt { return l.limit_pa > 0 ? json(l.limit_pa) : json(nullptr); }},
      {"margin_of_safety", "1", nullptr, "MS = allowable / (factor * peak) - 1", [](const L& l) -> Opt { return l.judgement.judged ? json(l.judgement.margin) : json(nullptr); }},
      {"verdict", "", nullptr, "ok, FAIL, or not judged (no allowable, nothing recovered)",
       [](const L& l) -> Opt { return json(!l.judgement.judged ? "not judged" : l.judgement.pass ? "ok" : "FAIL"); }},
      {"first_exceeded_s", "s", nullptr, "the first sample whose stress passed limit_pa (null: none)",
       [](const L& l) -> Opt { return l.first_exceeded_s >= 0 ? json(l.first_exceeded_s) : json(nullptr); }},
  };
  // clang-format on
  return fields;
}

const std::vector<Field<SensorSummary>>& sensorSummaryFields() {
  using json = nlohmann::ordered_json;
  using Opt = std::optional<json>;
  using S = SensorSummary;
  // clang-format off
  static const std::vector<Field<S>> fields{
      {"name", "", nullptr, "the sensor (the scene's name)", [](const S& s) -> Opt { return json(s.name); }},
      {"type", "", nullptr, "encoder, gyro, accelerometer, ...", [](const S& s) -> Opt { return json(s.type); }},
      {"unit", "", nullptr, "the unit of its history.csv column", [](const S& s) -> Opt { return json(s.unit); }},
      {"saturated_samples", "", nullptr, "samples at or beyond its range",
       [](const S& s) -> Opt { return json(s.saturated_samples); }},
      {"samples", "", nullptr, "samples in the run", [](const S& s) -> Opt { return json(s.samples); }},
  };
  // clang-format on
  return fields;
}

std::string simulationHistoryCsv(const SimulationRecord& rec) {
  std::string out;
  for (std::size_t c = 0; c < rec.columns.size(); ++c) out += (c ? "," : "") + csvColumnName(rec.columns[c]);
  out += '\n';
  // std::to_chars in the style of printf's %.10g (the standard's words), without
  // printf's locale and format parsing: the run's rows dominate what --out writes.
  char buf[32];
  std::size_t cells = 0;
  for (const auto& row : rec.rows) cells += row.size();
  out.reserve(out.size() + 18 * cells);
  for (const auto& row : rec.rows) {
    for (std::size_t c = 0; c < row.size(); ++c) {
      if (c) out += ',';
      const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, row[c], std::chars_format::general, 10);
      MMV_DEMAND(ec == std::errc());  // 10 significant digits fit in 32 characters
      out.append(buf, end);
    }
    out += '\n';
  }
  return out;
}

std::vector<std::string> simulationWarnings(const SimulationResult& r, double article_size_m) {
  std::vector<std::string> warnings;
  for (const auto& s : r.sensors)
    if (s.saturated_samples > 0)
      warnings.push_back("sensor " + s.name + " saturated in " + std::to_string(s.saturated_samples) + " of " +
                         std::to_string(s.samples) + " samples");
  for (const auto& t : r.torques)
    if (t.exceeded)
      warnings.push_back(t.joint + " needs " + strf("%.4g", t.peak_torque_nm) + " N*m, above its torquer's capacity of " +
                         strf("%.4g", t.capacity_nm) + " N*m");
  for (const auto& l : r.stresses)
    if (l.first_exceeded_s >= 0)
      warnings.push_back(strf("%s's stress passes its allowable over its factor (%.4g MPa) first at t = %.4g s and peaks at %.4g MPa "
                              "at t = %.4g s (%s): margin of safety %.3f; the article would not survive this run "
                              "(docs/strength.md)",
                              l.link.c_str(), 1e-6 * l.limit_pa, l.first_exceeded_s, 1e-6 * l.peak_pa, l.at_s,
                              l.root_only ? "at its root" : strf("x = %.4g m, %s face", l.loads.x, l.face.c_str()).c_str(),
                              l.judgement.margin));
  if (r.shaker && r.shaker->stroke_exceeded)
    warnings.push_back(strf("the shaker's armature travels %.4g mm, beyond its +-%.4g mm stroke (shaker.stroke_m): lower the "
                            "program's force near the article's resonances, or move the shaker where the article moves less",
                            r.shaker->peak_stroke_m * 1e3, r.shaker->stroke_m * 1e3));
  if (const std::string w = energyBalanceWarning(r); !w.empty()) warnings.push_back(w);
  if (const std::string w = constraintDriftWarning(r, article_size_m); !w.empty()) warnings.push_back(w);
  if (const std::string w = verificationWarning(r.verification); !w.empty()) warnings.push_back(w);
  if (const double payload = facility::TableSpec{}.payload_n; r.carried_weight_n > payload)
    warnings.push_back("the table carries " + strf("%.4g", r.carried_weight_n) + " N, above its " + strf("%.4g", payload) +
                       " N payload");
  return warnings;
}

}  // namespace mmv
