#include "sim/modes/modal.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "sim/model/article_builder.hpp"
#include "article/beam_theory.hpp"
#include "sim/modes/system_modes.hpp"
#include "sim/statics/linearize.hpp"
#include "sim/statics/statics.hpp"
#include "support/sanitizers.hpp"
#include "support/scenes.hpp"

namespace mmv {
namespace {

// Double pendulum, equal point masses m and lengths l: omega^2 = (2 -+ sqrt 2) g / l
// (docs/sources.md section 4). The rods weigh 1e-9 of the masses: 1e-6 relative tolerance.
TEST(Modal, DoublePendulumClosedForm) {
  const double l = 0.5, m = 2.0, g = 9.81;
  const ArticleScene s = testing::chainScene(2, 2 * l, 1e-9, g, m, m);
  const auto f = solveSceneModes(s).frequencies_hz;
  ASSERT_EQ(f.size(), 2);
  const double f1 = std::sqrt((2 - std::sqrt(2.0)) * g / l) / (2 * M_PI);
  const double f2 = std::sqrt((2 + std::sqrt(2.0)) * g / l) / (2 * M_PI);
  EXPECT_NEAR(f[0] / f1, 1.0, 1e-6);
  EXPECT_NEAR(f[1] / f2, 1.0, 1e-6);
}

// A hanging uniform chain of length L: omega_n = (j_0,n / 2) sqrt(g / L), with
// j_0,n the zeros of J0 (computed here from std::cyl_bessel_j). A chain of n rigid
// links approaches it as O(1/n^2); with n = 64 the measured errors of the first three
// modes are 0.0007 %, 0.025 % and 0.11 % (tolerance 0.2 %), and each error must shrink
// when n doubles (at n = 32 they are 0.003 %, 0.10 %, 0.42 %).
TEST(Modal, HangingChainBesselZeros) {
  const double L = 2.0, g = 9.81;
  const auto j0 = findRoots([](double x) { return std::cyl_bessel_j(0.0, x); }, 0.1, 20.0, 1e-2, 3);
  ASSERT_EQ(j0.size(), 3u);
  const auto f32 = solveSceneModes(testing::chainScene(32, L, 1.0, g)).frequencies_hz;
  const auto f64 = solveSceneModes(testing::chainScene(64, L, 1.0, g)).frequencies_hz;
  for (int i = 0; i < 3; ++i) {
    const double exact = j0[i] / 2 * std::sqrt(g / L) / (2 * M_PI);
    EXPECT_NEAR(f64[i] / exact, 1.0, 2e-3) << "mode " << i + 1;
    EXPECT_LT(std::abs(f64[i] - exact), std::abs(f32[i] - exact)) << "mode " << i + 1;
  }
}

// The eigen solution of the default MMV scene: residuals and M-orthogonality near
// round-off amplified by the spread of the spectrum (omega_max^2 / omega_min^2 ~ 1e6),
// hence 1e-9; frequencies positive and ascending.
TEST(Modal, DefaultSceneResidualAndOrthogonality) {
  const ArticleScene s = loadDefaultScene();
  const auto model = buildArticleModel(s);
  const EquilibriumResult eq = solveEquilibrium(*model);
  ASSERT_TRUE(eq.converged) << eq.failure;
  const LinearizedModel lin = linearize(*model, eq.state);
  const ModalSolution sol = solveModes(lin.M, lin.K);
  const Eigen::MatrixXd& V = sol.shapes;
  const Eigen::MatrixXd R = lin.K * V - lin.M * V * sol.omega2.asDiagonal();
  for (Eigen::Index i = 0; i < V.cols(); ++i) {
    const double scale = (lin.K * V.col(i)).norm() + sol.omega2[i] * (lin.M * V.col(i)).norm();
    EXPECT_LT(R.col(i).norm() / scale, 1e-9) << "mode " << i + 1;
  }
  const Eigen::MatrixXd I = V.transpose() * lin.M * V;
  EXPECT_LT((I - Eigen::MatrixXd::Identity(V.cols(), V.cols())).cwiseAbs().maxCoeff(), 1e-9);
  EXPECT_LT(sol.max_residual, 1e-9);
  for (Eigen::Index i = 0; i < sol.omega2.size(); ++i) {
    EXPECT_GT(sol.omega2[i], 0.0);
    if (i > 0) EXPECT_GE(sol.omega2[i], sol.omega2[i - 1]);
  }
}

// The report's article lives in 0.1-50 Hz: the default scene's lowest mode must be in
// that band, and the modes must be described (dominant link, energy shares summing to 1,
// effective masses that add up to the moving mass).
TEST(Modal, DefaultSceneReportIsComplete) {
  ModesOptions opt;
  opt.max_modes = 0;
  const ModesReport r = runModes(loadDefaultScene(), opt);
  ASSERT_EQ(static_cast<int>(r.modes.size()), r.model.num_dofs);
  EXPECT_GT(r.modes[0].frequency_hz, 0.1);
  EXPECT_LT(r.modes[0].frequency_hz, 50.0);
  double mx = 0, my = 0;
  for (const auto& m : r.modes) {
    double ke = 0, se = 0;
    for (const auto& p : m.kinetic) ke += p.fraction;
    for (const auto& p : m.strain) se += p.fraction;
    EXPECT_NEAR(ke, 1.0, 1e-12);
    EXPECT_NEAR(se, 1.0, 1e-12);
    EXPECT_FALSE(m.dominant_link_kinetic.empty());
    EXPECT_EQ(m.shape.size(), r.points.size());
    mx += m.effective_mass_x_kg;
    my += m.effective_mass_y_kg;
  }
  // Sum over all modes of L^2 = r^T M_qb^T M^-1 M_qb r: not the whole moving mass (the
  // base holds part of it), but positive and bounded by it.
  EXPECT_GT(mx, 0.0);
  EXPECT_LE(mx, r.model.moving_mass_kg * (1 + 1e-9));
  EXPECT_LE(my, r.model.moving_mass_kg * (1 + 1e-9));
}

// A pendulum whose mass is all in its tip mass: the tip mass's kinetic energy belongs
// to the link that carries it, so the link carries 100 % of the swing mode.
TEST(Modal, LumpedMassesCountWithTheLinkThatCarriesThem) {
  const ArticleScene s = testing::chainScene(1, 1.0, 1e-9, 9.81, 0.0, 2.0);
  const ModesReport r = runModes(s);
  ASSERT_EQ(r.modes.size(), 1u);
  const ModeInfo& m = r.modes[0];
  EXPECT_EQ(m.dominant_link_kinetic, "l1");
  ASSERT_FALSE(m.kinetic_by_link.empty());
  EXPECT_NEAR(m.kinetic_by_link.front().fraction, 1.0, 1e-12);
  EXPECT_EQ(m.kinetic.front().part, "l1.tip_mass");  // per part, the mass itself
  EXPECT_GT(m.kinetic.front().fraction, 1 - 1e-6);
  // Pendulum: all its stiffness is gravity's, and its frequency is sqrt(g/L).
  EXPECT_NEAR(m.geometric_stiffness_share, 1.0, 1e-9);
  EXPECT_NEAR(m.frequency_hz, std::sqrt(9.81 / 1.0) / (2 * M_PI), 1e-8);
  // Effective mass in x of a hanging point-mass pendulum is the whole mass.
  EXPECT_NEAR(m.effective_mass_x_kg, 2.0, 1e-6);
}

// An upright pendulum on a free joint is in equilibrium but unstable: the mode is
// reported as unstable with a growth rate, never as a NaN frequency.
TEST(Modal, UnstableEquilibriumIsNamed) {
  ArticleScene s = testing::chainScene(1, 1.0, 2.0, 9.81, 0.0, 1.0);
  s.article.base.direction = M_PI / 2;  // pointing up
  const ModesReport r = runModes(s);
  ASSERT_EQ(r.modes.size(), 1u);
  EXPECT_FALSE(r.modes[0].stable);
  EXPECT_LT(r.modes[0].omega2, 0.0);
  EXPECT_TRUE(std::isfinite(r.modes[0].frequency_hz));
}

// A free joint and no gravity: the arm swings freely, a rigid-body mode of zero
// frequency that round-off must not turn into "unstable" or a tiny frequency.
TEST(Modal, MechanismHasARigidBodyMode) {
  ArticleScene s = testing::cantileverScene(testing::Beam{}, 4, 0.0);
  s.article.joints[0].hold = JointHold::Free;
  const ModesReport r = runModes(s);
  ASSERT_EQ(r.modes.size(), 5u);
  EXPECT_TRUE(r.modes[0].rigid_body);
  EXPECT_TRUE(r.modes[0].stable);
  EXPECT_EQ(r.modes[0].frequency_hz, 0.0);
  for (std::size_t i = 1; i < r.modes.size(); ++i) {
    EXPECT_FALSE(r.modes[i].rigid_body);
    EXPECT_GT(r.modes[i].frequency_hz, 1.0);
  }
}

// Rigid-body modes come from the structure, not from a ratio to the stiffest mode
// (which grows as N^4 and swallowed real modes on fine meshes): a chain of free pins
// without gravity has exactly one rigid-body mode per free pin; with gravity, none
// (every pin is a pendulum); a floating (free-free) link has exactly its three planar
// mobilities; a clamped article has none.
TEST(Modal, RigidBodyModesAreTheFreeMobilities) {
  for (int n : {1, 3, 5}) {
    const ModesReport free = runModes(testing::chainScene(n, 1.0, 1.0, 0.0));
    int rigid = 0;
    for (const auto& m : free.modes) rigid += m.rigid_body;
    EXPECT_EQ(rigid, n) << n << " free pins, no gravity";
    const ModesReport hanging = runModes(testing::chainScene(n, 1.0, 1.0, 9.81));
    for (const auto& m : hanging.modes) {
      EXPECT_FALSE(m.rigid_body) << n << " pins under gravity: mode " << m.number;
      EXPECT_GT(m.frequency_hz, 0.1);
    }
  }
  ArticleScene floating = testing::cantileverScene(testing::Beam{}, 8, 0.0);
  floating.article.base.type = BaseType::Floating;
  const ModesReport f = runModes(floating);
  int rigid = 0;
  for (const auto& m : f.modes) rigid += m.rigid_body;
  EXPECT_EQ(rigid, 3);
  for (int i = 0; i < 3; ++i) EXPECT_TRUE(f.modes[i].rigid_body) << i;
  EXPECT_GT(f.modes[3].frequency_hz, 1.0);
}

// The same on fine meshes, where the old 1e-12 * max omega^2 cutoff reported real modes
// as rigid (the two-link demo's 0.6457 Hz mode at 192 segments, the default article's
// 1.336 Hz mode at 512): every mode stays flexible and matches the extrapolation of
// coarse meshes (converge's Richardson value from 32/64 segments; its own estimated
// error is below 0.02 %, so 0.05 % separates a right answer from a wrong one). The
// dense solver's absolute error, about eps * max omega^2, would be 5e-4 of the 0.6457 Hz
// mode at 512 segments; the refined low modes must not show it.
TEST(Modal, FineMeshesKeepEveryFlexibleMode) {
  struct Case {
    std::string scene;
    std::vector<int> segments;
  };
  const std::string dir = std::string(MMVLAB_SOURCE_DIR) + "/scenes/";
  // The meshes: 192, 512 and 1024 segments per link (1024: 4096 DOF, 30 s for the
  // article). Under the sanitizers 192 only: the finer meshes run the same code (the
  // partial eigensolver from 192 on) and cost 110 s there (tests/support/sanitizers.hpp).
  const std::vector<int> meshes = mmv::testing::kUnderSanitizers ? std::vector<int>{192} : std::vector<int>{192, 512, 1024};
  for (const Case& c : {Case{"two-link-demo.yaml", meshes}, Case{"mmv.yaml", meshes}}) {
    ArticleScene base = loadArticleSceneFile(dir + c.scene);
    auto firstModes = [&](int n) {
      ArticleScene s = base;
      overrideSegments(s, n);
      ModesOptions o;
      o.max_modes = 4;
      o.with_shapes = false;
      return runModes(s, o);
    };
    const ModesReport r32 = firstModes(32), r64 = firstModes(64);
    for (int n : c.segments) {
      const ModesReport fine = firstModes(n);
      EXPECT_TRUE(fine.warnings.empty()) << c.scene << " " << n << ": " << fine.warnings.front();
      for (int i = 0; i < 4; ++i) {
        const double richardson = r64.modes[i].frequency_hz + (r64.modes[i].frequency_hz - r32.modes[i].frequency_hz) / 3;
        EXPECT_FALSE(fine.modes[i].rigid_body) << c.scene << " " << n << " segments, mode " << i + 1;
        EXPECT_NEAR(fine.modes[i].frequency_hz, richardson, 5e-4 * richardson) << c.scene << " " << n << ", mode " << i + 1;
      }
    }
  }
}

// Near buckling: an upright cantilever under its own weight w buckles at Greenhill's
// length L_cr = (7.8373 E I / w)^(1/3) (Timoshenko & Gere, Theory of Elastic
// Stability, 2.9). The chain's critical length, found by bisection, is 0.067 %, 0.017 %
// and 0.004 % short of it at 16, 32 and 64 segments (O(1/N^2)), so at 64 segments 1 %
// below is stable, with gravity taking most of the stiffness, and 1 % above is reported
// unstable (not NaN) with a finite growth rate.
TEST(Modal, SelfWeightBucklingOfAnUprightColumn) {
  testing::Beam b;
  const double g = 9.81, w = b.massPerLength() * g;
  const double l_cr = std::cbrt(7.8373 * b.bendingStiffness() / w);
  auto first = [&](double length) {
    b.length = length;
    ModesOptions opt;
    opt.max_modes = 1;
    return runModes(testing::cantileverScene(b, 64, g, 90.0), opt).modes[0];
  };
  const ModeInfo below = first(0.99 * l_cr);
  EXPECT_TRUE(below.stable);
  EXPECT_LT(below.geometric_stiffness_share, -5.0);  // gravity takes most of the stiffness
  const ModeInfo above = first(1.01 * l_cr);
  EXPECT_FALSE(above.stable);
  EXPECT_LT(above.omega2, 0.0);
  EXPECT_TRUE(std::isfinite(above.omega2));
}

TEST(Modal, NonPositiveMassIsRejected) {
  Eigen::MatrixXd M = Eigen::MatrixXd::Identity(2, 2), K = Eigen::MatrixXd::Identity(2, 2);
  M(1, 1) = 0.0;
  EXPECT_THROW(solveModes(M, K), NumericalError);
  M(1, 1) = 1.0;
  M(0, 1) = M(1, 0) = 2.0;  // indefinite
  EXPECT_THROW(solveModes(M, K), NumericalError);
}

}  // namespace
}  // namespace mmv
