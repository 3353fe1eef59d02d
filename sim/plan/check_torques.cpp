// Torquer and gimbal lines of `mmvlab check` (sim/plan/check.hpp): holding torque worst
// over the held angles' ranges, slew peaks from the rigid-link run, gimbal ranges.
#include <algorithm>
#include <cmath>
#include <map>

#include "sim/core/text.hpp"
#include "sim/core/units.hpp"
#include "sim/model/article_builder.hpp"
#include "sim/plan/check_parts.hpp"
#include "sim/scene/programs.hpp"
#include "sim/statics/closures.hpp"
#include "sim/statics/statics.hpp"

namespace mmv::plan {

namespace {

/// A held angle the search moves: a locked joint or a gimbal axis.
struct HeldAngle {
  std::string name;
  int coordinate = -1;  ///< in the rigid model.
  double range = 0;     ///< rad, +-.
};

double rangeOf(const ArticleSpec& a, const std::string& name) {
  if (const JointSpec* j = a.findJoint(name)) return j->range;
  const auto& g = *a.base.gimbal;
  return name == "gimbal.yaw" ? g.yaw.range : name == "gimbal.pitch" ? g.pitch.range : g.roll.range;
}

std::vector<HeldAngle> heldAngles(const Model& rigid, const ArticleSpec& a) {
  std::vector<HeldAngle> out;
  for (int i = 0; i < rigid.getNumCoordinates(); ++i) {
    const Coordinate& c = rigid.getCoordinates()[i];
    if (c.kind == CoordinateKind::Joint && c.motion == CoordinateMotion::Rotation && c.held)
      out.push_back({c.name, i, rangeOf(a, c.name)});
  }
  return out;
}

/// The scene with the held angles set to `q` (rad, one per HeldAngle).
ArticleScene withAngles(const ArticleScene& scene, const std::vector<HeldAngle>& held, const std::vector<double>& q) {
  ArticleScene s = scene;
  for (std::size_t k = 0; k < held.size(); ++k) {
    auto j = std::find_if(s.article.joints.begin(), s.article.joints.end(), [&](const JointSpec& x) { return x.name == held[k].name; });
    if (j != s.article.joints.end()) {
      j->angle = q[k];
      continue;
    }
    auto& g = *s.article.base.gimbal;
    (held[k].name == "gimbal.yaw" ? g.yaw : held[k].name == "gimbal.pitch" ? g.pitch : g.roll).angle = q[k];
  }
  return s;
}

/// The torque every held rotation applies (N*m, ccw +) at the scene's equilibrium with
/// its own links, and the links' static stress there (sim/statics/link_stress.hpp).
struct HeldEquilibrium {
  std::map<std::string, double> torques;
  std::vector<LinkStaticStress> stress;
};
HeldEquilibrium heldEquilibrium(const ArticleScene& scene) {
  const auto model = buildArticleModel(scene);
  const EquilibriumResult eq = solveEquilibrium(*model);
  if (!eq.converged) throw NumericalError("check: no static equilibrium at " + scene.name + ": " + eq.failure);
  HeldEquilibrium out;
  for (int i = 0; i < model->getNumCoordinates(); ++i) {
    const Coordinate& c = model->getCoordinates()[i];
    if (c.kind == CoordinateKind::Joint && c.motion == CoordinateMotion::Rotation && c.held)
      out.torques[c.name] = -eq.generalized_force[i];
  }
  SimTK::State s = eq.state;  // a copied State must be realized again before use
  model->getSystem().realize(s, SimTK::Stage::Position);
  out.stress = staticLinkStress(*model, scene.article, s, eq.q, closureForces(*model, eq.closure_multipliers));
  return out;
}

/// Worst |holding torque| of each held angle over the box of ranges, on the rigid model.
class RigidSearch {
 public:
  RigidSearch(const Model& rigid, std::vector<HeldAngle> held) : model_(rigid), held_(std::move(held)),
      state_(rigid.getReferenceState()), q_(rigid.getQ(rigid.getReferenceState())) {}

  /// For each held angle: the angles (rad) where its torque is largest.
  std::vector<std::vector<double>> worst(int points) {
    const std::size_t n = held_.size();
    std::vector<std::vector<double>> best(n, std::vector<double>(n, 0.0));
    std::vector<double> best_value(n, -1), q(n);
    std::vector<int> index(n, 0);
    for (;;) {  // the grid, odometer order
      for (std::size_t k = 0; k < n; ++k) q[k] = -held_[k].range + 2 * held_[k].range * index[k] / (points - 1);
      const std::vector<double> t = torques(q);
      for (std::size_t k = 0; k < n; ++k)
        if (std::abs(t[k]) > best_value[k]) best_value[k] = std::abs(t[k]), best[k] = q;
      std::size_t k = 0;
      while (k < n && ++index[k] == points) index[k++] = 0;
      if (k == n) break;
    }
    for (std::size_t k = 0; k < n; ++k) refine(k, best[k], 1.0 / (points - 1));
    return best;
  }

