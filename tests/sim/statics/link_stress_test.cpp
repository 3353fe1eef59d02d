// Stress recovery on the flexible links (sim/statics/link_stress.hpp) against closed
// forms: a cantilever under its own weight and under a tip load, a hanging rod's axial
// stress, torsion on the spatial model, the modal stress of a cantilever's first two
// modes, and the observed order of the recovered moment; each link's root moment against
// the holding torque its torquer reports (two ways of one number); the margins.
#include "sim/statics/link_stress.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "sim/modes/system_modes.hpp"
#include "support/scenes.hpp"
#include "support/spatial_scenes.hpp"

namespace mmv {
namespace {

using testing::Beam;
using testing::cantileverScene;

constexpr double kGravity = 9.81;
constexpr double kFibre = 0.01;  // m, the explicit sections' extreme fibre

// A stiff beam (tip sag / length ~ 1e-5): small-deflection theory holds to ~1e-10, so
// what remains is the recovery's own error.
Beam stiffStressBeam() {
  Beam b;
  b.length = 1.5;
  b.second_moment = 1e-6;
  return b;
}

ArticleScene withFibre(ArticleScene s) {
  s.article.sections[0].explicit_fibre_distance = kFibre;
  return s;
}

LinkStaticStress onlyLink(const ModesReport& r) {
  EXPECT_EQ(r.static_stress.size(), 1u);
  return r.static_stress.front();
}

ModesReport solve(const ArticleScene& s, int modes = 1) {
  ModesOptions o;
  o.max_modes = modes;
  o.with_shapes = false;
  return runModes(s, o);
}

/// The root's loads and stress of a one-link article.
LinkStressPeak rootPeak(const ArticleScene& s) {
  const LinkStaticStress l = onlyLink(solve(s));
  EXPECT_TRUE(l.peak.recovered) << l.peak.why_not;
  EXPECT_EQ(l.peak.loads.x, 0.0);  // a cantilever's moment peaks at its root
  return l.peak;
}

/// The stress is |N| / A + |M| c / I of the loads recovered (the section's formula).
void expectStressOfItsLoads(const LinkStressPeak& p, const Beam& b) {
  EXPECT_NEAR(p.stress.equivalent, std::abs(p.loads.axial) / b.area + std::abs(p.loads.moment) * kFibre / b.second_moment,
              1e-12 * p.stress.equivalent);
}

// Root moment rho A g L^2 / 2, stress rho A g L^2 c / (2 I): the hinges carry the outboard
// weight's moment exactly, and the root's is extrapolated from the first two: -3/4 (h /
// L)^2 of it. (The sagged link also carries a little axial force, 1e-5 of the stress.)
TEST(LinkStress, CantileverUnderItsOwnWeight) {
  const Beam b = stiffStressBeam();
  const double moment = b.massPerLength() * kGravity * b.length * b.length / 2;
  for (int n : {16, 64}) {
    const LinkStressPeak p = rootPeak(withFibre(cantileverScene(b, n, kGravity)));
    EXPECT_NEAR(std::abs(p.loads.moment) / moment - 1, -0.75 / (n * n), 1e-8) << n;
    EXPECT_NEAR(p.stress.equivalent / (moment * kFibre / b.second_moment) - 1, -0.75 / (n * n), 1e-4) << n;
    expectStressOfItsLoads(p, b);
  }
}

// Root moment P L, stress P L c / I: the moment is linear in x, so the extrapolation is
// exact at any mesh of two segments or more (one segment has one hinge, at L / 2: its
// moment is taken as constant, first order, docs/strength.md). The tip load's component
// along the sagged link (7e-4 of the stress here) is the axial part.
TEST(LinkStress, CantileverUnderATipLoad) {
  Beam b = stiffStressBeam();
  b.density = 1e-3;  // its own weight 1e-9 of the tip's
  const double tip = 20;
  for (int n : {2, 3, 8}) {
    const LinkStressPeak p = rootPeak(withFibre(cantileverScene(b, n, kGravity, 0.0, tip)));
    EXPECT_NEAR(std::abs(p.loads.moment) / (tip * kGravity * b.length), 1.0, 1e-6) << n;
    EXPECT_NEAR(p.stress.equivalent / (tip * kGravity * b.length * kFibre / b.second_moment), 1.0, 2e-3) << n;
    expectStressOfItsLoads(p, b);
  }
}

// A hanging rod with a tip mass carries its weight below each section: N(0) = (rho A L +
// m) g in tension, no bending.
TEST(LinkStress, HangingRodCarriesItsWeightInTension) {
  const Beam b = stiffStressBeam();
  const double tip = 5;
  const LinkStaticStress l = onlyLink(solve(withFibre(cantileverScene(b, 8, kGravity, -90.0, tip))));
  ASSERT_TRUE(l.peak.recovered);
  const double weight = (b.massPerLength() * b.length + tip) * kGravity;
  EXPECT_NEAR(l.peak.loads.x, 0.0, 1e-12);
  EXPECT_NEAR(l.peak.loads.axial / weight, 1.0, 1e-9);
  EXPECT_NEAR(l.peak.stress.tension * b.area / weight, 1.0, 1e-6);
  EXPECT_LT(std::abs(l.peak.loads.moment), 1e-9 * weight * b.length);
}

// The recovered root moment converges at second order: errors over four meshes halve
// the segment length and fall by 4 each time.
TEST(LinkStress, RootMomentConvergesAtSecondOrder) {
  const Beam b = stiffStressBeam();
  const double exact = b.massPerLength() * kGravity * b.length * b.length / 2;
  double previous = 0;
  for (int n : {4, 8, 16, 32}) {
    const double error = std::abs(std::abs(rootPeak(withFibre(cantileverScene(b, n, kGravity))).loads.moment) - exact);
    if (previous > 0) EXPECT_NEAR(std::log2(previous / error), 2.0, 0.05) << n;
    previous = error;
  }
}

// The discretization estimate `modes` states for a stress (the scene at segments / 4 and
// / 2) against the true error of the closed form, and a stress the mesh cannot change
// (a hanging rod's pure tension) named so rather than "unconverged".
TEST(LinkStress, DiscretizationEstimateOfTheStress) {
  const Beam b = stiffStressBeam();
  const ArticleScene s = withFibre(cantileverScene(b, 16, kGravity));
  const ModesReport r = solve(s, 2);
  const DiscretizationEstimate d = estimateDiscretization(s, r);
  ASSERT_EQ(d.stresses.size(), 1u);
  const ConvergenceMode& m = d.stresses[0].ladder;
  EXPECT_EQ(m.check, "ok");
  EXPECT_NEAR(m.observed_order, 2.0, 0.05);
  const double exact = b.massPerLength() * kGravity * b.length * b.length * kFibre / (2 * b.second_moment);
  const double truth = std::abs(r.static_stress[0].peak.stress.equivalent - exact) / exact;
  EXPECT_NEAR(m.estimated_relative_error / truth, 1.0, 0.02);
  const ArticleScene hanging = withFibre(cantileverScene(b, 8, kGravity, -90.0, 5.0));
  const DiscretizationEstimate dh = estimateDiscretization(hanging, solve(hanging, 2));
  ASSERT_EQ(dh.stresses.size(), 1u);
  EXPECT_EQ(dh.stresses[0].ladder.check, "mesh-independent");
  EXPECT_EQ(dh.stresses[0].ladder.estimated_relative_error, 0.0);
}

// A tip mass offset across the plane twists a spatial cantilever by m g z: the shear at
// a round rod's surface is T R / J, and the equivalent stress sqrt(sigma^2 + 3 tau^2).
TEST(LinkStress, TorsionalShearOfARoundRod) {
  Section rod;
  rod.shape = SectionShape::RoundRod;
  rod.radius = 0.02;  // stiff and light: the tip turns 4e-4 rad, so the torque about the link is m g z to 1e-7
  const double mass = 2, z = 0.1, length = 1;
  ArticleScene s = testing::spatialCantilever(rod, 1.0, 2e11, 8e10, length, 8, mass);
  s.gravity = {0, -kGravity, 0};
  s.article.links[0].tip_mass->offset = {0, z};
  const LinkStaticStress l = onlyLink(solve(s));
  ASSERT_TRUE(l.peak.recovered) << l.peak.why_not;
  const double j = M_PI * std::pow(rod.radius, 4) / 2;
  EXPECT_NEAR(std::abs(l.peak.loads.torsion), mass * kGravity * z, 1e-6 * mass * kGravity * z);
  EXPECT_NEAR(l.peak.stress.shear, std::abs(l.peak.loads.torsion) * rod.radius / j, 1e-12 * l.peak.stress.shear);
  const double sigma = std::max(std::abs(l.peak.stress.tension), std::abs(l.peak.stress.compression));
  EXPECT_NEAR(l.peak.stress.equivalent, std::hypot(sigma, std::sqrt(3.0) * l.peak.stress.shear), 1e-9 * sigma);
}

// A clamped-free beam's mode n, phi = cosh bx - cos bx - s (sinh bx - sin bx): per unit tip
// displacement (|phi(L)| = 2) its largest bending moment is E I max|phi''| / 2, the
// stress E c max|phi''| / 2 per metre. The tip moves most, so the modal stress per mm of
// peak translation is that / 1000.
TEST(LinkStress, ModalStressOfACantileverAgainstItsCurvature) {
  const Beam b;
  ArticleScene s = withFibre(cantileverScene(b, 64, 0.0));
  ModesOptions o;
  o.max_modes = 2;
  o.with_shapes = false;
  const ModesReport r = runModes(s, o);
  ASSERT_EQ(r.modes.size(), 2u);
  const double beta_l[] = {1.87510407, 4.69409113};
  for (int i = 0; i < 2; ++i) {
    const double bl = beta_l[i], beta = bl / b.length;
    const double sig = (std::cosh(bl) + std::cos(bl)) / (std::sinh(bl) + std::sin(bl));
    double curvature = 0;  // max |phi''| / beta^2 over the beam
    for (int k = 0; k <= 4000; ++k) {
      const double x = bl * k / 4000.0;
      curvature = std::max(curvature, std::abs(std::cosh(x) + std::cos(x) - sig * (std::sinh(x) + std::sin(x))));
    }
    const double per_mm = b.youngs * kFibre * beta * beta * curvature / 2 / 1000;
    const ModeInfo& m = r.modes[i];
    ASSERT_EQ(m.peak_point, "link1.tip");
    ASSERT_EQ(m.stress_per_mm.size(), 1u);
    ASSERT_TRUE(m.stress_per_mm[0].recovered);
    EXPECT_NEAR(m.stress_per_mm[0].equivalent_pa_per_mm / per_mm, 1.0, 2e-3) << "mode " << i + 1;
  }
}

// Two ways of one number: the moment a link's root carries (extrapolated from its hinges)
// is the torque its torquer holds (the statics' generalized force), to O(h^2).
TEST(LinkStress, RootMomentIsTheHoldingTorque) {
  ArticleScene s = loadDefaultScene();
  overrideSegments(s, 32);
  SolvedScene solved = solveScene(s);
  const Model& model = *solved.model;
  SimTK::State eqs = solved.equilibrium.state;
  model.getSystem().realize(eqs, SimTK::Stage::Position);
  const ModesReport r = solve(s);
  for (const char* link : {"link1", "link2"}) {
    const LinkAxis* axis = model.findLinkAxis(link);
    ASSERT_NE(axis, nullptr);
    const SectionLoads root = loadsAt(hingeMoments(model, *axis, solved.equilibrium.q), 0.0);
    const std::string joint = s.article.findLink(link)->joint;
    double torque = 0;
    for (const auto& j : r.joints)
      if (j.name == joint) torque = j.torque_nm;
    ASSERT_GT(std::abs(torque), 1.0) << link;
    // The hinge spring's moment k q is the inboard side's turn; the torquer's torque on
    // its child is the opposite sense.
    EXPECT_NEAR(-root.moment / torque, 1.0, 2e-3) << link;
  }
}

TEST(LinkStress, MarginOfSafetyTakesTheGoverningAllowable) {
  Material m;
  m.name = "al";
  m.yield_strength = 240e6;
  m.ultimate_strength = 260e6;
  const StrengthFactors f;  // 1.25, 1.4
  const StrengthJudgement j = judgeStress(100e6, m, f);
  ASSERT_TRUE(j.judged);
  // yield: 240 / 125 - 1 = 0.92; ultimate: 260 / 140 - 1 = 0.857: ultimate governs.
  EXPECT_EQ(j.criterion, "ultimate");
  EXPECT_NEAR(j.margin, 260.0 / (1.4 * 100) - 1, 1e-12);
  EXPECT_TRUE(j.pass);
  const StrengthJudgement over = judgeStress(200e6, m, f);
  EXPECT_LT(over.margin, 0);
  EXPECT_FALSE(over.pass);
  // The limit the levels and runs are held to is where the margin is zero (two ways).
  const double limit = strengthLimit(m, f);
  EXPECT_NEAR(limit, 260e6 / 1.4, 1e-6);
  EXPECT_NEAR(judgeStress(limit, m, f).margin, 0.0, 1e-12);
  EXPECT_FALSE(judgeStress(limit * (1 + 1e-9), m, f).pass);
  Material none;
  none.name = "unknown";
  EXPECT_EQ(strengthLimit(none, f), 0.0);
  const StrengthJudgement n = judgeStress(100e6, none, f);
  EXPECT_FALSE(n.judged);
  EXPECT_NE(n.note.find("no allowable"), std::string::npos);
}

// A rigid link, or an explicit section without a fibre distance, is stated, not skipped.
TEST(LinkStress, WhatCannotBeRecoveredIsSaid) {
  const Beam b = stiffStressBeam();
  const LinkStaticStress plain = onlyLink(solve(cantileverScene(b, 4, kGravity)));
  EXPECT_FALSE(plain.peak.recovered);
  EXPECT_NE(plain.peak.why_not.find("fibre distance"), std::string::npos);
  const LinkStaticStress rigid = onlyLink(solve(withFibre(cantileverScene(b, 1, kGravity, 0.0, 0.0, true))));
  EXPECT_FALSE(rigid.peak.recovered);
  EXPECT_NE(rigid.peak.why_not.find("rigid"), std::string::npos);
}

// sigma = N / A -+ M c / I on a section whose fibres are stated: tension and compression
// faces, the strain through E.
TEST(LinkStress, SectionStressOfCombinedLoads) {
  SectionStrength s;
  s.area = 1e-4;
  s.second_moment = 1e-8;
  s.fibre = 0.01;
  s.youngs_modulus = 2e11;
  SectionLoads l;
  l.axial = 1000;  // 10 MPa
  l.moment = 2;    // 2 MPa at the fibre, compressing +y
  const SectionStress st = sectionStress(s, l);
  EXPECT_NEAR(st.tension, 12e6, 1e-3);
  EXPECT_NEAR(st.compression, 8e6, 1e-3);
  EXPECT_EQ(st.face, "-y");  // the stretched face: -y, as a positive moment compresses +y
  EXPECT_NEAR(st.strain, 12e6 / 2e11, 1e-18);
}

}  // namespace
}  // namespace mmv
