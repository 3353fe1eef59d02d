// Consistency: a mode's damping computed two ways. The damped eigenproblem of the
// linear model (`modes`' damping_ratio, sim/modes/damping.hpp) against the free decay
// of the nonlinear Simbody model in a time run (`simulate`), for every damping model a
// scene can name. The run starts at rest from the unloaded shape, so gravity's sag
// sets the article vibrating about its equilibrium; mode 1's coordinate
// eta_1 = phi_1^T M (q - q*) (the modal filter, exact for the linearized motion) is read
// from the run's states, and its logarithmic decrement over successive peaks
//     delta = ln(eta_k / eta_{k+1}) = 2 pi zeta / sqrt(1 - zeta^2)
// and its period 1 / (f sqrt(1 - zeta^2)) are compared with the modes' values.
// Before time runs honoured `modal_ratio` and `rayleigh`, the decay was 0 (dissipated 0 J).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <map>

#include "sim/modes/system_modes.hpp"
#include "sim/time/simulation.hpp"
#include "support/scenes.hpp"

namespace mmv {
namespace {

struct Decay {
  double decrement = 0;  ///< mean ln(eta_k / eta_{k+1}) over the peaks
  double period_s = 0;   ///< mean peak-to-peak time
  int peaks = 0;
};

/// Mode 1's free decay in a run of `scene` (started at rest, unloaded).
Decay modeOneDecay(const ArticleScene& scene, const SolvedScene& solved, double periods) {
  ArticleScene s = scene;
  const double f1 = std::sqrt(solved.modes.omega2[0]) / (2 * M_PI);
  s.simulation.from_equilibrium = false;
  s.simulation.duration = periods / f1;
  s.simulation.sample_rate_hz = 200 * f1;  // 200 samples a period: peaks found to 1e-5 by a parabola
  s.simulation.integrator = "cvode_bdf";
  s.simulation.accuracy = 1e-9;
  const SimulationResult r = simulate(s);
  EXPECT_GT(r.dissipated_j, 0.0);
  EXPECT_LT(std::abs(r.energy_balance_error_j), 1e-3 * std::max(r.dissipated_j, r.peak_kinetic_energy_j));
  // eta_1 at each sample from the coordinates the run recorded.
  const LinearizedModel& lin = solved.linearized;
  const Eigen::VectorXd w = lin.M * solved.modes.shapes.col(0);  // eta = w^T (q - q*)
  std::map<std::string, int> col;
  for (std::size_t c = 0; c < r.states.columns.size(); ++c) col[r.states.columns[c]] = static_cast<int>(c);
  std::vector<int> cols;
  for (int i : lin.dofs) {
    const Coordinate& c = solved.model->getCoordinates()[i];
    cols.push_back(col.at(c.name + (c.motion == CoordinateMotion::Rotation ? "_rad" : "_m")));
  }
  std::vector<double> t, eta;
  for (const auto& row : r.states.rows) {
    double e = 0;
    for (std::size_t a = 0; a < cols.size(); ++a)
      e += w[static_cast<Eigen::Index>(a)] * (row[cols[a]] - solved.equilibrium.q[lin.dofs[a]]);
    t.push_back(row[0]);
    eta.push_back(e);
  }
  // Peaks (local maxima above zero), refined by a parabola through three samples.
  std::vector<double> tp, ep;
  for (std::size_t k = 1; k + 1 < eta.size(); ++k) {
    if (!(eta[k] > eta[k - 1] && eta[k] >= eta[k + 1] && eta[k] > 0)) continue;
    const double a = 0.5 * (eta[k - 1] + eta[k + 1]) - eta[k], b = 0.5 * (eta[k + 1] - eta[k - 1]);
    const double x = -b / (2 * a), h = t[k + 1] - t[k];
    tp.push_back(t[k] + x * h);
    ep.push_back(eta[k] + b * x + a * x * x);
  }
  Decay d;
  d.peaks = static_cast<int>(ep.size());
  if (ep.size() < 3) return d;
  d.decrement = std::log(ep.front() / ep.back()) / double(ep.size() - 1);
  d.period_s = (tp.back() - tp.front()) / double(tp.size() - 1);
  return d;
}

struct Case {
  const char* name;
  DampingSpec damping;
};

class DampedDecay : public ::testing::TestWithParam<Case> {};

// A horizontal steel cantilever (1 m, EI 200 N*m^2; f1 8.9 Hz, sag 4.8 mm: the motion
// is linear to about 1e-3, which bounds the decrement's agreement below 2 %).
TEST_P(DampedDecay, ModeOneDecaysAtTheModesRatio) {
  const testing::Beam beam{1.0, 7800.0, 2.0e11, 1e-4, 1e-9};
  ArticleScene scene = testing::cantileverScene(beam, 8, 9.81, 0.0);
  scene.damping = GetParam().damping;
  const SolvedScene solved = solveScene(scene);
  ModesOptions opt;
  opt.max_modes = 3;
  opt.damping = scene.damping;
  const ModesReport rep = runModes(scene, opt);
  ASSERT_TRUE(rep.modes[0].has_damping);
  const double zeta = rep.modes[0].damping_ratio, f = rep.modes[0].frequency_hz;
  ASSERT_GT(zeta, 0.002);
  const Decay d = modeOneDecay(scene, solved, 12);
  ASSERT_GE(d.peaks, 10);
  const double expected = 2 * M_PI * zeta / std::sqrt(1 - zeta * zeta);
  EXPECT_NEAR(d.decrement / expected, 1.0, 0.02) << "decrement " << d.decrement << ", 2 pi zeta " << expected;
  EXPECT_NEAR(d.period_s * f * std::sqrt(1 - zeta * zeta), 1.0, 1e-3) << "period " << d.period_s << " s, f " << f << " Hz";
  std::printf("[consistency] %s: zeta %.5f, decrement %.6f vs 2 pi zeta / sqrt(1 - zeta^2) %.6f (%+.3f %%); period %+.2e\n",
              GetParam().name, zeta, d.decrement, expected, 100 * (d.decrement / expected - 1),
              d.period_s * f * std::sqrt(1 - zeta * zeta) - 1);
}

DampingSpec modal(double zeta) {
  DampingSpec d;
  d.kind = DampingSpec::Kind::Modal;
  d.modal_ratio = zeta;
  return d;
}
DampingSpec rayleigh(double alpha, double beta) {
  DampingSpec d;
  d.kind = DampingSpec::Kind::Rayleigh;
  d.alpha = alpha;
  d.beta = beta;
  return d;
}
DampingSpec hinges(double beta) {
  DampingSpec d;
  d.kind = DampingSpec::Kind::HingeViscous;
  d.hinge_beta = beta;
  return d;
}

INSTANTIATE_TEST_SUITE_P(Models, DampedDecay,
                         ::testing::Values(Case{"modal_1pct", modal(0.01)}, Case{"modal_3pct", modal(0.03)},
                                           Case{"rayleigh_mass", rayleigh(1.0, 0.0)},
                                           Case{"rayleigh_both", rayleigh(0.5, 2e-4)},
                                           Case{"hinge_dampers", hinges(4e-4)}),
                         [](const ::testing::TestParamInfo<Case>& i) { return std::string(i.param.name); });

// A link in modal coordinates (links[i].modes) carries the damping matrix too, through
// the Galerkin projection (the residual's inverse dynamics sees the force; the Newton
// Jacobian gets T^T C T): the same decrement as the modes' ratio.
TEST(DampedDecayModalLinks, AModalLinkDecaysAtTheModesRatio) {
  const testing::Beam beam{1.0, 7800.0, 2.0e11, 1e-4, 1e-9};
  ArticleScene scene = testing::cantileverScene(beam, 8, 9.81, 0.0);
  scene.damping = modal(0.02);
  const SolvedScene solved = solveScene(scene);
  scene.article.links[0].modes = 3;
  const Decay d = modeOneDecay(scene, solved, 12);
  ASSERT_GE(d.peaks, 10);
  const double expected = 2 * M_PI * 0.02 / std::sqrt(1 - 0.02 * 0.02);
  EXPECT_NEAR(d.decrement / expected, 1.0, 0.02) << "decrement " << d.decrement << ", 2 pi zeta " << expected;
  std::printf("[consistency] modal link (3 modes), modal 2 %%: decrement %.6f vs %.6f (%+.3f %%)\n", d.decrement, expected,
              100 * (d.decrement / expected - 1));
}

// Without a `damping:` the run is undamped and says so.
TEST(DampedDecayNone, AnUndampedRunSaysSo) {
  const testing::Beam beam{1.0, 7800.0, 2.0e11, 1e-4, 1e-9};
  ArticleScene scene = testing::cantileverScene(beam, 4, 9.81, 0.0);
  scene.simulation.duration = 0.2;
  const SimulationResult r = simulate(scene);
  EXPECT_EQ(r.dissipated_j, 0.0);
  EXPECT_NE(r.damping.find("none"), std::string::npos) << r.damping;
}

}  // namespace
}  // namespace mmv