  std::vector<double> torques(const std::vector<double>& q) {
    for (std::size_t k = 0; k < held_.size(); ++k) q_[held_[k].coordinate] = q[k];
    model_.setQ(state_, q_);
    const Eigen::VectorXd f = model_.calcAppliedForces(state_);
    std::vector<double> t(held_.size());
    for (std::size_t k = 0; k < held_.size(); ++k) t[k] = -f[held_[k].coordinate];
    return t;
  }

 private:
  /// Pattern search on |torque k| from q, steps a fraction of each range, down to 1e-4 rad.
  void refine(std::size_t k, std::vector<double>& q, double fraction) {
    double value = std::abs(torques(q)[k]);
    for (double step = fraction; step * 2 * maxRange() > 1e-4; step *= 0.5) {
      for (bool improved = true; improved;) {
        improved = false;
        for (std::size_t j = 0; j < held_.size(); ++j)
          for (double sign : {-1.0, 1.0}) {
            std::vector<double> trial = q;
            const double r = held_[j].range;
            trial[j] = std::clamp(q[j] + sign * step * 2 * r, -r, r);
            const double v = std::abs(torques(trial)[k]);
            if (v > value * (1 + 1e-12)) value = v, q = trial, improved = true;
          }
      }
    }
  }
  double maxRange() const {
    double r = 0;
    for (const auto& h : held_) r = std::max(r, h.range);
    return r;
  }

