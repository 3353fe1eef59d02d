#include "sim/linear/state_space.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "support/scenes.hpp"

namespace mmv {
namespace {

using cd = std::complex<double>;
using Eigen::MatrixXd;

// One DOF, m x'' + c x' + k x = f: displacement 1/(k - w^2 m + i w c), velocity i w
// times that, acceleration -w^2 times that. Both evaluations (first- and second-order
// form) to 1e-12 relative: only round-off separates them from the formula.
TEST(StateSpace, OneDofFrfMatchesTheFormula) {
  const double m = 2.0, c = 0.3, k = 50.0;
  MatrixXd M(1, 1), C(1, 1), K(1, 1), B(1, 1), I(1, 1), O(1, 1);
  M << m;
  C << c;
  K << k;
  B << 1;
  I << 1;
  O << 0;
  MatrixXd Cd(3, 1), Cv(3, 1), Ca(3, 1);
  Cd << 1, 0, 0;
  Cv << 0, 1, 0;
  Ca << 0, 0, 1;
  const StateSpace ss = secondOrderModel(M, C, K, B, Cd, Cv, Ca, MatrixXd());
  SecondOrderResponse so, modal;
  so.M = M, so.C = C, so.K = K, so.Bq = B, so.Cd = Cd, so.Cv = Cv, so.Ca = Ca, so.D = MatrixXd::Zero(3, 1);
  modal = so;
  modal.prepare();  // one DOF: any damping is proportional
  EXPECT_TRUE(modal.modal());
  for (double f : logFrequencies(0.01, 100, 57)) {
    const double w = 2 * M_PI * f;
    const cd x = 1.0 / cd(k - w * w * m, w * c);
    const cd expect[3] = {x, cd(0, w) * x, -w * w * x};
    const Eigen::MatrixXcd h1 = ss.response(w), h2 = so.response(w), h3 = modal.response(w);
    for (int r = 0; r < 3; ++r) {
      EXPECT_LT(std::abs(h1(r, 0) - expect[r]), 1e-12 * std::abs(expect[r])) << f << " " << r;
      EXPECT_LT(std::abs(h2(r, 0) - expect[r]), 1e-12 * std::abs(expect[r])) << f << " " << r;
      EXPECT_LT(std::abs(h3(r, 0) - expect[r]), 1e-12 * std::abs(expect[r])) << f << " " << r;
    }
  }
}

// Two DOF chain (ground - k1 - m1 - k2 - m2), Rayleigh damping, force on m2: the
// 2x2 inverse written out by hand (Cramer), independent of the LU used in the code.
TEST(StateSpace, TwoDofFrfMatchesCramer) {
  const double m1 = 1.0, m2 = 0.5, k1 = 100, k2 = 40, a = 0.1, b = 1e-3;
  MatrixXd M(2, 2), K(2, 2);
  M << m1, 0, 0, m2;
  K << k1 + k2, -k2, -k2, k2;
  const MatrixXd C = a * M + b * K;
  MatrixXd B(2, 1), Cd(2, 2);
  B << 0, 1;
  Cd << 1, 0, 0, 1;
  const StateSpace ss = secondOrderModel(M, C, K, B, Cd, MatrixXd(), MatrixXd(), MatrixXd());
  for (double f : logFrequencies(0.1, 50, 41)) {
    const double w = 2 * M_PI * f;
    const cd d11 = k1 + k2 - w * w * m1 + cd(0, w) * (a * m1 + b * (k1 + k2));
    const cd d12 = -k2 + cd(0, w) * (-b * k2);
    const cd d22 = k2 - w * w * m2 + cd(0, w) * (a * m2 + b * k2);
    const cd det = d11 * d22 - d12 * d12;
    const cd x1 = -d12 / det, x2 = d11 / det;  // column 2 of the inverse
    const Eigen::MatrixXcd h = ss.response(w);
    EXPECT_LT(std::abs(h(0, 0) - x1), 1e-12 * std::abs(x1)) << f;
    EXPECT_LT(std::abs(h(1, 0) - x2), 1e-12 * std::abs(x2)) << f;
  }
}

// A point-mass pendulum on the table, modal damping zeta: the absolute acceleration of
// the mass over the table's is (w0^2 + 2 i zeta w0 w) / (w0^2 - w^2 + 2 i zeta w0 w),
// the classical base-excitation transmissibility. The rod weighs 1e-9 of the mass:
// 1e-7 relative.
// Two uncoupled oscillators, displacement per unit force: the peak of 1 / (k - m w^2 +
// i c w) lies at w_n sqrt(1 - 2 zeta^2) with magnitude 1 / (2 zeta sqrt(1 - zeta^2) k).
// A 40-point grid over four decades misses it by up to 12 % in frequency; the search
// finds it to 1e-9.
TEST(StateSpace, RefinedPeaksFindTheResonanceBetweenGridPoints) {
  const double m = 1.5, k[2] = {40.0, 9000.0}, zeta[2] = {0.004, 0.02};
  SecondOrderResponse so;
  so.M = MatrixXd::Identity(2, 2) * m;
  so.K = MatrixXd::Zero(2, 2);
  so.C = MatrixXd::Zero(2, 2);
  for (int i = 0; i < 2; ++i) so.K(i, i) = k[i], so.C(i, i) = 2 * zeta[i] * std::sqrt(k[i] * m);
  so.Bq = MatrixXd::Identity(2, 2);
  so.Cd = MatrixXd::Identity(2, 2);
  so.D = MatrixXd::Zero(2, 2);
  so.prepare();
  const std::vector<double> f = logFrequencies(0.01, 100, 40);
  const PeakTable t = refinedPeaks(so, f);
  for (int i = 0; i < 2; ++i) {
    const double wn = std::sqrt(k[i] / m);
    EXPECT_NEAR(t.hz(i, i), wn * std::sqrt(1 - 2 * zeta[i] * zeta[i]) / (2 * M_PI), 1e-9 * wn / (2 * M_PI)) << i;
    EXPECT_NEAR(t.magnitude(i, i), 1 / (2 * zeta[i] * std::sqrt(1 - zeta[i] * zeta[i]) * k[i]), 1e-12 / k[i] / zeta[i]) << i;
  }
}

// A low-pass 1 / (s + 1) against itself plus 1e-3 straight through: relative to the
// peak (1) the error is 1e-3, but at 100 rad/s the response is 1e-2, so the local error
// there is 10 %.
TEST(StateSpace, LocalErrorIsRelativeToTheResponseAtThatFrequency) {
  StateSpace a;
  a.E = MatrixXd::Identity(1, 1);
  a.A = -MatrixXd::Identity(1, 1);
  a.B = MatrixXd::Identity(1, 1);
  a.C = MatrixXd::Identity(1, 1);
  a.D = MatrixXd::Zero(1, 1);
  StateSpace b = a;
  b.D(0, 0) = 1e-3;
  const std::vector<double> w = {0.01, 1.0, 10.0, 100.0};
  const ModelError e = compareResponses(a, b, w);
  EXPECT_NEAR(e.max_relative, 1e-3 * std::sqrt(1 + 0.01 * 0.01), 1e-12);  // the peak on the grid: at 0.01 rad/s
  EXPECT_NEAR(e.max_local, 1e-3 * std::sqrt(1 + 100.0 * 100.0), 1e-9);
  EXPECT_NEAR(e.max_local_hz, 100.0 / (2 * M_PI), 1e-12);
}

// The table scene with 10 modes kept: 0.25 % of the peak overall hides a reduced model
// that is off by more than the response itself near 66 Hz (an antiresonance of the full
// model the reduced one misplaces).
TEST(StateSpace, LocalErrorShowsWhatThePeakNormalizedOneHides) {
  const ArticleScene s = loadArticleSceneFile(MMVLAB_SOURCE_DIR "/scenes/mmv-table.yaml");
  const LinearModel lm = buildLinearModel(s, {{"table_x", InputKind::BaseAcceleration, "", 0}},
                                          {{"link3a.tip:x", OutputKind::Acceleration, "link3a.tip", 0, true}}, *s.damping);
  ReductionOptions o;
  o.modes = 10;
  const ReducedModel red = reduceModal(lm.full, o);
  std::vector<double> w = logFrequencies(0.01, 100, 400);
  for (double& x : w) x *= 2 * M_PI;
  const ModelError e = compareResponses(fullResponses(lm.second_order, w), red.model, w);
  EXPECT_LT(e.max_relative, 0.005);
  EXPECT_GT(e.max_local, 1.0);
  EXPECT_NEAR(e.max_local_hz, 66, 3);
}

TEST(StateSpace, PendulumOnTheTableTransmissibility) {
  const double l = 0.8, g = 9.81, zeta = 0.05;
  const ArticleScene s = testing::chainScene(1, l, 1e-9, g, 0.0, 2.0);
  DampingSpec d;
  d.modal_ratio = zeta;
  const LinearModel lm = buildLinearModel(s, {{"table_x", InputKind::BaseAcceleration, "", 0}},
                                          {{"tip_ax", OutputKind::Acceleration, "l1.tip", 0, true}}, d);
  const double w0 = std::sqrt(g / l);
  for (double f : logFrequencies(0.05, 5.0, 31)) {
    const double w = 2 * M_PI * f;
    const cd t = cd(w0 * w0, 2 * zeta * w0 * w) / cd(w0 * w0 - w * w, 2 * zeta * w0 * w);
    EXPECT_LT(std::abs(lm.full.response(w)(0, 0) - t), 1e-7 * std::abs(t)) << f;
    EXPECT_LT(std::abs(lm.second_order.response(w)(0, 0) - t), 1e-7 * std::abs(t)) << f;
  }
}

LinearModel defaultModel() {
  ArticleScene s = loadDefaultScene();
  overrideSegments(s, 8);
  DampingSpec d;
  d.modal_ratio = 0.02;
  return buildLinearModel(s, defaultInputs(), defaultOutputs(s), d);
}

TEST(StateSpace, ResidualizationKeepsEveryDcGainAndTruncationDoesNot) {
  const LinearModel lm = defaultModel();
  const Eigen::MatrixXcd h0 = lm.full.response(0.0);
  ReductionOptions o;
  o.modes = 4;
  const ReducedModel res = reduceModal(lm.full, o);
  EXPECT_TRUE(res.residualized);
  EXPECT_LT((res.model.response(0.0) - h0).cwiseAbs().maxCoeff(), 1e-10 * h0.cwiseAbs().maxCoeff());
  o.residualize = false;
  const ReducedModel trunc = reduceModal(lm.full, o);
  EXPECT_GT((trunc.model.response(0.0) - h0).cwiseAbs().maxCoeff(), 1e-3 * h0.cwiseAbs().maxCoeff());
}

// The modes a target needs, against a scan of every count: the table scene's link 3a
// response needs 7 modes for 1 % of its peak (the fewest whose reduction meets it), and
// a target no count up to the cap meets is said to be out of reach.
TEST(StateSpace, ModesForATargetAreTheFewestThatMeetIt) {
  const ArticleScene s = loadArticleSceneFile(MMVLAB_SOURCE_DIR "/scenes/mmv-table.yaml");
  const LinearModel lm = buildLinearModel(s, {{"table_x", InputKind::BaseAcceleration, "", 0}},
                                          {{"link3a.tip:x", OutputKind::Acceleration, "link3a.tip", 0, true}}, *s.damping);
  std::vector<double> w = logFrequencies(0.01, 100, 400);
  for (double& x : w) x *= 2 * M_PI;
  const std::vector<Eigen::MatrixXcd> hf = fullResponses(lm.second_order, w);
  std::vector<double> scan;  // scan[k - 1]: the error with k modes
  for (int k = 1; k <= 14; ++k) {
    ReductionOptions o;
    o.modes = k;
    scan.push_back(compareResponses(hf, reduceModal(lm.full, o).model, w).max_relative);
  }
  for (double target : {0.05, 0.01, 0.003}) {
    int fewest = 0;
    for (int k = 1; k <= 14 && !fewest; ++k)
      if (scan[k - 1] <= target) fewest = k;
    ASSERT_GT(fewest, 0) << target;
    for (int start : {2, 10}) {  // the count asked for: the search goes down or up from it
      ReductionOptions base;
      base.modes = start;
      ModelError err;
      modesForTarget(lm.full, base, hf, w, target, 14, err);
      EXPECT_TRUE(err.needed.reached) << target;
      EXPECT_EQ(err.needed.modes, fewest) << target << " from " << start;
      EXPECT_NEAR(err.needed.error, scan[fewest - 1], 1e-9 * scan[fewest - 1] + 1e-15);
    }
  }
  ReductionOptions base;
  base.modes = 3;
  ModelError err;
  modesForTarget(lm.full, base, hf, w, 1e-9, 6, err);
  EXPECT_FALSE(err.needed.reached);
  EXPECT_EQ(err.needed.modes, 6);
  EXPECT_NEAR(err.needed.error, scan[5], 1e-9 * scan[5]);
}

TEST(StateSpace, BandErrorFallsAsModesAreAdded) {
  const LinearModel lm = defaultModel();
  std::vector<double> w = logFrequencies(0.1, 60, 200);
  for (double& x : w) x *= 2 * M_PI;
  double previous = INFINITY;
  for (int k : {4, 8, 12, 16, 24}) {
    ReductionOptions o;
    o.modes = k;
    const double e = compareResponses(lm.full, reduceModal(lm.full, o).model, w).max_relative;
    EXPECT_LE(e, previous * (1 + 1e-9)) << k;
    previous = e;
  }
  EXPECT_LT(previous, 1e-3);
  ReductionOptions all;
  all.modes = 1000;
  EXPECT_LT(compareResponses(lm.full, reduceModal(lm.full, all).model, w).max_relative, 1e-9);
}

// With modal damping zeta the poles are -zeta w +- i w sqrt(1 - zeta^2) for every
// undamped frequency w of the linearization.
TEST(StateSpace, PolesAreTheLinearizationsEigenvalues) {
  const LinearModel lm = defaultModel();
  const ModalSolution modes = solveModes(lm.Mz, lm.Kz);
  const Eigen::VectorXcd p = lm.full.poles();
  for (Eigen::Index i = 0; i < modes.omega2.size(); ++i) {
    const double w = std::sqrt(modes.omega2[i]);
    const cd expect(-0.02 * w, w * std::sqrt(1 - 0.02 * 0.02));
    double best = INFINITY;
    for (Eigen::Index j = 0; j < p.size(); ++j) best = std::min(best, std::abs(p[j] - expect));
    EXPECT_LT(best, 1e-7 * w) << "mode " << i;
  }
}

// The slides' method: eigenvalues of the implicit integrator's Jacobian pencil, mapped
// back with the inverse Tustin transform, equal the poles found directly.
TEST(StateSpace, IntegratorJacobianPencilGivesThePoles) {
  const LinearModel lm = defaultModel();
  const Eigen::VectorXcd p = lm.full.poles();
  for (double dcoef : {1e-3, 1e-2}) {
    const Eigen::VectorXcd q = polesFromIntegratorJacobian(lm.full, dcoef);
    ASSERT_EQ(q.size(), p.size());
    for (Eigen::Index i = 0; i < p.size(); ++i) {
      double best = INFINITY;
      for (Eigen::Index j = 0; j < q.size(); ++j) best = std::min(best, std::abs(q[j] - p[i]));
      EXPECT_LT(best, 1e-6 * std::abs(p[i])) << "pole " << i << " dCoef " << dcoef;
    }
  }
}

TEST(StateSpace, BadSpecsAreNamed) {
  ArticleScene s = loadDefaultScene();
  overrideSegments(s, 2);
  const DampingSpec d;
  EXPECT_THROW(buildLinearModel(s, {{"t", InputKind::JointTorque, "joint2", 0}}, defaultOutputs(s), d), SceneError);
  EXPECT_THROW(buildLinearModel(s, defaultInputs(), {{"y", OutputKind::Displacement, "link9.tip", 0, false}}, d),
               SceneError);
  EXPECT_THROW(buildLinearModel(s, defaultInputs(), {{"y", OutputKind::Displacement, "link1.tip", 0, true}}, d),
               SceneError);
}

}  // namespace
}  // namespace mmv

