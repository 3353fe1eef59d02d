#include "sim/linear/strength_levels.hpp"

#include <algorithm>
#include <cmath>
#include <complex>

#include "article/flexible_link.hpp"
#include "sim/core/text.hpp"
#include "sim/statics/closures.hpp"
#include "sim/statics/link_stress.hpp"

namespace mmv {

StrengthOutputs::StrengthOutputs(const ArticleScene& scene, int axes, std::vector<OutputSpec>& outputs) : axes_(axes) {
  first_stress_ = outputs.size();
  for (const LinkSpec& l : scene.article.links) {
    const double limit = strengthLimit(*scene.article.findMaterial(l.material), scene.article.strength);
    const Section& sec = *scene.article.findSection(l.section);
    const bool out = scene.article.bendsOutOfPlane(l);
    if (l.rigid || !(limit > 0) || !(sectionFibreDistance(sec) > 0) || (out && !(sectionFibreDistanceOut(sec) > 0))) continue;
    Link k{l.name, outputs.size(), 0, 0, limit};
    // The root, the hinges where the model puts them (the builder's own discretization), the tip.
    const Material& mat = *scene.article.findMaterial(l.material);
    std::vector<double> xs{0.0};
    for (double x : discretizeLink(l.length, mat.density * sectionArea(sec), mat.youngs_modulus * sectionSecondMoment(sec), l.segments,
                                   l.rigid).hinge_x)
      xs.push_back(x);
    xs.push_back(l.length);
    for (double x : xs)
      for (const char* face : {"+y", "+z"}) {
        if (face[1] == 'z' && !out) continue;
        OutputSpec o{strf("stress %s@%g %s", l.name.c_str(), x, face), OutputKind::Displacement, l.name + ".root", 5, false};
        o.stress_face = face, o.stress_link = l.name, o.stress_x_m = x;
        outputs.push_back(o);
      }
    k.count = outputs.size() - k.first;
    links_.push_back(k);
  }
  first_tip_ = outputs.size();
  for (const LinkSpec& l : scene.article.links) {
    tips_.push_back(l.name + ".tip");
    tip_link_m_.push_back(l.length);
    for (int a = 0; a < axes; ++a) outputs.push_back({l.name + ".tip " + std::to_string(a), OutputKind::Displacement, l.name + ".tip", a, false});
  }
}

std::size_t StrengthOutputs::stressRows() const { return first_tip_ - first_stress_; }

void StrengthOutputs::setStaticStress(const ArticleScene& scene, const LinearModel& lm) {
  const Model& model = *lm.solved.model;
  SimTK::State st = lm.solved.equilibrium.state;  // a copied State must be realized again
  model.getSystem().realize(st, SimTK::Stage::Position);
  const std::vector<LinkStaticStress> links =
      staticLinkStress(model, scene.article, st, lm.solved.equilibrium.q, closureForces(model, lm.solved.equilibrium.closure_multipliers));
  for (auto& k : links_)
    for (std::size_t i = 0; i < scene.article.links.size(); ++i)
      if (scene.article.links[i].name == k.name && links[i].peak.recovered) k.static_pa = links[i].peak.stress.equivalent;
}

LevelStrength StrengthOutputs::hold(const Eigen::MatrixXcd& H, Eigen::Index input, double max_deflection_m, double& level,
                                    std::string& limit) const {
  const auto amplitude = [&](const Link& k) {  // the link's largest stress amplitude per unit input
    double a = 0;
    for (std::size_t r = k.first; r < k.first + k.count; ++r) a = std::max(a, std::abs(H(static_cast<Eigen::Index>(r), input)));
    return a;
  };
  for (const auto& k : links_) {
    const double per_unit = amplitude(k), room = std::max(k.limit_pa - k.static_pa, 0.0);
    if (per_unit * level > room) level = per_unit > 0 ? room / per_unit : 0.0, limit = "stress";
  }
  LevelStrength out;
  double tip_per_unit = 0;
  for (std::size_t t = 0; t < tips_.size(); ++t) {
    double sq = 0;
    for (int a = 0; a < axes_; ++a) sq += std::norm(H(static_cast<Eigen::Index>(first_tip_ + t * axes_ + a), input));
    if (std::sqrt(sq) > tip_per_unit) tip_per_unit = std::sqrt(sq), out.tip = tips_[t], out.tip_link_m = tip_link_m_[t];
  }
  if (max_deflection_m > 0 && tip_per_unit * level > max_deflection_m) level = max_deflection_m / tip_per_unit, limit = "deflection";
  out.tip_amplitude_m = tip_per_unit * level;
  double worst_use = -1;  // the link nearest its limit at the level set
  for (const auto& k : links_) {
    const double a = amplitude(k) * level, use = (k.static_pa + a) / k.limit_pa;
    if (use > worst_use) worst_use = use, out.link = k.name, out.static_pa = k.static_pa, out.amplitude_pa = a, out.limit_pa = k.limit_pa;
  }
  return out;
}

std::vector<StrengthOutputs::LinkPeak> StrengthOutputs::runPeaks(const Eigen::MatrixXd& run) const {
  std::vector<LinkPeak> out;
  for (const auto& k : links_) {
    LinkPeak p{k.name, k.static_pa, 0, k.limit_pa, 0};
    for (Eigen::Index s = 0; s < run.rows(); ++s)
      for (std::size_t r = k.first; r < k.first + k.count; ++r)
        if (std::abs(run(s, static_cast<Eigen::Index>(r))) > p.dynamic_pa) p.dynamic_pa = std::abs(run(s, static_cast<Eigen::Index>(r))), p.sample = s;
    out.push_back(p);
  }
  return out;
}

std::string StrengthOutputs::capRandom(const std::vector<double>& mean_squares, double crest, double& G) const {
  std::string bound;
  for (const auto& k : links_)
    for (std::size_t r = k.first; r < k.first + k.count; ++r) {
      const double ms = mean_squares[r - first_stress_], room = std::max(k.limit_pa - k.static_pa, 0.0);
      if (crest * std::sqrt(ms * G) > room) G = std::pow(room / crest, 2) / ms, bound = k.name;
    }
  return bound;
}

}  // namespace mmv
