#pragma once
/// The model a time run integrates when the scene leaves it open (`simulation.fidelity:
/// auto`, the default of a scene file): "model only what a scene requires". A run that
/// only needs the first modes of each link should not integrate its stiff hinges.
///
/// The stated rule: each flexible link is carried by its modes (root held, the rest of
/// the article rigid, at the run's start: sim/time/modal_links.hpp) up to
/// kFidelityBandFactor times the highest frequency the scene's programs excite, and at
/// least kFidelityMinModes of them, under CVODE BDF unless the scene names an ODE
/// method. A start at rest away from the equilibrium (a release) applies the link's
/// load at once, a step that excites every mode, each with at most twice its static
/// response, which falls as 1 / omega^2 as a program's does above its band: the same
/// rule, and the link also keeps its modes until those left out carry at most
/// kReleaseStaticShare of its static response to that load (stiffness norm; weight,
/// which weights the modes too, leaves 3e-7 to 3e-4 with 4 modes on the free swing; a
/// dead load near a root needs more: docs/accuracy.md). The segment model (every hinge its own
/// coordinate) is kept, with the reason, where modal links cannot represent the run: a
/// closed tree (closures, a shaker's stinger), the spatial model, a trapezoidal move (its
/// acceleration steps excite every mode at full strength), or an integrator the scene
/// names that cannot carry them. `simulation.fidelity: segments` keeps it always; a
/// link's own `modes:` is the scene's choice and is kept as written.

#include <string>

#include "sim/scene/scene.hpp"

namespace mmv {

constexpr double kFidelityBandFactor = 10;
constexpr int kFidelityMinModes = 4;
constexpr double kReleaseStaticShare = 1e-3;

struct FidelityChoice {
  bool modal = false;      ///< links in modal coordinates (the scene's `modes:` or the rule's)
  bool by_rule = false;    ///< modal by the rule above (not the scene's `modes:`)
  double band_hz = 0;      ///< the highest frequency the programs excite (0: nothing moves the article)
  std::string band_from;   ///< which program sets it ("the table's program"), empty when none
  double cutoff_hz = 0;    ///< the rule's: each link's modes up to this (modal, by the rule)
  std::string reason;      ///< one line: what the run integrates and why
};

/// Whether the article's links can be carried in modal coordinates in a time run: a
/// planar open tree without a shaker's stinger; else false with `why` set.
bool modalLinksAllowed(const ArticleScene& scene, std::string* why = nullptr);

/// The highest frequency (Hz) the scene's programs excite in a time run: table motion,
/// joint torque programs, joint and gimbal slews (facility::Slew::bandHz); 0 when none
/// moves the article, infinity for a trapezoidal move. `from` names the program that
/// sets it. Throws SceneError for a program the facility refuses (as the run would).
double excitedBandHz(const ArticleScene& scene, std::string* from = nullptr);

/// Applies the scene's fidelity to `scene` (its links' `modes_up_to_hz`; the integrator
/// when the scene names none: CVODE BDF for modal links, else CPodes, or with an
/// absolute tolerance CVODE BDF or IDA on a closed tree; a verification companion's
/// modes, SimulationSpec::modal_refinement) and says what was chosen and why.
FidelityChoice resolveFidelity(ArticleScene& scene);

}  // namespace mmv