namespace mmv {
namespace {

/// Largest |a - b| over 0.05-100 Hz, relative to the largest |a| of each pair.
double secondVsFirstOrder(const StateSpace& full, const SecondOrderResponse& so) {
  double worst = 0;
  Eigen::MatrixXd peak = Eigen::MatrixXd::Zero(full.C.rows(), full.B.cols()), diff = peak;
  for (double f : logFrequencies(0.05, 100, 200)) {
    const Eigen::MatrixXcd a = full.response(2 * M_PI * f), b = so.response(2 * M_PI * f);
    peak = peak.cwiseMax(a.cwiseAbs());
    diff = diff.cwiseMax((a - b).cwiseAbs());
  }
  for (Eigen::Index i = 0; i < peak.size(); ++i) worst = std::max(worst, diff(i) / std::max(peak(i), 1e-300));
  return worst;
}

TEST(StateSpace, SecondOrderAndModalResponsesEqualTheFirstOrderOnes) {
  ArticleScene s = loadArticleSceneFile(MMVLAB_SOURCE_DIR "/scenes/mmv-table.yaml");
  overrideSegments(s, 6);
  // The scene's hinge dampers under gravity's geometric stiffness: not proportional, the
  // Hessenberg path.
  const LinearModel hinge = buildLinearModel(s, defaultInputs(), defaultOutputs(s), *s.damping);
  EXPECT_FALSE(hinge.second_order.modal());
  EXPECT_TRUE(hinge.second_order.hessenberg());
  EXPECT_LT(secondVsFirstOrder(hinge.full, hinge.second_order), 1e-9);
  {
    // At 16 segments the explicit first-order matrix (M^-1 K) alone costs digits (3e-9
    // measured for an LU on it, 6e-8 through the Hessenberg form without refinement);
    // the refined response matches the second-order LU to 1e-11.
    ArticleScene fine = s;
    overrideSegments(fine, 16);
    const LinearModel h16 = buildLinearModel(fine, defaultInputs(), defaultOutputs(fine), *fine.damping);
    ASSERT_TRUE(h16.second_order.hessenberg());
    SecondOrderResponse lu;  // not prepared: an n x n complex LU per frequency
    const SecondOrderResponse& h = h16.second_order;
    lu.M = h.M, lu.C = h.C, lu.K = h.K, lu.Bq = h.Bq, lu.Cd = h.Cd, lu.Cv = h.Cv, lu.Ca = h.Ca, lu.D = h.D;
    ASSERT_FALSE(lu.hessenberg() || lu.modal());
    for (double f : logFrequencies(0.05, 100, 200)) {
      const Eigen::MatrixXcd a = lu.response(2 * M_PI * f), b = h.response(2 * M_PI * f);
      EXPECT_LT((a - b).cwiseAbs().maxCoeff(), 1e-11 * a.cwiseAbs().maxCoeff()) << f << " Hz";
    }
    EXPECT_LT(secondVsFirstOrder(h16.full, h), 1e-11);
  }
  // Modal and Rayleigh damping: the real modes diagonalise C, the modal path.
  DampingSpec modal;
  modal.modal_ratio = 0.02;
  const LinearModel m = buildLinearModel(s, defaultInputs(), defaultOutputs(s), modal);
  EXPECT_TRUE(m.second_order.modal());
  EXPECT_LT(secondVsFirstOrder(m.full, m.second_order), 1e-9);
  DampingSpec rayleigh;
  rayleigh.kind = DampingSpec::Kind::Rayleigh;
  rayleigh.alpha = 0.05, rayleigh.beta = 1e-4;
  const LinearModel r = buildLinearModel(s, defaultInputs(), defaultOutputs(s), rayleigh);
  EXPECT_TRUE(r.second_order.modal());
  EXPECT_LT(secondVsFirstOrder(r.full, r.second_order), 1e-9);
}

// Proportional damping on a fine mesh: the modal path by construction. The diagonality
// test prepare() makes on a basis of its own loses digits with the model's size (Phi^T C
// Phi off the diagonal 6e-9 of it at 64 segments per link, modal damping, against the
// 1e-10 it needs), which sent the default scene's frf to the Hessenberg path at 3.6x the
// cost. Both kinds match the n x n complex LU at every frequency.
TEST(StateSpace, ProportionalDampingOnAFineMeshTakesTheModalPath) {
  ArticleScene s = loadArticleSceneFile(MMVLAB_SOURCE_DIR "/scenes/mmv.yaml");
  overrideSegments(s, 64);
  DampingSpec modal;
  modal.modal_ratio = 0.01;
  DampingSpec rayleigh;
  rayleigh.kind = DampingSpec::Kind::Rayleigh;
  rayleigh.alpha = 0.05, rayleigh.beta = 1e-4;
  for (const DampingSpec& d : {modal, rayleigh}) {
    const LinearModel m = buildLinearModel(s, defaultInputs(), defaultOutputs(s), d);
    const SecondOrderResponse& h = m.second_order;
    ASSERT_EQ(h.K.rows(), 256);
    EXPECT_TRUE(h.modal());
    EXPECT_FALSE(h.hessenberg());
    SecondOrderResponse lu;  // not prepared: an n x n complex LU per frequency
    lu.M = h.M, lu.C = h.C, lu.K = h.K, lu.Bq = h.Bq, lu.Cd = h.Cd, lu.Cv = h.Cv, lu.Ca = h.Ca, lu.D = h.D;
    double worst = 0;
    for (double f : logFrequencies(0.05, 100, 60)) {
      const Eigen::MatrixXcd a = lu.response(2 * M_PI * f), b = h.response(2 * M_PI * f);
      worst = std::max(worst, (a - b).cwiseAbs().maxCoeff() / a.cwiseAbs().maxCoeff());
    }
    EXPECT_LT(worst, 1e-9) << static_cast<int>(d.kind);
  }
}

// The frequency grid resolves a lightly damped resonance: a 1-DOF oscillator at 1.34 Hz
// with 0.8 % damping (the article's first mode) on a 400-point log grid over 0.01-100 Hz
// (2.3 % apart, wider than its 1.6 % half-power band) shows a peak up to several dB low;
// with the resonance points the grid's largest |H| is within 0.01 dB of the true peak
// 1 / (2 zeta sqrt(1 - zeta^2)), and 9 points lie inside the band.
TEST(Grid, ResolvesTheHalfPowerBandOfEveryLightlyDampedMode) {
  const double fn = 1.34, z = 0.008;
  const auto H = [&](double f) {
    const double r = f / fn;
    return 1 / std::abs(std::complex<double>(1 - r * r, 2 * z * r));
  };
  const double peak_db = 20 * std::log10(1 / (2 * z * std::sqrt(1 - z * z)));
  const auto grid_peak_db = [&](const std::vector<double>& f) {
    double m = 0;
    for (double x : f) m = std::max(m, H(x));
    return 20 * std::log10(m);
  };
  const std::vector<double> plain = logFrequencies(0.01, 100, 400);
  const std::vector<double> fine = resolveResonances(plain, {fn, 250.0, 5.0, 7.0}, {z, 0.01, 0.0, 0.7});
  EXPECT_LT(std::abs(grid_peak_db(fine) - peak_db), 0.01);
  EXPECT_GT(peak_db - grid_peak_db(plain), 0.05);  // what the plain grid missed here
  int in_band = 0;
  for (double x : fine) in_band += x >= fn * (1 - z) && x <= fn * (1 + z);
  EXPECT_GE(in_band, 9);
  // Sorted, no duplicates; a mode outside the range (250 Hz), an undamped one (5 Hz)
  // and a heavily damped one (7 Hz, no resonance) add nothing.
  EXPECT_TRUE(std::is_sorted(fine.begin(), fine.end()));
  EXPECT_EQ(std::adjacent_find(fine.begin(), fine.end()), fine.end());
  EXPECT_EQ(fine.size(), plain.size() + 18);
  EXPECT_EQ(fine.front(), plain.front());
  EXPECT_EQ(fine.back(), plain.back());
  EXPECT_EQ(resolveResonances(fine, {fn}, {z}), fine);  // idempotent
}

}  // namespace
}  // namespace mmv

