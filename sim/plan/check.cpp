// `mmvlab check` (sim/plan/check.hpp): the scene's modes and a rigid-link run, then
// each group of lines (sim/plan/check_*.cpp), then the overall verdict.
#include "sim/plan/check.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>

#include "facility/table_programs.hpp"
#include "sim/core/progress.hpp"
#include "sim/core/text.hpp"
#include "sim/plan/check_parts.hpp"

namespace mmv {

const char* verdictName(Verdict v) {
  switch (v) {
    case Verdict::Pass: return "pass";
    case Verdict::Warn: return "warn";
    case Verdict::Fail: return "FAIL";
    case Verdict::NotChecked: return "n/a";
    case Verdict::Info: return "info";
    case Verdict::Advisory: return "advisory";
  }
  return "?";
}

void judge(CheckLine& l, double required_margin_pct) {
  l.has_capacity = l.capacity > 0 && std::isfinite(l.capacity);
  if (!l.has_capacity) {
    l.verdict = Verdict::NotChecked;
    return;
  }
  l.margin_pct = (l.capacity - l.demand) / l.capacity * 100;
  l.verdict = l.margin_pct < 0 ? Verdict::Fail : l.margin_pct < required_margin_pct ? Verdict::Warn : Verdict::Pass;
}

void makeAdvisory(CheckLine& l) {
  if (l.verdict == Verdict::Fail) l.verdict = Verdict::Advisory;
}

namespace plan {

CheckLine makeLine(const std::string& group, const std::string& id, const std::string& requirement, double demand, double capacity,
                   const std::string& unit, const std::string& note, double required_margin_pct) {
  CheckLine l;
  l.group = group;
  l.id = id;
  l.requirement = requirement;
  l.demand = demand;
  l.capacity = capacity;
  l.unit = unit;
  l.note = note;
  judge(l, required_margin_pct);
  if (!l.has_capacity && note.empty() && capacity == 0) l.note = "no capacity in the scene to check against";
  return l;
}

ArticleScene rigidCopy(const ArticleScene& scene) {
  ArticleScene r = scene;
  for (auto& l : r.article.links) l.rigid = true;
  return r;
}

namespace {

bool somethingMoves(const ArticleScene& s) {
  bool moves = s.article.base.motion.has_value() || !s.sensors.empty();
  for (const auto& j : s.article.joints) moves = moves || j.slew || j.torque_input;
  const auto& g = s.article.base.gimbal;
  return moves || (g && (g->yaw.slew || g->pitch.slew || g->roll.slew));
}

/// The time run of the rigid-link article with the scene's programs (explicit
/// integrator: the rigid model has few or no degrees of freedom).
void runRigid(CheckInputs& in) {
  if (!somethingMoves(in.scene)) return;
  if (!in.scene.article.closures.empty()) {
    in.rigid_run_skipped = "closed tree (rigid links would be over-constrained)";
    return;
  }
  ArticleScene s = in.rigid;
  s.simulation.integrator = "rk_merson";
  s.simulation.accuracy = 1e-6;
  in.rigid_run = simulate(s);
}

}  // namespace

}  // namespace plan

CheckReport runCheck(const ArticleScene& scene, const CheckOptions& options, const ModesReport* modes) {
  const auto t0 = std::chrono::steady_clock::now();
  plan::CheckInputs in{scene, options, {}, plan::rigidCopy(scene), {}, {}};
  if (modes) {
    in.modes = *modes;
  } else {
    ModesOptions mo;
    mo.with_shapes = false;
    in.modes = runModes(scene, mo);
  }
  {
    const ProgressStage stage("the rigid article's slews and table programs");
    plan::runRigid(in);
  }

  CheckReport rep;
  rep.scene_name = scene.name;
  rep.scene_source = scene.source;
  rep.overrides = scene.overrides;
  for (const auto& l : scene.article.links)
    if (!l.rigid) rep.segments = std::max(rep.segments, l.segments);
  std::optional<ProgressStage> stage(std::in_place, "torquer lines");
  std::vector<plan::HeldStress> solved;
  plan::addTorqueLines(in, rep.lines, solved);
  plan::addStrengthLines(in, solved, rep.lines);
  stage.emplace("table and mode lines");
  plan::addTableAndModeLines(in, rep.lines);
  stage.emplace("planarity lines");
  plan::addPlanarityLines(in, rep.lines);
  stage.emplace("sensor lines: the linear time responses");
  plan::addSensorLines(in, rep.lines);
  stage.emplace("shaker lines: its levels on the scene's accelerometers");
  plan::addShakerLines(in, rep.lines);
  stage.reset();
  plan::addLabLines(in, rep.lines);
  plan::addPlausibilityLines(in, rep.lines);
  const std::vector<std::string> order{"torquers", "gimbal", "strength", "table", "modes", "planarity", "sensors", "shaker", "lab",
                                        "plausibility"};
  std::stable_sort(rep.lines.begin(), rep.lines.end(), [&](const CheckLine& a, const CheckLine& b) {
    return std::find(order.begin(), order.end(), a.group) < std::find(order.begin(), order.end(), b.group);
  });
  rep.overall = Verdict::Pass;
  for (const auto& l : rep.lines) {
    if (l.verdict == Verdict::Fail) rep.overall = Verdict::Fail;
    if ((l.verdict == Verdict::Warn || l.verdict == Verdict::Advisory) && rep.overall == Verdict::Pass)
      rep.overall = Verdict::Warn;
    if (l.verdict == Verdict::NotChecked) ++rep.not_checked;
  }
  rep.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return rep;
}

}  // namespace mmv