  const Model& model_;
  std::vector<HeldAngle> held_;
  SimTK::State state_;
  Eigen::VectorXd q_;
};

/// Torques below 1e-9 N*m are round-off (an axis gravity cannot load, e.g. the gimbal's yaw).
double roundOff(double t) { return t < 1e-9 ? 0.0 : t; }

std::string anglesText(const std::vector<HeldAngle>& held, const std::vector<double>& q) {
  std::string s;
  for (std::size_t k = 0; k < held.size(); ++k) s += (k ? ", " : "") + held[k].name + strf(" %+.1f deg", q[k] * kRadToDeg);
  return s;
}

/// What a torquer's torque per kilogram must be to give `torque`: the report's
/// torque-to-weight limit, comparable with a catalogue.
std::string perKilogram(const ArticleSpec& a, const std::string& joint, double torque) {
  const JointSpec* j = a.findJoint(joint);
  if (!j || !j->torquer || !(j->torquer->mass > 0)) return "";
  return strf("; needs %.3g N*m per kg of its %.4g kg torquer", torque / j->torquer->mass, j->torquer->mass);
}

void addHoldingLines(const CheckInputs& in, std::vector<CheckLine>& out, std::vector<HeldStress>& solved) {
  const ArticleScene& scene = in.scene;
  const auto rigid_model = buildArticleModel(in.rigid);
  const std::vector<HeldAngle> held = heldAngles(*rigid_model, scene.article);
  if (held.empty()) return;
  std::string fixed_by = scene.article.closures.empty() ? "" : "a closed tree: its closures fix the configuration";
  for (const auto& j : scene.article.joints)
    if (fixed_by.empty() && j.hold != JointHold::Locked) fixed_by = j.name + " is not locked: its angle follows from equilibrium";
  const double margin = in.options.required_margin_pct;
  if (!fixed_by.empty()) {
    const auto t = heldEquilibrium(scene).torques;
    for (const auto& h : held) {
      const double tau = std::abs(t.at(h.name));
      const double cap = scene.article.torqueCapacity(h.name);
      out.push_back(makeLine(h.name.rfind("gimbal.", 0) == 0 ? "gimbal" : "torquers", "torque." + h.name + ".hold", h.name + " holding torque at the scene's angles",
                             tau, cap, "N*m", fixed_by + "; checked at the scene's configuration only" +
                             perKilogram(scene.article, h.name, tau), margin));
    }
    return;
  }
  int points = in.options.grid_points > 0 ? in.options.grid_points : held.size() > 5 ? 3 : 5;
  points = std::max(points, 2);
  RigidSearch search(*rigid_model, held);
  const auto worst = search.worst(points);
  for (std::size_t k = 0; k < held.size(); ++k) {
    const double rigid = roundOff(std::abs(search.torques(worst[k])[k]));
    HeldEquilibrium at = heldEquilibrium(withAngles(scene, held, worst[k]));
    const double tau = roundOff(std::abs(at.torques.at(held[k].name)));
    solved.push_back({anglesText(held, worst[k]) + " (" + held[k].name + "'s worst holding torque)", std::move(at.stress)});
    const double cap = scene.article.torqueCapacity(held[k].name);
    out.push_back(makeLine(held[k].name.rfind("gimbal.", 0) == 0 ? "gimbal" : "torquers", "torque." + held[k].name + ".hold",
                           held[k].name + strf(" holding torque, worst over +-%.0f deg", held[k].range * kRadToDeg), tau, cap,
                           "N*m", tau == 0 ? std::string("gravity exerts no torque about this axis anywhere in the range")
                                           : "at " + anglesText(held, worst[k]) + strf(" (rigid links: %.4g N*m)", rigid) +
                           perKilogram(scene.article, held[k].name, tau), margin));
  }
}

bool hasSlews(const ArticleSpec& a) {
  for (const auto& j : a.joints)
    if (j.slew) return true;
  const auto& g = a.base.gimbal;
  return g && (g->yaw.slew || g->pitch.slew || g->roll.slew);
}

void addSlewLines(const CheckInputs& in, std::vector<CheckLine>& out) {
  if (!hasSlews(in.scene.article)) return;
  if (!in.rigid_run) {
    CheckLine l = makeLine("torquers", "torque.run", "slew torques", 0, 0, "N*m", in.rigid_run_skipped + ": run `mmvlab simulate`", 0);
    l.verdict = Verdict::NotChecked;
    out.push_back(l);
    return;
  }
  for (const auto& t : in.rigid_run->torques)
    out.push_back(makeLine(t.joint.rfind("gimbal.", 0) == 0 ? "gimbal" : "torquers", "torque." + t.joint + ".run", t.joint + " peak torque during the scene's run",
                           roundOff(t.peak_torque_nm), t.capacity_nm, "N*m",
                           strf("rigid links through %.3g s of slews and table motion (gravity + inertia; run `mmvlab simulate` for the flexible peaks)",
                                in.scene.simulation.duration) + perKilogram(in.scene.article, t.joint, t.peak_torque_nm),
                           in.options.required_margin_pct));
}

/// Each slew against the run it is planned in: one that starts at or after the run's end
/// is never seen, one that ends after it is seen in part (before, both were accepted
/// silently). Advisory: the equipment can do it, the run does not show it.
void addSlewTimingLines(const CheckInputs& in, std::vector<CheckLine>& out) {
  const double run = in.scene.simulation.duration;
  for (const SlewTiming& t : slewTimings(in.scene.article)) {
    const std::string outside = slewOutsideRun(t, run);
    CheckLine l = makeLine(t.group, "slew." + t.axis + ".timing", t.axis + " slew ends within the run", t.end_s, run, "s",
                           outside.empty() ? strf("from %.4g s to %.4g s", t.start_s, t.end_s) : outside, 0);
    makeAdvisory(l);
    out.push_back(l);
  }
}

/// The largest |angle| an axis reaches (rad): its held angle or its slew's largest (an
/// angle program's as the reader checked it, between the samples too).
double axisReach(const GimbalAxisSpec& a) {
  if (!a.slew) return std::abs(a.angle);
  return std::max(std::abs(a.angle), makeSlew(*a.slew, a.angle, a.range, a.continuous).largestAngle());
}

/// The gimbal's angles (held and slewed) against its ranges (the reader refuses beyond);
/// an axis on a slip ring (range_deg: unlimited) has no range to hold it to.
void addGimbalRangeLines(const CheckInputs& in, std::vector<CheckLine>& out) {
  const auto& g = in.scene.article.base.gimbal;
  if (!g) return;
  const std::pair<const char*, const GimbalAxisSpec*> axes[] = {{"yaw", &g->yaw}, {"pitch", &g->pitch}, {"roll", &g->roll}};
  for (const auto& [name, axis] : axes) {
    if (axis->continuous) {
      out.push_back(makeLine("gimbal", std::string("gimbal.") + name + ".angle", std::string("gimbal ") + name + " angle", 0, 0, "deg",
                             "a slip ring (range_deg: unlimited): no travel to run out of", 0));
      out.back().verdict = Verdict::NotChecked;
      continue;
    }
    const bool program = axis->slew && !axis->slew->program_csv.empty();
    out.push_back(makeLine("gimbal", std::string("gimbal.") + name + ".angle", std::string("gimbal ") + name + " angle",
                           axisReach(*axis) * kRadToDeg, axis->range * kRadToDeg, "deg",
                           program       ? "largest of the held angle and the angle program's"
                           : axis->slew ? "largest of the held angle and the slew's end"
                                        : "held angle",
                           in.options.required_margin_pct));
    if (out.back().verdict == Verdict::Warn) out.back().verdict = Verdict::Pass;  // an angle inside its range is fine
  }
}

}  // namespace

void addTorqueLines(const CheckInputs& in, std::vector<CheckLine>& out, std::vector<HeldStress>& solved) {
  addHoldingLines(in, out, solved);
  addSlewLines(in, out);
  addSlewTimingLines(in, out);
  addGimbalRangeLines(in, out);
}

}  // namespace mmv::plan