namespace mmv {
namespace {

/// Largest |a(w) - response(w)| over the grid, relative to the largest |response|.
double gapToTheLu(const StateSpace& s, const StateSpaceResponses& r, const std::vector<double>& w) {
  double gap = 0, peak = 0;
  for (double x : w) {
    const Eigen::MatrixXcd ref = s.response(x);
    peak = std::max(peak, ref.cwiseAbs().maxCoeff());
    gap = std::max(gap, (r.at(x) - ref).cwiseAbs().maxCoeff());
  }
  return gap / peak;
}

// The Hessenberg responses (the reduced models' error over the grid uses them; the full
// models' responses take SecondOrderResponse's refined path) against
// the LU at every frequency of a 300-point grid: the table scene's full first-order model
// (hinge dampers, E = diag(I, M)), its 6-mode reduction, and a descriptor model whose E
// is dense; a singular E takes the LU at every frequency.
TEST(StateSpace, ResponsesByHessenbergAreTheLusAtEveryFrequency) {
  ArticleScene s = loadArticleSceneFile(MMVLAB_SOURCE_DIR "/scenes/mmv-table.yaml");
  overrideSegments(s, 6);
  const LinearModel lm = buildLinearModel(s, defaultInputs(), defaultOutputs(s), *s.damping);
  std::vector<double> w = logFrequencies(0.01, 100, 300);
  for (double& x : w) x *= 2 * M_PI;
  ReductionOptions o;
  o.modes = 6;
  const StateSpace reduced = reduceModal(lm.full, o).model;
  StateSpace mixed = reduced;  // the same model seen through a dense, well-conditioned T
  const Eigen::Index n = mixed.A.rows();
  const MatrixXd T = MatrixXd::Identity(n, n) + 0.3 * MatrixXd::Random(n, n) / std::sqrt(double(n));
  mixed.E = T * reduced.E;
  mixed.A = T * reduced.A;
  mixed.B = T * reduced.B;
  for (const StateSpace* m : std::vector<const StateSpace*>{&lm.full, &reduced, &mixed}) {
    const StateSpaceResponses r(*m, w);
    EXPECT_TRUE(r.hessenberg()) << m->numStates();
    const double gap = gapToTheLu(*m, r, w);
    std::printf("[hessenberg] %d states: %.3g of the peak\n", m->numStates(), gap);
    // The reductions (modal states, well conditioned) to round-off; the full model's
    // E^-1 A holds M^-1 K (the stiff hinges' omega^2): measured 1.2e-10 of the peak.
    EXPECT_LT(gap, m == &lm.full ? 1e-9 : 1e-11) << m->numStates();
  }
  StateSpace singular;  // x1' = -x1 + x2 + u, 0 = x1 - 2 x2: an algebraic state
  singular.E = (MatrixXd(2, 2) << 1, 0, 0, 0).finished();
  singular.A = (MatrixXd(2, 2) << -1, 1, 1, -2).finished();
  singular.B = (MatrixXd(2, 1) << 1, 0).finished();
  singular.C = (MatrixXd(1, 2) << 0, 1).finished();
  singular.D = MatrixXd::Zero(1, 1);
  const StateSpaceResponses r(singular, w);
  EXPECT_FALSE(r.hessenberg());
  EXPECT_EQ(gapToTheLu(singular, r, w), 0.0);
  // x2 = x1 / 2, x1' = -x1 / 2 + u: H = 0.5 / (i w + 0.5).
  EXPECT_NEAR(std::abs(r.at(1.0)(0, 0) - 0.5 / cd(0.5, 1.0)), 0.0, 1e-15);
}

}  // namespace
}  // namespace mmv
