#pragma once
/// Component modes: one link (or branch) of a scene alone, with the discretization
/// it has in the scene, under a boundary condition the user picks, without gravity
/// (as component modes are classically computed, and as the MMV report's TREETOPS run
/// did). Each mode is printed beside the Euler-Bernoulli closed form for the same
/// conditions (article/beam_theory.hpp: uniform beam, tip mass and tip inertia).
///
/// Boundary conditions (root - tip): the root is clamped (the joint locked), pinned
/// (a free pin) or free (a floating root: rotation and both translations); the tip is
/// free or pinned (held across the link: the links are inextensible, so the axial
/// direction needs no constraint). Rigid-body modes of pinned or free roots are left
/// out.
///
/// On the spatial model (docs/spatial.md) a component also bends out of its plane and
/// twists. The joints are pins about the plane's normal, so a pinned root holds the
/// out-of-plane rotation and the twist as a clamp does; a pinned tip holds the point
/// along the normal too (a ball joint). Each mode's closed form is its family's: the
/// beam roots with E I_out and the tip's rotary inertia about the in-plane normal
/// (half the torquer's), or the torsion roots with G J, the section's polar inertia and
/// the tip's polar inertia about the link (half the torquer's; beam_theory.hpp).
///
/// Tip mass rules, since the report's text and its TREETOPS numbers disagree on what
/// link 1 and link 2 carried: `none`; `torquer` (the torquers at the link's tip only:
/// what the report's TREETOPS mass ratio 1.7984 for link 1 is); `outboard` (all the
/// mass outboard of the tip: torquers, links and tip masses, as a point mass: what its
/// text says); or an explicit mass and rotary inertia. A tip mass the link itself
/// carries in the scene is always included.

#include <Eigen/Dense>
#include <optional>
#include <string>
#include <vector>

#include "sim/scene/scene.hpp"

namespace mmv {

enum class ComponentBC { ClampedFree, PinnedFree, FreeFree, ClampedPinned, PinnedPinned };
enum class TipMassRule { None, Torquer, Outboard };

const char* componentBCName(ComponentBC bc);
const char* tipMassRuleName(TipMassRule rule);
/// Parses "clamped-free", ...; returns false for an unknown name.
bool parseComponentBC(const std::string& text, ComponentBC& bc);
bool parseTipMassRule(const std::string& text, TipMassRule& rule);

struct ComponentOptions {
  ComponentBC bc = ComponentBC::ClampedFree;
  TipMassRule rule = TipMassRule::Torquer;
  /// Replaces the rule when set: what stands in for the rest of the article, added (like
  /// every rule) to the link's own `tip_mass`, which is part of the link.
  std::optional<LumpedMass> explicit_tip;
  int num_modes = 4;
};

struct ComponentMode {
  double frequency_hz = 0;
  double closed_form_hz = 0;
  bool has_closed_form = false;
  /// Spatial model: in-plane, out-of-plane, torsion or mixed (planarity.hpp); the closed
  /// form is that family's (none for mixed). Empty on the planar model.
  std::string family;
};

struct ComponentResult {
  std::string link;
  ComponentBC bc = ComponentBC::ClampedFree;
  std::string tip_rule;   ///< "torquer", "outboard", "none" or "explicit".
  LumpedMass tip;         ///< the tip mass used (kg, kg*m^2), the link's own included.
  double mass_ratio = 0;  ///< mu = M_tip / (rho A L).
  double link_mass_kg = 0;
  std::vector<ComponentMode> modes;
  /// Shapes over the link's hinge angles h1..hN (columns, mass-normalised in the
  /// component), for synthesis.
  Eigen::MatrixXd hinge_shapes;
};

/// The mass at the tip of `link` under `rule` (the link's own tip mass included).
LumpedMass tipMassFor(const ArticleSpec& a, const std::string& link, TipMassRule rule);

/// Component modes of `link`. Throws SceneError for an unknown or rigid link.
ComponentResult calcComponentModes(const ArticleScene& scene, const std::string& link, const ComponentOptions& options);

/// The link alone as a scene: no gravity, root at the origin along +x, the given
/// boundary condition and tip mass. Used by calcComponentModes and the synthesis.
ArticleScene componentScene(const ArticleScene& scene, const std::string& link, ComponentBC bc, const LumpedMass& tip);

}  // namespace mmv
