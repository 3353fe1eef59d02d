// Each link's stress through a time run (sim/time/run_stress.hpp) against closed forms
// and against the other ways of one number: a rigid link slewed at a stated angular
// acceleration (the inertial root moment I alpha, the centrifugal axial force), the run
// at rest against `modes`' static stress (reactions against the outboard weights), a
// flexible link's recovered root moment against its torquer's torque, and two branches
// on one joint sharing its torque.
#include "sim/time/run_stress.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "sim/model/article_builder.hpp"
#include "sim/modes/system_modes.hpp"
#include "sim/scene/scene.hpp"
#include "sim/statics/statics.hpp"
#include "sim/time/simulation.hpp"
#include "support/scenes.hpp"

namespace mmv {
namespace {

using testing::Beam;
using testing::cantileverScene;

constexpr double kRunFibre = 0.01;  // m, the explicit section's extreme fibre

std::size_t columnOf(const SimulationRecord& r, const std::string& name) {
  for (std::size_t c = 0; c < r.columns.size(); ++c)
    if (r.columns[c] == name) return c;
  ADD_FAILURE() << "no column " << name;
  return 0;
}

/// A one-link article whose joint moves `delta` rad from 0 in a triangular trapezoid
/// (the rate never reached) at `alpha` rad/s^2, from t0.
ArticleScene slewedLink(const Beam& b, int segments, bool rigid, double gravity, double delta, double alpha, double t0) {
  ArticleScene s = cantileverScene(b, segments, gravity, 0.0, 0.0, rigid);
  s.article.sections[0].explicit_fibre_distance = kRunFibre;
  SlewSpec slew;
  slew.to = delta;
  slew.start_time = t0;
  slew.trapezoidal = true;
  slew.max_rate = 100;
  slew.max_acceleration = alpha;
  s.article.joints[0].slew = slew;
  s.simulation.duration = t0 + 2 * std::sqrt(delta / alpha) + 0.05;
  s.simulation.sample_rate_hz = 400;
  return s;
}

// Gravity off: the root carries M = I_root alpha (I_root = m L^2 / 3: a rigid link's
// section has no rotary inertia in the model) and the centrifugal N = m omega^2 L / 2, omega = alpha (t - t0)
// while it accelerates. The stress column is N / A + |M| c / I at each sample, and the
// torquer's column is the same moment found another way (the joint's motion force).
TEST(RunStress, RigidLinkSlewedAtAStatedAcceleration) {
  Beam b;
  b.length = 1.2;
  const double alpha = 10, t0 = 0.1, delta = 0.5, m = b.massPerLength() * b.length;
  const double inertia = m * b.length * b.length / 3;
  const SimulationResult r = simulate(slewedLink(b, 1, true, 0.0, delta, alpha, t0));
  const std::size_t sigma = columnOf(r.record, "link1_stress_pa"), torque = columnOf(r.record, "joint1_torque_n_m");
  int checked = 0;
  for (const auto& row : r.record.rows) {
    const double t = row[0];
    if (t < t0 + 0.01 || t > t0 + std::sqrt(delta / alpha) - 0.01) continue;  // inside the acceleration phase
    const double omega = alpha * (t - t0);
    const double expected = m * omega * omega * b.length / 2 / b.area + inertia * alpha * kRunFibre / b.second_moment;
    EXPECT_NEAR(row[sigma] / expected - 1, 0, 1e-5) << "t = " << t;
    EXPECT_NEAR(row[torque] / (inertia * alpha) - 1, 0, 1e-5) << "t = " << t;
    ++checked;
  }
  EXPECT_GT(checked, 50);
  ASSERT_EQ(r.stresses.size(), 1u);
  const LinkRunStress& peak = r.stresses.front();
  EXPECT_TRUE(peak.recovered && peak.root_only);
  EXPECT_NEAR(std::abs(peak.loads.moment) / (inertia * alpha) - 1, 0, 1e-5);  // the peak is where omega is largest
  EXPECT_NEAR(peak.at_s, t0 + std::sqrt(delta / alpha), 1.0 / 400);
}

// A run that starts at the static equilibrium and stays there reads `modes`' static
// stress: the reactions' axial force is the outboard weight's, the hinges' moments the
// same springs. An inclined link with a tip mass carries both axial force and bending.
TEST(RunStress, AtRestTheRunReadsTheStaticStress) {
  Beam b;
  b.second_moment = 1e-6;
  ArticleScene s = cantileverScene(b, 12, 9.81, -60.0, 2.0);
  s.article.sections[0].explicit_fibre_distance = kRunFibre;
  s.simulation.duration = 0.02;
  const SimulationResult r = simulate(s);
  ModesOptions o;
  o.max_modes = 1;
  o.with_shapes = false;
  const LinkStaticStress st = runModes(s, o).static_stress.front();
  ASSERT_TRUE(st.peak.recovered);
  const std::size_t sigma = columnOf(r.record, "link1_stress_pa");
  EXPECT_NEAR(r.record.rows.front()[sigma] / st.peak.stress.equivalent - 1, 0, 1e-9);
  const LinkRunStress& run = r.stresses.front();
  EXPECT_NEAR(run.peak_pa / st.peak.stress.equivalent - 1, 0, 1e-5);  // the run drifts from rest at its accuracy
  EXPECT_NEAR(run.loads.axial / st.peak.loads.axial - 1, 0, 1e-5);
  EXPECT_GT(std::abs(run.loads.axial) / b.area, 1e-3 * run.peak_pa);  // the axial force counts here
  EXPECT_EQ(run.loads.x, st.peak.loads.x);
  EXPECT_EQ(run.face, st.peak.stress.face);
  EXPECT_LT(run.first_exceeded_s, 0);  // no allowable in the test material: never exceeded
  EXPECT_FALSE(run.judgement.judged);
}

// In a slew with gravity the flexible link's root moment, extrapolated from its first
// hinges, is its torquer's torque (the joint's motion force) to the recovery's second
// order; 8 segments: within 1 %.
TEST(RunStress, FlexibleRootMomentIsTheTorquersTorque) {
  Beam b;
  b.second_moment = 2e-8;
  const double alpha = 8, t0 = 0.05, delta = 0.4;
  const SimulationResult r = simulate(slewedLink(b, 8, false, 9.81, delta, alpha, t0));
  const LinkRunStress& peak = r.stresses.front();
  ASSERT_TRUE(peak.recovered);
  EXPECT_FALSE(peak.root_only);
  EXPECT_EQ(peak.loads.x, 0.0);  // a slewed cantilever's moment peaks at its root
  const std::size_t torque = columnOf(r.record, "joint1_torque_n_m");
  const auto row = std::find_if(r.record.rows.begin(), r.record.rows.end(), [&](const auto& x) { return x[0] == peak.at_s; });
  ASSERT_NE(row, r.record.rows.end());
  EXPECT_NEAR(-peak.loads.moment / (*row)[torque] - 1, 0, 0.01);
}

// MMV's rigid copy at its equilibrium: each link's root moment from the reactions is its
// joint's holding torque, and link 3's two branches (each a share) sum to joint 3's.
TEST(RunStress, BranchesOnOneJointShareItsTorque) {
  ArticleScene s = loadArticleSceneFile(std::string(MMVLAB_SOURCE_DIR) + "/scenes/mmv.yaml");
  for (auto& l : s.article.links) l.rigid = true;
  const auto model = buildArticleModel(s);
  const EquilibriumResult eq = solveEquilibrium(*model);
  ASSERT_TRUE(eq.converged);
  SimTK::State st = eq.state;
  model->getSystem().realize(st, SimTK::Stage::Acceleration);
  SimTK::Vector_<SimTK::SpatialVec> reactions;
  model->getMatter().calcMobilizerReactionForces(st, reactions);
  const auto root = [&](const std::string& link, std::vector<const LinkAxis*> branches) {
    return rootReactionLoads(*model, *model->findLinkAxis(link), branches, st, reactions).moment;
  };
  const auto held = [&](const std::string& joint) {
    for (int i = 0; i < model->getNumCoordinates(); ++i)
      if (model->getCoordinates()[i].name == joint) return -eq.generalized_force[i];
    ADD_FAILURE() << joint;
    return 0.0;
  };
  const double tau1 = held("joint1"), tau3 = held("joint3");
  EXPECT_NEAR(root("link1", {}), -tau1, 1e-8 * std::abs(tau1));
  const double a = root("link3a", {model->findLinkAxis("link3b")}), b3 = root("link3b", {model->findLinkAxis("link3a")});
  EXPECT_NEAR(a + b3, -tau3, 1e-8 * std::abs(tau3));
  EXPECT_GT(std::abs(a), 0.1 * std::abs(tau3));
  EXPECT_GT(std::abs(b3), 0.1 * std::abs(tau3));
}

}  // namespace
}  // namespace mmv
