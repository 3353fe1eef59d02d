// `mmvlab check` on the spatial model (sim/plan/check.hpp): does the test stay planar?
// The modes report's planarity section (sim/modes/planarity.hpp) judged as check lines.
#include <algorithm>
#include <cmath>

#include "sim/core/text.hpp"
#include "sim/plan/check_parts.hpp"

namespace mmv::plan {
namespace {

/// The excitations the scene's programs apply, by the planarity report's names: the
/// table (base x, and its held coordinate), slewed joints and gimbal axes, commanded
/// torques on free joints are not among them (no held coordinate).
std::vector<std::string> sceneExcitations(const ArticleScene& s) {
  std::vector<std::string> out;
  if (s.article.base.type == BaseType::Table && s.article.base.motion) out.push_back("base x");
  for (const auto& j : s.article.joints)
    if (j.slew) out.push_back(j.name);
  if (const auto& g = s.article.base.gimbal) {
    if (g->yaw.slew) out.push_back("gimbal.yaw");
    if (g->pitch.slew) out.push_back("gimbal.pitch");
    if (g->roll.slew) out.push_back("gimbal.roll");
  }
  return out;
}

void addModeSeparationLines(const CheckInputs& in, const PlanarityReport& p, std::vector<CheckLine>& out) {
  const double zeta = in.scene.damping && in.scene.damping->kind == DampingSpec::Kind::Modal ? in.scene.damping->modal_ratio : 0.01;
  CheckLine count = makeLine("planarity", "planarity.modes", "modes in the band that leave the plane", static_cast<double>(p.others.size()), 0,
                             "modes", "", 0);
  std::string list;
  for (const auto& m : p.others) list += strf("%s%d (%.4g Hz, %s)", list.empty() ? "" : ", ", m.number.number(), m.frequency_hz, m.family.label.c_str());
  count.note = strf("%.3g-%.3g Hz: %s; %d in-plane", p.band_low_hz, p.band_high_hz, list.empty() ? "none" : list.c_str(),
                    p.in_plane_in_band) +
               (p.covers_band ? "" : strf("; modes solved only up to %.3g Hz", p.solved_up_to_hz));
  count.verdict = p.covers_band ? Verdict::Info : Verdict::Warn;
  out.push_back(count);
  for (const auto& m : p.others) {
    if (!m.nearest_in_plane) continue;
    const double spacing = std::abs(m.frequency_hz - m.nearest_hz), half_power = 2 * zeta * std::max(m.frequency_hz, m.nearest_hz);
    CheckLine l = makeLine("planarity", strf("planarity.mode%d.separation", m.number.number()),
                           strf("mode %d (%s) apart from in-plane mode %d by more than its half-power bandwidth", m.number.number(),
                                m.family.label.c_str(), m.nearest_in_plane->number()),
                           half_power, spacing, "Hz",
                           strf("%.4g and %.4g Hz (%+.2f %%)%s", m.frequency_hz, m.nearest_hz, m.separation_pct,
                                spacing < half_power ? ": one response peak hides the other; only the sensors' "
                                                       "out-of-plane axes tell them apart"
                                                     : ""),
                           0);
    makeAdvisory(l);
    out.push_back(l);
  }
}

void addResponseLines(const CheckInputs& in, const PlanarityReport& p, std::vector<CheckLine>& out) {
  const std::vector<std::string> used = sceneExcitations(in.scene);
  if (used.empty()) {
    CheckLine l = makeLine("planarity", "planarity.response", "response out of the plane under the scene's programs", 0, 0, "",
                           "the scene has no table program and no slew: `mmvlab modes` gives the ratio under every excitation", 0);
    l.verdict = Verdict::Info;
    out.push_back(l);
    return;
  }
  const double limit = in.options.max_out_of_plane_ratio;
  for (const std::string& e : used) {
    const PlanarityResponse* worst = nullptr;
    for (const auto& r : p.responses)
      if (r.excitation == e && (!worst || r.ratio > worst->ratio)) worst = &r;
    if (!worst) continue;
    const bool decoupled = worst->decoupled;
    CheckLine l = makeLine("planarity", "planarity." + e, "response out of the plane under " + e + " within the limit",
                           decoupled ? 0.0 : worst->ratio, limit, "ratio",
                           decoupled ? "decoupled: the article's symmetry keeps the motion in its plane (below 1e-9)"
                                     : strf("worst at %s: peak resonant response along the plane's normal over that in it "
                                            "(modes %d and %d, equal modal damping); above the limit the test is not planar",
                                            worst->point.c_str(), worst->out_mode.number(), worst->in_mode.number()),
                           in.options.required_margin_pct);
    makeAdvisory(l);
    out.push_back(l);
  }
}

}  // namespace

void addPlanarityLines(const CheckInputs& in, std::vector<CheckLine>& out) {
  if (!in.modes.planarity) return;
  addModeSeparationLines(in, *in.modes.planarity, out);
  addResponseLines(in, *in.modes.planarity, out);
}

}  // namespace mmv::plan
