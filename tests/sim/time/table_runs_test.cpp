// Time runs of a beam hanging from the base table: the energy books against the sample
// rate, and one hinge's transmissibility against the closed form.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>

#include "sim/time/simulation.hpp"
#include "support/scenes.hpp"
#include "support/time_run.hpp"

namespace mmv {
namespace {

/// The tests' slender 0.5 m beam.
testing::Beam halfMetreBeam() {
  testing::Beam beam;
  beam.length = 0.5;
  beam.second_moment = 2e-10;
  return beam;
}

/// That beam hanging from the table in `segments`, hinge dampers c = beta k.
ArticleScene dampedBeamOnTheTable(int segments, double gravity, double beta) {
  ArticleScene s = testing::cantileverScene(halfMetreBeam(), segments, gravity, -90.0);
  s.article.base.type = BaseType::Table;
  DampingSpec d;
  d.kind = DampingSpec::Kind::HingeViscous;
  d.hinge_beta = beta;
  s.damping = d;
  return s;
}

// The energy books integrate the table's work and the hinge dampers' dissipation by
// Simpson's rule with an interpolated midpoint: a 10 Hz table program sampled at 200/s
// (the power at 20 Hz, 10 samples a period) gives the work and dissipation of a 4000/s
// run to 1e-4, and its balance closes. The trapezoid on the samples alone was 3 % off
// (its (w h)^2 / 12) and warned "not accurate" whatever the tolerance.
TEST(Simulation, TheEnergyBooksDoNotDependOnTheSampleRate) {
  ArticleScene s = dampedBeamOnTheTable(2, 9.81, 0.002);
  s.article.base.motion = TableMotion::sine(1e-3, 10.0);
  s.simulation.from_equilibrium = true;
  s.simulation.duration = 1.0;
  s.simulation.integrator = "cvode_bdf";
  s.simulation.accuracy = 1e-9;
  s.simulation.sample_rate_hz = 200;
  const SimulationResult coarse = simulate(s);
  s.simulation.sample_rate_hz = 4000;
  const SimulationResult fine = simulate(s);
  ASSERT_GT(std::abs(fine.motion_work_j), 1e-4);
  ASSERT_GT(fine.dissipated_j, 1e-5);
  EXPECT_NEAR(coarse.motion_work_j / fine.motion_work_j, 1.0, 1e-4);
  EXPECT_NEAR(coarse.dissipated_j / fine.dissipated_j, 1.0, 1e-4);
  EXPECT_LT(std::abs(coarse.max_energy_balance_error_j), 1e-4 * energyScale(coarse));
  EXPECT_EQ(energyBalanceWarning(coarse), "");
}

// One DOF on the table: a rigid half-piece on a single bending hinge (spring k, damper
// c) hanging below a clamped root, no gravity. For table motion x_b the piece obeys
// I_h th'' + c th' + k th = -m (l/2) x_b'', and its tip moves x_b + l th, so the tip's
// transmissibility is 1 + (m l^2 / 2) w^2 / (k - I_h w^2 + i w c). Sine dwells below,
// near and above resonance: amplitude and phase within 1e-3 (the transient has decayed
// to below 1e-5 in the settling time).
TEST(Simulation, OneDofOnTheTableMatchesTheAnalyticTransmissibility) {
  const testing::Beam beam = halfMetreBeam();
  ArticleScene s = dampedBeamOnTheTable(1, 0.0, 0.01);
  const DampingSpec& d = *s.damping;
  const double l = beam.length / 2, m = beam.massPerLength() * l, Ih = m * l * l / 3;
  const double k = beam.bendingStiffness() / beam.length, c = d.hinge_beta * k;
  const double fn = std::sqrt(k / Ih) / (2 * M_PI);
  for (double f : {0.5 * fn, fn, 2.0 * fn}) {
    s.article.base.motion = TableMotion::sine(1e-3, f);
    SineDwellOptions o;
    o.point = "link1.tip";
    o.settle_s = 30 / (2 * M_PI * fn * (c / (2 * std::sqrt(k * Ih))));  // 30 time constants
    const SineDwellResult run = runSineDwell(s, o);
    const double w = 2 * M_PI * f;
    const std::complex<double> t = 1.0 + (m * l * l / 2) * w * w / std::complex<double>(k - Ih * w * w, w * c);
    EXPECT_NEAR(std::abs(run.transmissibility) / std::abs(t), 1.0, 1e-3) << f / fn << " fn";
    EXPECT_NEAR(std::arg(run.transmissibility / t), 0.0, 1e-3) << f / fn << " fn";
  }
}

}  // namespace
}  // namespace mmv
