#include "sim/time/run_stress.hpp"

#include <algorithm>

#include "sim/core/errors.hpp"

namespace mmv {

RunStress::RunStress(const Model& model, const ArticleSpec& article) : model_(model), article_(article) {
  for (const LinkSpec& l : article.links) {
    Link k{&l, article.findMaterial(l.material), model.findLinkAxis(l.name), {}, {}, {}};
    MMV_DEMAND(k.material != nullptr && k.axis != nullptr);
    for (const LinkSpec& other : article.links)
      if (&other != &l && other.joint == l.joint) k.branches.push_back(model.findLinkAxis(other.name));
    k.section = sectionStrength(*k.material, *article.findSection(l.section));
    k.run.link = l.name;
    k.run.material = l.material;
    k.run.root_only = l.rigid;
    k.run.limit_pa = strengthLimit(*k.material, article.strength);
    // A rigid link's root carries every load; a flexible one the loads its hinges have.
    const bool out_of_plane = model.isSpatial() && (l.rigid || article.bendsOutOfPlane(l));
    if (!(k.section.fibre > 0) || (out_of_plane && !(k.section.fibre_out > 0)))
      k.run.why_not = "its section gives no fibre distance (fibre_distance, fibre_distance_out): stress not recovered";
    else if (out_of_plane && !(k.section.shear_per_torque > 0))
      k.run.why_not = "its section gives no torsional shear (an explicit section): stress not recovered";
    k.run.recovered = k.run.why_not.empty();
    any_recovered_ = any_recovered_ || k.run.recovered;
    links_.push_back(std::move(k));
  }
}

std::vector<std::string> RunStress::columns() const {
  std::vector<std::string> out;
  for (const Link& k : links_)
    if (k.run.recovered) out.push_back(k.run.link + "_stress_pa");
  return out;
}

void RunStress::sample(double t, const SimTK::State& s, const Eigen::VectorXd& q, std::vector<double>& row) {
  if (!any_recovered_) return;
  model_.getMatter().calcMobilizerReactionForces(s, reactions_);
  for (Link& k : links_) {
    if (!k.run.recovered) continue;
    LinkStressPeak p;
    if (k.spec->rigid) {
      p.loads = rootReactionLoads(model_, *k.axis, k.branches, s, reactions_);
      p.stress = sectionStress(k.section, p.loads);
    } else {
      std::vector<SectionLoads> hinges = hingeMoments(model_, *k.axis, q);
      setReactionAxialForces(model_, *k.axis, s, reactions_, hinges);
      p = peakStress(*k.spec, k.section, hinges);
    }
    const double sigma = p.stress.equivalent;
    row.push_back(sigma);
    LinkRunStress& r = k.run;
    if (r.first_exceeded_s < 0 && r.limit_pa > 0 && sigma > r.limit_pa) r.first_exceeded_s = t;
    if (sigma > r.peak_pa || t == 0) r.peak_pa = sigma, r.at_s = t, r.loads = p.loads, r.face = p.stress.face;
  }
}

std::vector<LinkRunStress> RunStress::summary() const {
  std::vector<LinkRunStress> out;
  for (const Link& k : links_) {
    LinkRunStress r = k.run;
    if (r.recovered) r.judgement = judgeStress(r.peak_pa, *k.material, article_.strength);
    out.push_back(std::move(r));
  }
  return out;
}

}  // namespace mmv
