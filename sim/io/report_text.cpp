#include <algorithm>
#include <cstdarg>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "sim/core/units.hpp"
#include "sim/io/convergence_fields.hpp"
#include "sim/modes/converge.hpp"
#include "sim/io/report.hpp"
#include "sim/core/text.hpp"

namespace mmv {
namespace {


double shareOf(const std::vector<PartShare>& shares, const std::string& part) {
  for (const auto& s : shares)
    if (s.part == part) return s.fraction;
  return 0;
}

}  // namespace

const char* mmvlabVersion() { return MMVLAB_VERSION; }  // CMakeLists.txt's project(VERSION)

namespace {

/// The system modes' table with its legend.
std::string modesTable(const ModesReport& r) {
  std::ostringstream os;
  os << "\nSystem modes about the equilibrium\n"
        "  kinetic, strain: the link with the largest share of the mode's energy, counted with the\n"
        "                   lumped masses it carries (tip mass, torquers at its tip)\n"
        "  geometric_%: share of the modal stiffness from preload (gravity, loads, closure forces)\n"
        "  m_eff: effective mass for base translation (what a shaker at the base sees)\n"
        "  peak: the named point that moves most\n";
  if (r.damped)
    os << "  zeta_%: damping ratio under the scene's damping: " << r.damping_model << "\n"
       << strf("          (the damped eigenproblem over %d real modes%s)\n", r.damping_basis_modes,
               r.damping_exact ? ", every mode: exact" : ", the lowest: a projection");
  else
    os << "  damping: none in the scene (give it `damping:` to see each mode's ratio; frf and rom assume 1 % modal)\n";
  if (r.spatial)
    os << "  family: what the mode's strain energy bends (in-plane, out-of-plane, torsion: 80 % or more; else mixed)\n";
  os << strf("  %4s %13s  %-20s %-20s %9s %10s %10s  %s%s%s\n", "mode", "frequency_Hz", "kinetic (link)", "strain (link)",
            "geometric_%", "m_eff_x_kg", "m_eff_y_kg", r.spatial ? strf("%10s  %-13s ", "m_eff_z_kg", "family").c_str() : "",
            r.damped ? strf("%8s  ", "zeta_%").c_str() : "", "peak");
  for (const auto& m : r.modes) {
    const std::string f = m.rigid_body ? strf("%13s", "0 (rigid)")
                          : m.stable   ? strf("%13.4f", m.frequency_hz)
                                       : strf("%13s", "UNSTABLE");
    const std::string k = strf("%s (%.0f %%)", m.dominant_link_kinetic.c_str(), 100 * shareOf(m.kinetic_by_link, m.dominant_link_kinetic));
    const std::string s = m.dominant_link_strain.empty()
                              ? std::string("-")
                              : strf("%s (%.0f %%)", m.dominant_link_strain.c_str(), 100 * shareOf(m.strain_by_link, m.dominant_link_strain));
    const std::string zeta = !r.damped                                     ? ""
                             : m.rigid_body || !m.stable || !m.has_damping ? strf("%8s  ", "-")
                                                                           : strf("%8.3f  ", 100 * m.damping_ratio);
    const std::string fam = r.spatial ? strf("%10.4f  %-13s ", m.effective_mass_z_kg, m.family.label.c_str()) : "";
    os << strf("  %4d %s  %-20s %-20s %9.2f %10.4f %10.4f  %s%s%s\n", m.number.number(), f.c_str(), k.c_str(), s.c_str(),
              100 * m.geometric_stiffness_share, m.effective_mass_x_kg, m.effective_mass_y_kg, fam.c_str(), zeta.c_str(),
              m.peak_point.c_str());
    if (!m.stable)
      os << strf("       unstable: omega^2 = %.4g rad^2/s^2, growth rate %.4g 1/s\n", m.omega2, std::sqrt(-m.omega2));
  }
  return os.str();
}

}  // namespace

std::string staticStressText(const std::vector<LinkStaticStress>& links, const StrengthFactors& f) {
  std::ostringstream os;
  os << strf("\nStatic stress at the equilibrium (peak per link; margin of safety MS = allowable / (factor * stress) - 1,\n"
             "factors yield %.3g and ultimate %.3g%s; docs/strength.md)\n",
             f.yield_factor, f.ultimate_factor, f.given ? ", the scene's" : ", NASA-STD-5001B's protoflight defaults");
  Table t({"link", "x_m", "face", "axial_N", "moment_N*m", "stress_MPa", "allowable_MPa", "factor", "MS", "verdict"});
  std::vector<std::string> notes;
  for (const auto& l : links) {
    const LinkStressPeak& p = l.peak;
    if (!p.recovered) {
      t.add({p.link, "-", "-", "-", "-", "-", "-", "-", "-", "-"});
      notes.push_back(p.link + ": " + p.why_not);
      continue;
    }
    const StrengthJudgement& j = l.judgement;
    t.add({p.link, strf("%.4f", p.loads.x), p.stress.face, strf("%.4g", p.loads.axial), strf("%.4g", p.loads.moment),
           strf("%.4g", 1e-6 * p.stress.equivalent),
           j.judged ? strf("%.4g (%s)", 1e-6 * j.allowable, j.criterion.c_str()) : std::string("-"),
           j.judged ? strf("%.3g", j.factor) : std::string("-"), j.judged ? strf("%.3f", j.margin) : std::string("-"),
           j.judged ? (j.pass ? "ok" : "FAIL") : "not judged"});
    if (!j.judged) notes.push_back(p.link + ": " + j.note);
  }
  os << t.text();
  for (const auto& n : notes) os << "  " << n << "\n";
  return os.str();
}

/// Each mode's peak bending stress per mm of its peak translation, a column per link.
static std::string modalStressText(const ModesReport& r) {
  if (std::none_of(r.modes.begin(), r.modes.end(), [](const ModeInfo& m) { return !m.stress_per_mm.empty(); })) return "";
  std::ostringstream os;
  os << "\nModal bending stress per mm of each mode's peak translation (MPa/mm, the link's peak: what a test level\n"
        "moving the mode's peak point 1 mm puts in each link; docs/strength.md)\n";
  std::vector<std::string> head{"mode"};
  for (const auto& l : r.static_stress) head.push_back(l.peak.link);
  Table t(head);
  for (const auto& m : r.modes) {
    if (m.stress_per_mm.empty()) continue;
    std::vector<std::string> row{std::to_string(m.number.number())};
    for (const auto& l : m.stress_per_mm) row.push_back(l.recovered ? strf("%.4g", 1e-6 * l.equivalent_pa_per_mm) : "-");
    t.add(row);
  }
  os << t.text();
  return os.str();
}

std::string formatModesText(const ModesReport& r) {
  std::ostringstream os;
  const double g = std::hypot(r.gravity[0], r.gravity[1]);
  os << r.scene_name << "  (scene: " << r.scene_source << ")\n";
  os << "Model: " << (r.spatial ? "spatial, " : "") << r.model.num_links << " links (segments:";
  for (const auto& [name, n] : r.model.link_segments)
    os << ' ' << name << ' ' << (n ? std::to_string(n) : "rigid") << (r.model.planar_links.count(name) ? " (planar)" : "");
  os << "), " << r.model.num_bodies << " bodies, " << r.model.num_dofs << " DOF; "
     << strf("mass %.3f kg (%.3f kg moving); gravity %.4g m/s^2\n", r.model.total_mass_kg, r.model.moving_mass_kg, g);
  os << strf("Static equilibrium: converged in %d Newton iteration%s, residual %.2g N*m (force scale %.3g N*m)\n\n",
            r.equilibrium_iterations, r.equilibrium_iterations == 1 ? "" : "s", r.equilibrium_residual_nm,
            r.force_scale_nm);

  os << "Joints and the torque each torquer holds (ccw +, on the outboard link)\n";
  os << strf("  %-10s %-7s %15s %17s %12s\n", "joint", "hold", "commanded_deg", "equilibrium_deg", "torque_N*m");
  for (const auto& j : r.joints)
    os << strf("  %-10s %-7s %15.3f %17.3f %12.4f\n", j.name.c_str(), j.hold.c_str(), j.commanded_rad * kRadToDeg,
              j.equilibrium_rad * kRadToDeg, j.torque_nm);

  if (!r.closures.empty()) {
    os << "\nClosures and the force each applies to the article (world frame)\n";
    os << strf("  %-14s %12s %12s%s %12s\n", "closure", "Fx_N", "Fy_N", r.spatial ? "         Fz_N" : "", "gap_m");
    for (const auto& c : r.closures)
      os << strf("  %-14s %12.4f %12.4f%s %12.1e\n", c.name.c_str(), c.fx, c.fy,
                 r.spatial ? strf(" %12.4f", c.fz).c_str() : "", c.error_m);
  }
  os << "\nLink tips at equilibrium (deflection = equilibrium minus the unbent shape)\n";
  os << strf("  %-12s %10s %10s %12s %12s%s\n", "point", "x_m", "y_m", "dx_mm", "dy_mm", r.spatial ? "        dz_mm" : "");
  for (const auto& p : r.points)
    if (p.name.size() > 4 && p.name.compare(p.name.size() - 4, 4, ".tip") == 0)
      os << strf("  %-12s %10.4f %10.4f %12.4f %12.4f%s\n", p.name.c_str(), p.x, p.y, 1e3 * p.dx, 1e3 * p.dy,
                 r.spatial ? strf(" %12.4f", 1e3 * p.dz).c_str() : "");

  os << staticStressText(r.static_stress, r.strength);
  os << modesTable(r);
  if (static_cast<int>(r.modes.size()) < r.model.num_dofs)
    os << "  (" << r.modes.size() << " of " << r.model.num_dofs << " modes shown; --modes 0 shows all)\n";
  os << discretizationText(r.discretization);
  if (r.segments_choice) os << segmentsChoiceText(*r.segments_choice);
  if (r.planarity) os << planarityText(*r.planarity);
  if (!r.modes.empty() && !r.modes.front().at_points.empty()) {
    os << "\nMode shapes at the points asked for (translation per unit modal coordinate of the mass-normalised shape,\n"
          "phi^T M phi = 1: m per (kg^1/2 m), i.e. kg^-1/2; not a displacement in metres)\n";
    Table t(r.spatial ? std::vector<std::string>{"mode", "point", "ux_per_modal_unit", "uy_per_modal_unit", "uz_per_modal_unit"}
                      : std::vector<std::string>{"mode", "point", "ux_per_modal_unit", "uy_per_modal_unit"});
    for (const auto& m : r.modes)
      for (const auto& p : m.at_points) {
        std::vector<std::string> row{std::to_string(m.number.number()), p.point, strf("%.6g", p.ux), strf("%.6g", p.uy)};
        if (r.spatial) row.push_back(strf("%.6g", p.uz));
        t.add(row);
      }
    os << t.text();
  }
  os << modalStressText(r);
  if (!r.modes.empty() && !r.modes.front().strains.empty()) {
    os << "\nModal strain over the spans asked for (mean surface strain, -c (theta_B - theta_A) / span, per unit modal\n"
          "coordinate of the mass-normalised shape: kg^-1/2)\n";
    Table t({"mode", "span", "strain_per_modal_unit"});
    for (const auto& m : r.modes)
      for (const auto& g : m.strains) t.add({std::to_string(m.number.number()), g.span, strf("%.6g", g.strain)});
    os << t.text();
  }
  os << strf("\nChecks: eigen residual %.1e, M-orthogonality error %.1e, stiffness asymmetry %.1e\n", r.eigen_residual,
            r.orthogonality_error, r.stiffness_asymmetry);
  for (const auto& w : r.warnings) os << "warning: " << w << '\n';
  os << strf("Time: build %.1f ms, equilibrium %.1f ms, linearize %.1f ms, eigen %.1f ms\n", 1e3 * r.seconds_build,
            1e3 * r.seconds_equilibrium, 1e3 * r.seconds_linearize, 1e3 * r.seconds_eigen);
  return os.str();
}

std::string discretizationText(const DiscretizationEstimate& d) {
  if (!d.available) return d.reason.empty() ? "" : "\nDiscretization error: not estimated (" + d.reason + ")\n";
  std::string ladder;
  for (int k : d.divisors) ladder += "/" + std::to_string(k) + ", ";
  std::ostringstream os;
  os << "\nDiscretization error of each frequency: the scene solved again with every flexible link's segments "
     << ladder.substr(0, ladder.size() - 2) << ", in " << strf("%.0f", 1e3 * d.seconds) << " ms\n"
     << "  richardson: the O(1/N^2) extrapolation; check: ok (observed order within 0.5 of 2), order (another order,\n"
     << "  used for the estimate), unconverged (the estimate is a lower bound); without a quartered run, unchecked\n";
  Table t({"mode", "frequency_Hz", "richardson_Hz", "est_err_%", "order", "check"});
  for (const auto& m : d.modes) {
    const double f = m.frequency_hz.back();
    t.add({std::to_string(m.number.number()), strf("%.4f", f), m.has_estimate ? strf("%.4f", m.extrapolated_hz) : "-",
           m.has_estimate ? strf("%.3g", 100 * m.estimated_relative_error) : "-",
           m.has_observed_order ? strf("%.2f", m.observed_order) : "-", m.check.empty() ? "unchecked" : m.check});
  }
  os << t.text();
  if (!d.stresses.empty()) {
    os << "Discretization error of each link's peak static stress, on the same meshes\n";
    Table st({"link", "stress_MPa", "richardson_MPa", "est_err_%", "order", "check"});
    for (const auto& s : d.stresses) {
      const ConvergenceMode& m = s.ladder;
      st.add({s.link, strf("%.6g", 1e-6 * m.frequency_hz.back()), m.has_estimate ? strf("%.6g", 1e-6 * m.extrapolated_hz) : "-",
              m.has_estimate ? strf("%.3g", 100 * m.estimated_relative_error) : "-",
              m.has_observed_order ? strf("%.2f", m.observed_order) : "-", m.check.empty() ? "unchecked" : m.check});
    }
    os << st.text();
  }
  return os.str();
}

std::string segmentsChoiceText(const SegmentsChoice& c) {
  std::ostringstream os;
  os << strf("\nTarget error %g (relative, each frequency): %d segments per flexible link, chosen in %.0f ms\n", c.target,
             c.segments, 1e3 * c.seconds);
  Table t({"segments", "worst_est_err_%", "mode", "check", "solve_ms", "target"});
  for (const auto& l : c.ladder)
    t.add({std::to_string(l.segments), std::isfinite(l.worst_error) ? strf("%.3g", 100 * l.worst_error) : "-",
           l.worst_mode ? std::to_string(l.worst_mode->number()) : "-", l.worst_check.empty() ? "-" : l.worst_check,
           strf("%.1f", 1e3 * l.seconds), l.met ? "met" : "-"});
  return os.str() + t.text();
}

std::string formatConvergenceText(const ConvergenceStudy& c) {
  std::ostringstream os;
  os << c.scene_name << "  (scene: " << c.scene_source << ")\n";
  os << "Discretization study: every flexible link with N segments (rigid links unchanged).\n\n";
  os << strf("  %8s %6s %12s\n", "segments", "DOF", "time_ms");
  for (const auto& run : c.runs) os << strf("  %8d %6d %12.2f\n", run.segments, run.num_dofs, 1e3 * run.seconds);
  os << "\nFrequency (Hz) of each mode against segments per link\n  mode";
  for (const auto& run : c.runs) os << strf(" %11s", ("N=" + std::to_string(run.segments)).c_str());
  os << strf(" %12s %8s %12s  %s\n", "richardson", "order", "est_err_%", "check");
  for (const auto& m : c.modes) {
    os << strf("  %4d", m.number.number());
    for (std::size_t k = 0; k < c.runs.size(); ++k) {
      const double f = k < m.frequency_hz.size() ? m.frequency_hz[k] : NAN;
      if (std::isfinite(f)) os << strf(" %11.5f", f);
      else os << strf(" %11s", "-");
    }
    // The mode's record (convergenceModeFields), as converge.json and converge.csv hold it.
    const auto rec = fieldsJson(convergenceModeFields(), m, [](const auto&) { return true; });
    const auto cell = [&rec](const char* key, int width, int precision, double scale) {
      return rec[key].is_number() ? strf(" %*.*f", width, precision, scale * rec[key].get<double>()) : strf(" %*s", width, "-");
    };
    os << cell("richardson_hz", 12, 5, 1) << cell("observed_order", 8, 2, 1) << cell("estimated_relative_error", 12, 4, 100)
       << "  "
       << (rec["check"] == "unchecked" ? std::string("-") : rec["check"].get<std::string>()) << '\n';
  }
  os << "\nEstimated error (%) of each run against the Richardson value: what N segments cost in accuracy\n  mode";
  for (const auto& run : c.runs) os << strf(" %11s", ("N=" + std::to_string(run.segments)).c_str());
  os << "\n";
  for (const auto& m : c.modes) {
    if (!m.has_estimate) continue;
    os << strf("  %4d", m.number.number());
    for (std::size_t k = 0; k < c.runs.size(); ++k) {
      const double f = k < m.frequency_hz.size() ? m.frequency_hz[k] : NAN;
      if (std::isfinite(f)) os << strf(" %11.4f", 100 * (f - m.extrapolated_hz) / m.extrapolated_hz);
      else os << strf(" %11s", "-");
    }
    os << "\n";
  }
  os << "\nrichardson: f_N + (f_N - f_N/2)/(2^2 - 1), assuming the discretization's O(1/N^2) error;\n"
        "order: observed log2((f_N/4 - f_N/2)/(f_N/2 - f_N)) from the three finest runs;\n"
        "est_err_%: |f_N - richardson| / richardson at the finest N, in percent;\n"
        "check: ok = observed order within 0.5 of 2, so richardson and est_err_% hold; order = converging\n"
        "at another order p > 0.5, est_err_% = |f_N - f_N/2| / (2^min(p,2) - 1) / f_N; unconverged = order below\n"
        "0.5 or non-monotone (modes swapping between runs, or N far from the asymptotic range):\n"
        "est_err_% = |f_N - f_N/2| / f_N, a lower bound, and richardson is not to be trusted.\n";
  return os.str();
}

}  // namespace mmv

namespace mmv {

}  // namespace mmv
