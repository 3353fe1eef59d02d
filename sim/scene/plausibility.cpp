#include "sim/scene/plausibility.hpp"

#include <cmath>

#include "article/section.hpp"
#include "sim/core/text.hpp"

namespace mmv {

std::vector<std::string> scenePlausibility(const ArticleScene& scene) {
  using namespace plausible;
  const ArticleSpec& a = scene.article;
  std::vector<std::string> out;
  const auto say = [&](const std::string& key, const std::string& text) {
    out.push_back((scene.positions.file.empty() ? std::string() : scene.positions.where(key) + ": ") + text);
  };
  for (const auto& m : a.materials) {
    const std::string key = "materials." + m.name;
    if (m.density > kMaxDensity)
      say(key + ".density", strf("%s.density %.6g kg/m^3 is above any metal's: given in g/m^3, or lb/ft^3?", key.c_str(), m.density));
    if (m.density < kMinDensity)
      say(key + ".density", strf("%s.density %.6g kg/m^3 is below any structural material's: given in g/cm^3 (1.65 for 1650)?",
                                 key.c_str(), m.density));
    if (m.youngs_modulus < kMinModulus)
      say(key + ".youngs_modulus", strf("%s.youngs_modulus %.6g Pa is softer than rubber: GPa or MPa written as Pa?", key.c_str(),
                                        m.youngs_modulus));
    if (m.youngs_modulus > kMaxModulus)
      say(key + ".youngs_modulus", strf("%s.youngs_modulus %.6g Pa is stiffer than diamond: an exponent too many?", key.c_str(),
                                        m.youngs_modulus));
  }
  for (const auto& l : a.links) {
    const std::string key = l.key.empty() ? "links" : l.key;
    if (l.length > kMaxLength)
      say(key + ".length", strf("%s (%s).length %.6g m is longer than a lab can hold: given in mm or in?", key.c_str(),
                                l.name.c_str(), l.length));
    const Section* s = a.findSection(l.section);
    const Material* m = a.findMaterial(l.material);
    if (!s || !m) continue;
    if (sectionArea(*s) > kMaxArea)
      say("sections." + s->name, strf("sections.%s: area %.3g m^2 is a floor slab's: dimensions given in mm?", s->name.c_str(),
                                      sectionArea(*s)));
    const double mass = m->density * sectionArea(*s) * l.length;
    if (mass > kMaxLinkMass)
      say(key, strf("link %s weighs %.4g kg: check the units of its length, section and density", l.name.c_str(), mass));
    if (l.tip_mass && mass > 0 && l.tip_mass->mass > kMaxTipMassRatio * mass)
      say(key + ".tip_mass", strf("%s (%s).tip_mass %.4g kg is %.0f times the link's own %.4g kg: grams written as kg?",
                                  key.c_str(), l.name.c_str(), l.tip_mass->mass, l.tip_mass->mass / mass, mass));
  }
  const double g = std::hypot(scene.gravity[0], scene.gravity[1], scene.gravity[2]);
  if (g > 0 && (g < kMinGravity || g > kMaxGravity))
    say("gravity", strf("gravity %.4g m/s^2 is not a laboratory's (9.78-9.83 m/s^2): given in ft/s^2 or cm/s^2?", g));
  return out;
}

}  // namespace mmv
