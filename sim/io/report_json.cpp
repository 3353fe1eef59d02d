#include <cmath>

#include "sim/core/units.hpp"
#include "sim/modes/converge.hpp"
#include "sim/io/convergence_fields.hpp"
#include "sim/io/mode_fields.hpp"
#include "sim/io/report.hpp"

namespace mmv {
namespace {

using json = nlohmann::ordered_json;

/// One mode of `r` in the modes JSON.
json modeJson(const ModesReport& r, const ModeInfo& m) {
  json mj = modeFieldsJson(r, m);
  json shape = json::array();
  for (const auto& p : m.shape) {
    json pj = {{"point", p.point}, {"ux", p.ux}, {"uy", p.uy}};
    if (r.spatial) pj["uz"] = p.uz;
    if (p.has_rotation) pj["rz"] = p.rz;
    shape.push_back(pj);
  }
  mj["shape"] = shape;
  if (!m.at_points.empty()) {
    json at = json::array();
    for (const auto& p : m.at_points) {
      json pj = {{"point", p.point}, {"ux_per_modal_unit", p.ux}, {"uy_per_modal_unit", p.uy}};
      if (r.spatial) pj["uz_per_modal_unit"] = p.uz;
      at.push_back(pj);
    }
    mj["at_points"] = at;
  }
  if (!m.stress_per_mm.empty()) {
    json st = json::array();
    for (const auto& l : m.stress_per_mm) {
      json lj = {{"link", l.link}, {"recovered", l.recovered}};
      if (l.recovered) {
        lj["x_m"] = l.x_m;
        lj["face"] = l.face;
        lj["equivalent_pa_per_mm"] = l.equivalent_pa_per_mm;
        lj["moment_n_m_per_mm"] = l.moment_nm_per_mm;
      } else {
        lj["why_not"] = l.why_not;
      }
      st.push_back(lj);
    }
    mj["stress_per_mm_of_peak"] = st;
  }
  if (!m.strains.empty()) {
    json st = json::array();
    for (const auto& g : m.strains) st.push_back({{"span", g.span}, {"strain_per_modal_unit", g.strain}});
    mj["strains"] = st;
  }
  return mj;
}

}  // namespace

json staticStressJson(const std::vector<LinkStaticStress>& links, const StrengthFactors& f) {
  json out = json::array();
  for (const auto& l : links) {
    const LinkStressPeak& p = l.peak;
    json lj = {{"link", p.link}, {"material", l.material}, {"recovered", p.recovered}};
    if (!p.recovered) {
      lj["why_not"] = p.why_not;
      out.push_back(lj);
      continue;
    }
    lj["x_m"] = p.loads.x;
    lj["face"] = p.stress.face;
    lj["axial_n"] = p.loads.axial;
    lj["moment_n_m"] = p.loads.moment;
    lj["moment_out_n_m"] = p.loads.moment_out;
    lj["torsion_n_m"] = p.loads.torsion;
    lj["tension_pa"] = p.stress.tension;
    lj["compression_pa"] = p.stress.compression;
    lj["shear_pa"] = p.stress.shear;
    lj["equivalent_pa"] = p.stress.equivalent;
    lj["strain"] = p.stress.strain;
    const StrengthJudgement& j = l.judgement;
    lj["judged"] = j.judged;
    if (j.judged) {
      lj["criterion"] = j.criterion;
      lj["allowable_pa"] = j.allowable;
      lj["factor"] = j.factor;
      lj["margin_of_safety"] = j.margin;
      lj["verdict"] = j.pass ? "ok" : "FAIL";
    } else {
      lj["note"] = j.note;
    }
    out.push_back(lj);
  }
  return {{"factors", {{"yield", f.yield_factor}, {"ultimate", f.ultimate_factor}, {"stated_by_scene", f.given}}},
          {"links", out}};
}

json modesToJson(const ModesReport& r) {
  json j;
  j["mmvlab_version"] = mmvlabVersion();
  j["command"] = "modes";
  j["scene"] = {{"name", r.scene_name}, {"source", r.scene_source}};
  json links = json::array();
  for (const auto& [name, n] : r.model.link_segments) {
    links.push_back({{"name", name}, {"segments", n ? json(n) : json("rigid")}});
    if (r.spatial) links.back()["model"] = r.model.planar_links.count(name) ? "planar" : "spatial";
  }
  j["model"] = {{"kind", r.spatial ? "spatial" : "planar"},
                {"links", links},
                {"bodies", r.model.num_bodies},
                {"coordinates", r.model.num_coordinates},
                {"dofs", r.model.num_dofs},
                {"total_mass_kg", r.model.total_mass_kg},
                {"moving_mass_kg", r.model.moving_mass_kg},
                {"gravity_m_per_s2", r.gravity}};
  json joints = json::array();
  for (const auto& jr : r.joints)
    joints.push_back({{"name", jr.name},
                      {"hold", jr.hold},
                      {"commanded_angle_deg", jr.commanded_rad * kRadToDeg},
                      {"equilibrium_angle_deg", jr.equilibrium_rad * kRadToDeg},
                      {"torque_n_m", jr.torque_nm}});
  json closures = json::array();
  for (const auto& c : r.closures) {
    closures.push_back({{"name", c.name}, {"force_x_n", c.fx}, {"force_y_n", c.fy}, {"gap_m", c.error_m}});
    if (r.spatial) closures.back()["force_z_n"] = c.fz;
  }
  json points = json::array();
  for (const auto& p : r.points) {
    json pj = {{"name", p.name}, {"x_m", p.x}, {"y_m", p.y}, {"deflection_x_m", p.dx}, {"deflection_y_m", p.dy}};
    if (r.spatial) pj["z_m"] = p.z, pj["deflection_z_m"] = p.dz;
    points.push_back(pj);
  }
  j["equilibrium"] = {{"converged", r.equilibrium_converged},
                      {"iterations", r.equilibrium_iterations},
                      {"residual_n_m", r.equilibrium_residual_nm},
                      {"force_scale_n_m", r.force_scale_nm},
                      {"joints", joints},
                      {"closures", closures},
                      {"points", points},
                      {"static_stress", staticStressJson(r.static_stress, r.strength)}};
  json modes = json::array();
  for (const auto& m : r.modes) modes.push_back(modeJson(r, m));
  j["damping"] = r.damped ? json{{"model", r.damping_model}, {"basis_modes", r.damping_basis_modes}, {"exact", r.damping_exact}}
                          : json{{"model", "none"}};
  j["modes"] = modes;
  j["checks"] = {{"eigen_residual", r.eigen_residual},
                 {"orthogonality_error", r.orthogonality_error},
                 {"stiffness_asymmetry", r.stiffness_asymmetry}};
  if (const auto& d = r.discretization; d.available || !d.reason.empty()) j["discretization_error"] = discretizationJson(d);
  if (r.segments_choice) j["target_error"] = segmentsChoiceJson(*r.segments_choice);
  if (r.planarity) j["planarity"] = planarityJson(*r.planarity);
  if (!r.warnings.empty()) j["warnings"] = r.warnings;
  j["time_s"] = {{"build", r.seconds_build},
                 {"equilibrium", r.seconds_equilibrium},
                 {"linearize", r.seconds_linearize},
                 {"eigen", r.seconds_eigen}};
  return j;
}

json discretizationJson(const DiscretizationEstimate& d) {
  if (!d.available) return {{"available", false}, {"reason", d.reason}};
  json modes = json::array();
  for (const auto& m : d.modes) modes.push_back(fieldsJson(convergenceModeFields(), m, [](const auto&) { return true; }));
  json stresses = json::array();
  for (const auto& s : d.stresses) {
    const ConvergenceMode& m = s.ladder;
    json sj = {{"link", s.link}, {"equivalent_stress_pa", m.frequency_hz}};
    if (m.has_estimate) sj["richardson_pa"] = m.extrapolated_hz, sj["estimated_relative_error"] = m.estimated_relative_error;
    if (m.has_observed_order) sj["observed_order"] = m.observed_order;
    sj["check"] = m.check.empty() ? "unchecked" : m.check;
    stresses.push_back(sj);
  }
  return {{"available", true}, {"segment_divisors", d.divisors}, {"wall_time_s", d.seconds}, {"modes", modes},
          {"static_stress", stresses}};
}

json segmentsChoiceJson(const SegmentsChoice& c) {
  json ladder = json::array();
  for (const auto& l : c.ladder)
    ladder.push_back({{"segments", l.segments},
                      {"worst_estimated_relative_error", std::isfinite(l.worst_error) ? json(l.worst_error) : json(nullptr)},
                      {"worst_mode", l.worst_mode ? json(l.worst_mode->number()) : json(nullptr)},
                      {"check", l.worst_check.empty() ? json(nullptr) : json(l.worst_check)},
                      {"solve_time_s", l.seconds},
                      {"met", l.met}});
  return {{"target_relative_error", c.target}, {"segments", c.segments}, {"wall_time_s", c.seconds}, {"ladder", ladder}};
}

json convergenceToJson(const ConvergenceStudy& c) {
  json j;
  j["mmvlab_version"] = mmvlabVersion();
  j["command"] = "converge";
  j["scene"] = {{"name", c.scene_name}, {"source", c.scene_source}};
  json runs = json::array();
  for (const auto& r : c.runs) {
    json f = json::array();
    for (double x : r.frequency_hz) f.push_back(x);
    runs.push_back({{"segments", r.segments}, {"dofs", r.num_dofs}, {"time_s", r.seconds}, {"frequencies_hz", f}});
  }
  j["runs"] = runs;
  json modes = json::array();
  for (const auto& m : c.modes) {
    json mj = fieldsJson(convergenceModeFields(), m, [](const auto&) { return true; });
    json e = json::array();  // converge.csv's relative_error, run by run (null: the run has no such mode)
    for (std::size_t k = 0; k < m.frequency_hz.size(); ++k)
      e.push_back(k < c.runs.size() && std::isfinite(m.frequency_hz[k])
                      ? *fieldValue(convergencePointFields(), ConvergencePoint{&m, &c.runs[k], k}, "relative_error")
                      : json(nullptr));
    mj["relative_error_by_run"] = e;
    modes.push_back(mj);
  }
  j["modes"] = modes;
  return j;
}

}  // namespace mmv
