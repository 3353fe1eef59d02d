#include "sim/modes/components.hpp"

#include <cmath>
#include <map>

#include "sim/model/article_builder.hpp"
#include "article/beam_theory.hpp"
#include "sim/statics/linearize.hpp"
#include "sim/modes/modal.hpp"
#include "sim/modes/planarity.hpp"
#include "sim/modes/system_modes.hpp"
#include "sim/statics/statics.hpp"

namespace mmv {
namespace {

struct BCInfo {
  ComponentBC bc;
  const char* name;
  BeamEnd root, tip;
};
constexpr BCInfo kBCs[] = {
    {ComponentBC::ClampedFree, "clamped-free", BeamEnd::Clamped, BeamEnd::Free},
    {ComponentBC::PinnedFree, "pinned-free", BeamEnd::Pinned, BeamEnd::Free},
    {ComponentBC::FreeFree, "free-free", BeamEnd::Free, BeamEnd::Free},
    {ComponentBC::ClampedPinned, "clamped-pinned", BeamEnd::Clamped, BeamEnd::Pinned},
    {ComponentBC::PinnedPinned, "pinned-pinned", BeamEnd::Pinned, BeamEnd::Pinned},
};

const BCInfo& info(ComponentBC bc) {
  for (const auto& i : kBCs)
    if (i.bc == bc) return i;
  return kBCs[0];
}

double linkMass(const ArticleSpec& a, const LinkSpec& l) {
  return a.findMaterial(l.material)->density * sectionArea(*a.findSection(l.section)) * l.length;
}

/// Everything outboard of the tip of `link`: the joints on it (torquers) and, through
/// them, every link, tip mass and torquer further out.
void addOutboard(const ArticleSpec& a, const std::string& link, LumpedMass& m) {
  for (const auto& j : a.joints) {
    if (j.parent != link) continue;
    if (j.torquer) m.mass += j.torquer->mass;
    for (const auto& l : a.links) {
      if (l.joint != j.name) continue;
      m.mass += linkMass(a, l);
      if (l.tip_mass) m.mass += l.tip_mass->mass;
      addOutboard(a, l.name, m);
    }
  }
}

/// The closed-form frequencies (Hz) of the link's first `count` modes of each family
/// under boundary condition `bi`: "in-plane" (the planar model's only family),
/// "out-of-plane" and "torsion" on a link that bends out of its plane (components.hpp).
std::map<std::string, std::vector<double>> closedForms(const ArticleSpec& a, const LinkSpec& l, const BCInfo& bi,
                                                       const LumpedMass& tip, double mass_ratio, int count) {
  const Material& mat = *a.findMaterial(l.material);
  const Section& sec = *a.findSection(l.section);
  const double rho_a = mat.density * sectionArea(sec), L = l.length;
  const auto bending = [&](BeamEnd root, BeamEnd tip_end, double rotary, double second_moment) {
    std::vector<double> hz;
    for (double r : beamRoots(root, tip_end, mass_ratio, rotary / (rho_a * std::pow(L, 3)), count))
      hz.push_back(beamFrequencyHz(r, L, mat.youngs_modulus * second_moment, rho_a));
    return hz;
  };
  std::map<std::string, std::vector<double>> out;
  out["in-plane"] = bending(bi.root, bi.tip, tip.rotary_inertia, sectionSecondMoment(sec));
  if (!a.bendsOutOfPlane(l)) return out;
  // The joint pins turn about the plane's normal only: out of the plane and in torsion
  // the root is clamped unless it floats. A lumped mass is a disk about the normal
  // (article_builder.cpp): half its rotary inertia about the link and the in-plane normal.
  const BeamEnd held_root = bi.root == BeamEnd::Free ? BeamEnd::Free : BeamEnd::Clamped;
  out["out-of-plane"] = bending(held_root, bi.tip, 0.5 * tip.rotary_inertia, sectionSecondMomentOut(sec));
  const double polar_per_length = mat.density * (sectionSecondMoment(sec) + sectionSecondMomentOut(sec));
  std::vector<double>& torsion = out["torsion"];
  for (double b : torsionRoots(held_root, 0.5 * tip.rotary_inertia / (polar_per_length * L), count))
    torsion.push_back(torsionFrequencyHz(b, L, mat.shear_modulus * sectionTorsionConstant(sec), polar_per_length));
  return out;
}

}  // namespace

const char* componentBCName(ComponentBC bc) { return info(bc).name; }

const char* tipMassRuleName(TipMassRule rule) {
  switch (rule) {
    case TipMassRule::None: return "none";
    case TipMassRule::Torquer: return "torquer";
    case TipMassRule::Outboard: return "outboard";
  }
  return "?";
}

bool parseComponentBC(const std::string& text, ComponentBC& bc) {
  for (const auto& i : kBCs)
    if (text == i.name) {
      bc = i.bc;
      return true;
    }
  return false;
}

bool parseTipMassRule(const std::string& text, TipMassRule& rule) {
  for (TipMassRule r : {TipMassRule::None, TipMassRule::Torquer, TipMassRule::Outboard})
    if (text == tipMassRuleName(r)) {
      rule = r;
      return true;
    }
  return false;
}

LumpedMass tipMassFor(const ArticleSpec& a, const std::string& link, TipMassRule rule) {
  const LinkSpec* l = a.findLink(link);
  LumpedMass m = l && l->tip_mass ? *l->tip_mass : LumpedMass{};
  if (rule == TipMassRule::Torquer) {
    for (const auto& j : a.joints)
      if (j.parent == link && j.torquer) {
        m.mass += j.torquer->mass;
        m.rotary_inertia += j.torquer->rotary_inertia;
      }
  } else if (rule == TipMassRule::Outboard) {
    addOutboard(a, link, m);
  }
  return m;
}

ArticleScene componentScene(const ArticleScene& scene, const std::string& link, ComponentBC bc, const LumpedMass& tip) {
  const LinkSpec* spec = scene.article.findLink(link);
  if (!spec) throw SceneError(scene.source + ": unknown link '" + link + "'");
  if (spec->rigid) throw SceneError(scene.source + ": link '" + link + "' is rigid: it has no component modes");
  const BCInfo& bi = info(bc);
  ArticleScene s;
  s.name = link + " alone, " + bi.name;
  s.source = scene.source;
  s.gravity = {0, 0, 0};
  s.article.materials = scene.article.materials;
  s.article.sections = scene.article.sections;
  s.article.base.type = bi.root == BeamEnd::Free ? BaseType::Floating : BaseType::Fixed;
  JointSpec j;
  j.name = "root";
  j.parent = "base";
  j.hold = bi.root == BeamEnd::Clamped ? JointHold::Locked : JointHold::Free;
  s.article.joints.push_back(j);
  s.article.model = scene.article.model;
  s.article.lock_out_of_plane = scene.article.lock_out_of_plane;
  LinkSpec l = *spec;
  l.joint = "root";
  l.mount_angle = 0;
  l.tilt = 0;
  l.tip_mass.reset();
  if (tip.mass > 0 || tip.rotary_inertia > 0) l.tip_mass = tip;
  s.article.links.push_back(l);
  if (bi.tip == BeamEnd::Pinned) {
    ClosureSpec c;
    c.name = "tip";
    c.point = link + ".tip";
    c.type = ClosureType::Slider;  // held across the link, which lies along +x
    c.direction = 0;
    c.where = scene.source + " (component " + link + ")";
    s.article.closures.push_back(c);
  }
  return s;
}

ComponentResult calcComponentModes(const ArticleScene& scene, const std::string& link, const ComponentOptions& options) {
  const LinkSpec* spec = scene.article.findLink(link);
  if (!spec) throw SceneError(scene.source + ": unknown link '" + link + "'");
  ComponentResult r;
  r.link = link;
  r.bc = options.bc;
  r.tip = tipMassFor(scene.article, link, options.explicit_tip ? TipMassRule::None : options.rule);
  if (options.explicit_tip) {  // added to the link's own tip mass, as the rules are
    r.tip.mass += options.explicit_tip->mass;
    r.tip.rotary_inertia += options.explicit_tip->rotary_inertia;
  }
  r.tip_rule = options.explicit_tip ? "explicit" : tipMassRuleName(options.rule);
  r.link_mass_kg = linkMass(scene.article, *spec);
  r.mass_ratio = r.tip.mass / r.link_mass_kg;

  const ArticleScene cs = componentScene(scene, link, options.bc, r.tip);
  const auto model = buildArticleModel(cs);
  const EquilibriumResult eq = solveEquilibrium(*model);
  if (!eq.converged) throw NumericalError("component " + link + ": " + eq.failure);
  const LinearizedModel lin = linearize(*model, eq.state, eq.closure_multipliers);
  ModalSolution sol = solveModes(lin.M, lin.K, lin.Z);
  markRigidBodyModes(sol, lin, cs);
  if (model->isSpatial()) separateDegenerateFamilies(*model, lin.dofs, sol);  // a round rod's pairs

  // Hinge rows of the DOF vector, in hinge order.
  std::vector<int> hinge_rows;
  for (std::size_t a = 0; a < lin.dofs.size(); ++a)
    if (model->getCoordinates()[lin.dofs[a]].kind == CoordinateKind::Hinge) hinge_rows.push_back(static_cast<int>(a));

  const bool spatial = scene.article.model == ArticleModel::Spatial;
  const auto closed = closedForms(scene.article, *spec, info(options.bc), r.tip, r.mass_ratio, options.num_modes);
  std::map<std::string, std::size_t> next;  // the next closed form of each family
  std::vector<int> kept;
  for (Eigen::Index i = 0; i < sol.omega2.size() && static_cast<int>(kept.size()) < options.num_modes; ++i)
    if (!sol.isRigidBody(static_cast<int>(i))) kept.push_back(static_cast<int>(i));
  r.hinge_shapes.resize(hinge_rows.size(), kept.size());
  for (std::size_t k = 0; k < kept.size(); ++k) {
    ComponentMode m;
    m.frequency_hz = sol.frequencyHz(kept[k]);
    if (spatial) m.family = classifyMode(*model, lin.dofs, sol.shapes.col(kept[k])).label;
    const auto family = closed.find(spatial ? m.family : "in-plane");
    if (family != closed.end() && next[family->first] < family->second.size()) {
      m.has_closed_form = true;
      m.closed_form_hz = family->second[next[family->first]++];
    }
    r.modes.push_back(m);
    for (std::size_t h = 0; h < hinge_rows.size(); ++h) r.hinge_shapes(h, k) = sol.shapes(hinge_rows[h], kept[k]);
  }
  return r;
}

}  // namespace mmv
