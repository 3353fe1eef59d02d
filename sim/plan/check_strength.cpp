// Strength lines of `mmvlab check` (sim/plan/check.hpp): each flexible link's static
// stress against its allowable over its factor of safety (docs/strength.md), worst over
// the scene's configuration and the configurations the holding-torque search solved.
#include "sim/core/text.hpp"
#include "sim/plan/check_parts.hpp"

namespace mmv::plan {

namespace {

/// One link's line: `worst` the largest stress over the configurations, at `where`.
CheckLine strengthLine(const ArticleSpec& article, const LinkStaticStress& worst, const std::string& where, int configurations) {
  const LinkStressPeak& p = worst.peak;
  const std::string id = "stress." + p.link + ".hold";
  const std::string requirement =
      p.link + (configurations > 1 ? " static stress, worst over the held configurations" : " static stress at the scene's angles");
  if (!p.recovered) {
    CheckLine l = makeLine("strength", id, requirement, 0, 0, "MPa", p.why_not, 0);
    l.verdict = Verdict::NotChecked;
    return l;
  }
  const Material& m = *article.findMaterial(article.findLink(p.link)->material);
  const StrengthJudgement j = judgeStress(p.stress.equivalent, m, article.strength);
  const std::string at = strf("at %s, x = %.4g m (%s face)", where.c_str(), p.loads.x, p.stress.face.c_str());
  if (!j.judged) {
    CheckLine l = makeLine("strength", id, requirement, 1e-6 * p.stress.equivalent, 0, "MPa", at + "; " + j.note, 0);
    l.verdict = Verdict::NotChecked;
    return l;
  }
  // The factor of safety is this line's margin: it passes at MS >= 0, whatever --margin asks.
  return makeLine("strength", id, requirement, 1e-6 * p.stress.equivalent, 1e-6 * j.allowable / j.factor, "MPa",
                  at + strf("; capacity: %s strength %.4g MPa / factor %.3g; margin of safety MS = %.3f; its margin rule: "
                            "the factor (MS >= 0), not --margin",
                            j.criterion.c_str(), 1e-6 * j.allowable, j.factor, j.margin),
                  0);
}

}  // namespace

void addStrengthLines(const CheckInputs& in, const std::vector<HeldStress>& solved, std::vector<CheckLine>& out) {
  const auto& own = in.modes.static_stress;
  for (std::size_t l = 0; l < own.size(); ++l) {
    if (in.scene.article.links[l].rigid) continue;  // a rigid link has no stress to recover: not a line
    LinkStaticStress worst = own[l];
    std::string where = "the scene's angles";
    for (const HeldStress& h : solved) {
      if (l >= h.links.size() || !h.links[l].peak.recovered || !worst.peak.recovered) continue;
      if (h.links[l].peak.stress.equivalent > worst.peak.stress.equivalent) worst = h.links[l], where = h.where;
    }
    out.push_back(strengthLine(in.scene.article, worst, where, 1 + static_cast<int>(solved.size())));
  }
}

}  // namespace mmv::plan
