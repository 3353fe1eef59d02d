// Strength lines of `mmvlab check` (sim/plan/check.hpp): each flexible link's static
// stress against its allowable over its factor of safety (docs/strength.md), worst over
// the scene's configuration and the configurations the holding-torque search solved,
// and its root stress in the rigid-link run of the scene's programs.
#include <algorithm>
#include <cmath>

#include "sim/core/text.hpp"
#include "sim/linear/strength_levels.hpp"
#include "sim/linear/time_response.hpp"
#include "sim/plan/check_parts.hpp"
#include "sim/scene/programs.hpp"

namespace mmv::plan {

namespace {

/// A link's stress line: `stress` (Pa, 0 with `why_not` when not recovered) judged
/// against its material's allowable over the scene's factor, `at` where and when.
CheckLine strengthLine(const ArticleSpec& article, const std::string& link, const std::string& id, const std::string& requirement,
                       double stress, const std::string& why_not, const std::string& at) {
  if (!why_not.empty()) {
    CheckLine l = makeLine("strength", id, requirement, 0, 0, "MPa", why_not, 0);
    l.verdict = Verdict::NotChecked;
    return l;
  }
  const Material& m = *article.findMaterial(article.findLink(link)->material);
  const StrengthJudgement j = judgeStress(stress, m, article.strength);
  if (!j.judged) {
    CheckLine l = makeLine("strength", id, requirement, 1e-6 * stress, 0, "MPa", at + "; " + j.note, 0);
    l.verdict = Verdict::NotChecked;
    return l;
  }
  // The factor of safety is this line's margin: it passes at MS >= 0, whatever --margin asks.
  return makeLine("strength", id, requirement, 1e-6 * stress, 1e-6 * j.allowable / j.factor, "MPa",
                  at + strf("; capacity: %s strength %.4g MPa / factor %.3g; margin of safety MS = %.3f; its margin rule: "
                            "the factor (MS >= 0), not --margin",
                            j.criterion.c_str(), 1e-6 * j.allowable, j.factor, j.margin),
                  0);
}

/// The scene moves the article (a slew, a table program, a commanded torque), beyond
/// sensing it.
bool programsMove(const ArticleScene& s) {
  bool moves = s.article.base.motion.has_value();
  for (const auto& j : s.article.joints) moves = moves || j.slew || j.torque_input;
  const auto& g = s.article.base.gimbal;
  return moves || (g && (g->yaw.slew || g->pitch.slew || g->roll.slew));
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
    const LinkStressPeak& p = worst.peak;
    out.push_back(strengthLine(in.scene.article, p.link, "stress." + p.link + ".hold",
                               p.link + (solved.empty() ? " static stress at the scene's angles"
                                                        : " static stress, worst over the held configurations"),
                               p.stress.equivalent, p.recovered ? "" : p.why_not,
                               strf("at %s, x = %.4g m (%s face)", where.c_str(), p.loads.x, p.stress.face.c_str())));
  }
  addRunStrengthLines(in, out);
  addTableStrengthLines(in, out);
}

void addTableStrengthLines(const CheckInputs& in, std::vector<CheckLine>& out) {
  const ArticleScene& scene = in.scene;
  const auto& motion = scene.article.base.motion;
  if (!motion || scene.article.base.type != BaseType::Table) return;
  std::vector<OutputSpec> outputs;
  const int axes = scene.article.model == ArticleModel::Spatial ? 3 : 2;
  StrengthOutputs strength(scene, axes, outputs);
  if (strength.stressRows() == 0) return;  // no link with an allowable and a recoverable stress: the hold lines say why
  DampingSpec damping;  // frf's default: 1 % in every mode, unless the scene says otherwise
  if (scene.damping) damping = *scene.damping;
  const LinearModel lm = buildLinearModel(scene, {{"table_x", InputKind::BaseAcceleration, "", 0}}, outputs, damping);
  strength.setStaticStress(scene, lm);
  // The program over the scene's run from rest, at simulate's sample times (as the sensor lines).
  const auto program = makeTableProgram(*motion);
  const int steps = std::max(1, static_cast<int>(std::ceil(scene.simulation.duration * scene.simulation.sample_rate_hz)));
  const double dt = scene.simulation.duration / steps;
  const Eigen::MatrixXd run = timeResponse(lm.full, [&](double t) { return Eigen::VectorXd::Constant(1, program->acceleration(t)); }, dt, steps);
  for (const auto& p : strength.runPeaks(run))
    out.push_back(strengthLine(scene.article, p.link, "stress." + p.link + ".table",
                               p.link + " stress under the table's program (flexible linear model)", p.static_pa + p.dynamic_pa, "",
                               strf("static peak %.4g MPa + the program's largest bending amplitude %.4g MPa at t = %.4g s (the flexible "
                                    "linear model over the scene's %.3g s run from rest, at simulate's samples, the resonances "
                                    "in it; the two peaks added: conservative where they fall apart)",
                                    1e-6 * p.static_pa, 1e-6 * p.dynamic_pa, static_cast<double>(p.sample) * dt,
                                    scene.simulation.duration)));
}

void addRunStrengthLines(const CheckInputs& in, std::vector<CheckLine>& out) {
  if (!in.rigid_run || !programsMove(in.scene)) return;
  for (std::size_t l = 0; l < in.rigid_run->stresses.size(); ++l) {
    if (in.scene.article.links[l].rigid) continue;  // the scene's own rigid link: as its hold line, none
    const LinkRunStress& r = in.rigid_run->stresses[l];
    out.push_back(strengthLine(
        in.scene.article, r.link, "stress." + r.link + ".run", r.link + " root stress during the scene's run (slews, table motion)",
        r.peak_pa, r.recovered ? "" : r.why_not,
        strf("rigid links through %.3g s of the scene's programs (gravity + inertia), at t = %.4g s (%s face; axial %.4g N, "
             "moment %.4g N*m); the flexible links' dynamic response is not in it: `mmvlab simulate` reports each link's "
             "peak stress along it",
             in.scene.simulation.duration, r.at_s, r.face.c_str(), r.loads.axial, r.loads.moment)));
  }
}

}  // namespace mmv::plan
