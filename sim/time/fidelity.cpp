#include "sim/time/fidelity.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "sim/core/errors.hpp"
#include "sim/core/integrators.hpp"
#include "sim/core/text.hpp"
#include "sim/scene/programs.hpp"

namespace mmv {

bool modalLinksAllowed(const ArticleScene& scene, std::string* why) {
  const auto no = [&](const char* reason) {
    if (why) *why = reason;
    return false;
  };
  const ArticleSpec& a = scene.article;
  if (a.model != ArticleModel::Planar) return no("the spatial model's links bend in three dimensions");
  if (!a.closures.empty()) return no("the closures close the tree");
  if (scene.shaker && scene.shaker->program) return no("the shaker's stinger closes the tree");
  if (std::none_of(a.links.begin(), a.links.end(), [](const LinkSpec& l) { return !l.rigid; }))
    return no("every link is rigid");
  return true;
}

namespace {

/// Keeps the larger of two bands with its source.
void widen(double band, const std::string& source, double& best, std::string& from) {
  if (band > best) best = band, from = source;
}

double slewBand(const std::optional<SlewSpec>& spec, double angle, bool continuous) {
  if (!spec) return 0;
  return makeSlew(*spec, angle, INFINITY, continuous).bandHz();
}

}  // namespace

double excitedBandHz(const ArticleScene& scene, std::string* from) {
  double band = 0;
  std::string source;
  try {
    const BaseSpec& base = scene.article.base;
    if (base.type == BaseType::Table && base.motion)
      widen(makeTableProgram(*base.motion)->maxFrequencyHz(), "the table's program", band, source);
    if (base.type == BaseType::Table && base.motion_z)
      widen(makeTableProgram(*base.motion_z)->maxFrequencyHz(), "the table's program across the plane", band, source);
    for (const JointSpec& j : scene.article.joints) {
      if (j.torque_input) widen(makeTableProgram(*j.torque_input)->maxFrequencyHz(), j.name + "'s torque program", band, source);
      widen(slewBand(j.slew, j.angle, j.continuous), j.name + "'s slew", band, source);
    }
    if (base.gimbal)
      for (const auto& [name, axis] : {std::pair<const char*, const GimbalAxisSpec*>{"yaw", &base.gimbal->yaw},
                                       {"pitch", &base.gimbal->pitch},
                                       {"roll", &base.gimbal->roll}})
        widen(slewBand(axis->slew, axis->angle, axis->continuous), std::string("the gimbal's ") + name + " slew", band,
              source);
  } catch (const std::invalid_argument& e) {
    throw SceneError(scene.source + ": " + e.what());
  }
  if (from) *from = source;
  return band;
}

namespace {

/// A verification companion's modes: up to 2^refinement times the run's highest
/// frequency, at least one more, within the hinges (sim/time/modal_links.hpp).
void refine(ArticleScene& scene) {
  const double factor = std::ldexp(1.0, std::min(scene.simulation.modal_refinement, 10));
  for (LinkSpec& l : scene.article.links)
    if (l.modal()) l.modes_frequency_factor = factor;
}

/// What the run integrates (the links' `modes_up_to_hz` set when the rule chooses modes).
FidelityChoice chooseFidelity(ArticleScene& scene) {
  FidelityChoice c;
  SimulationSpec& spec = scene.simulation;
  auto& links = scene.article.links;
  if (std::any_of(links.begin(), links.end(), [](const LinkSpec& l) { return l.modes > 0; })) {
    c.modal = true;
    c.reason = "links in modal coordinates as the scene's `modes:` ask";
    return c;
  }
  if (spec.fidelity == SimulationSpec::Fidelity::Segments) {
    c.reason = "every hinge its own coordinate (the segment model)";
    return c;
  }
  const auto segments = [&](const std::string& why) {
    c.reason = "every hinge its own coordinate (the segment model): " + why;
    return c;
  };
  if (std::all_of(links.begin(), links.end(), [](const LinkSpec& l) { return l.rigid; })) {
    c.reason = "rigid links only (no hinges to carry)";
    return c;
  }
  std::string why;
  if (!modalLinksAllowed(scene, &why)) return segments(why + ", which links in modal coordinates cannot carry");
  if (!spec.integrator.empty() && !integratorInfo(spec.integrator).runs_modal_links)
    return segments("the scene's integrator, " + spec.integrator +
                    ", cannot carry links in modal coordinates (cvode_bdf, cvode_adams, arkode_erk, arkode_dirk can)");
  c.band_hz = excitedBandHz(scene, &c.band_from);
  if (!std::isfinite(c.band_hz)) return segments(c.band_from + " is a trapezoidal move, whose acceleration steps excite every mode");
  c.modal = c.by_rule = true;
  c.cutoff_hz = kFidelityBandFactor * c.band_hz;
  for (LinkSpec& l : links)
    if (!l.rigid) l.modes_up_to_hz = c.cutoff_hz, l.modes_cover_release = !spec.from_equilibrium;
  c.reason = c.band_hz > 0
                 ? strf("links in modal coordinates: each link's modes up to %.4g Hz (%g x the %.4g Hz %s reaches), at "
                        "least %d",
                        c.cutoff_hz, kFidelityBandFactor, c.band_hz, c.band_from.c_str(), kFidelityMinModes)
                 : strf("links in modal coordinates: each link's first %d modes (no program moves the article)",
                        kFidelityMinModes);
  if (!spec.from_equilibrium)
    c.reason += strf(", and those the release needs (a start at rest: the modes left out carry at most %g of each "
                     "link's static response to its load at the start)",
                     kReleaseStaticShare);
  return c;
}

}  // namespace

FidelityChoice resolveFidelity(ArticleScene& scene) {
  FidelityChoice c = chooseFidelity(scene);
  SimulationSpec& spec = scene.simulation;
  if (spec.integrator.empty()) {  // none named: implicit (the hinges are stiff); CPodes and IDA hold closures
    const bool closed = !scene.article.closures.empty() || (scene.shaker && scene.shaker->program);
    spec.integrator = c.modal || (spec.absolute_tolerance > 0 && !closed) ? "cvode_bdf"
                      : spec.absolute_tolerance > 0                        ? "ida"
                                                                           : "cpodes";
    c.reason += ", under " + spec.integrator + " (the scene names no integrator)";
  }
  if (c.modal && spec.modal_refinement > 0) {
    refine(scene);
    c.reason += strf("; a verification companion: the modes up to %d times the highest frequency kept, at least one more",
                     1 << std::min(spec.modal_refinement, 10));
  }
  if (c.by_rule)
    c.reason += "; `simulation.fidelity: segments` for every hinge";
  return c;
}

}  // namespace mmv
