// The modal reduction's two eigen solvers (sim/linear/state_modes.hpp): the partial
// (shift-invert Arnoldi on the second-order structure) against the dense one.
#include "sim/linear/state_modes.hpp"

#include <gtest/gtest.h>

#include <iomanip>

#include <algorithm>
#include <cmath>
#include <string>

#include "sim/core/errors.hpp"
#include "support/scenes.hpp"

namespace mmv {
namespace {

using Eigen::MatrixXd;
using Solver = ReductionOptions::Solver;

std::vector<double> omegas(double f0, double f1, int n) {
  std::vector<double> w = logFrequencies(f0, f1, n);
  for (double& x : w) x *= 2 * M_PI;
  return w;
}

ReducedModel reduceWith(const StateSpace& full, int modes, Solver solver) {
  ReductionOptions o;
  o.modes = modes;
  o.solver = solver;
  return reduceModal(full, o);
}

/// Backward error of each computed mode on the quadratic problem (lambda^2 M + lambda C + K) phi = 0.
double worstResidual(const StateSpace& full, const detail::StateEigen& sm) {
  const Eigen::Index n = full.numStates() / 2;
  const MatrixXd M = full.E.bottomRightCorner(n, n), C = -full.A.bottomRightCorner(n, n), K = -full.A.bottomLeftCorner(n, n);
  double worst = 0;
  for (const auto& m : sm.modes) {
    const std::complex<double> l = sm.lambda[m.index];
    const Eigen::VectorXcd phi = sm.V.col(m.index).head(n);
    const Eigen::VectorXcd r = l * l * (M * phi) + l * (C * phi) + K * phi;
    worst = std::max(worst, r.norm() / ((std::norm(l) * M.norm() + std::abs(l) * C.norm() + K.norm()) * phi.norm()));
  }
  return worst;
}

/// The two reductions are the same model to the dense solver's accuracy, and the
/// partial one is as accurate: its modes solve the quadratic problem to round-off
/// (the dense solver works on the explicit M^-1 K, whose norm, the stiffest hinge's
/// omega^2, costs the low modes digits: 1e-9 backward error, 1e-8 in frequency), and its
/// reduced model is no farther from the full model than the dense one plus the distance
/// between them (which of the two is ahead is round-off: the table scene's M and K from
/// the tree's recursions or from Simbody's, equal to 1e-12, put either ahead by 1.3e-7 of
/// the error).
/// `truth`: the full model's responses at w.
void expectSameReduction(const StateSpace& full, int modes, const std::vector<double>& w,
                         const std::vector<Eigen::MatrixXcd>& truth) {
  const ReducedModel dense = reduceWith(full, modes, Solver::Dense);
  const ReducedModel lowest = reduceWith(full, modes, Solver::Lowest);
  EXPECT_TRUE(dense.every_mode_computed);
  EXPECT_FALSE(lowest.every_mode_computed);
  const std::optional<detail::StateEigen> sm = detail::lowestStateModes(full, modes);
  ASSERT_TRUE(sm.has_value());
  ASSERT_FALSE(sm->every_mode);
  EXPECT_LT(worstResidual(full, *sm), 1e-11);
  ASSERT_EQ(dense.kept_frequencies_hz.size(), lowest.kept_frequencies_hz.size());
  for (std::size_t k = 0; k < dense.kept_frequencies_hz.size(); ++k)
    EXPECT_NEAR(lowest.kept_frequencies_hz[k], dense.kept_frequencies_hz[k], 1e-7 * dense.kept_frequencies_hz[k]) << k;
  const double apart = compareResponses(dense.model, lowest.model, w).max_relative;
  EXPECT_LT(apart, 1e-7);
  ASSERT_EQ(dense.model.numStates(), lowest.model.numStates());
  const double e_dense = compareResponses(truth, dense.model, w).max_relative;
  const double e_lowest = compareResponses(truth, lowest.model, w).max_relative;
  // No farther from the full model than the dense one, within the distance between the
  // two (relative to the dense model's peak, at most 1 + e_dense times the full one's):
  // a bound by the triangle inequality, not by one machine's round-off.
  EXPECT_LE(e_lowest, e_dense + apart * (1 + e_dense) + 1e-15) << std::setprecision(12) << e_lowest - e_dense;
}

// The table scene's hinge dampers under gravity: non-proportional damping, and past the
// tenth pair the overdamped roots crowd at -1/beta (hundreds within 1e-5 of each other).
TEST(StateModes, LowestAndDenseReductionsAgreeOnTheTableScene) {
  ArticleScene s = loadArticleSceneFile(MMVLAB_SOURCE_DIR "/scenes/mmv-table.yaml");
  overrideSegments(s, 32);
  const LinearModel lm = buildLinearModel(s, defaultInputs(), defaultOutputs(s), *s.damping);
  // (12: the twelfth pair lies just below the cluster, which the completeness check must
  // then converge on.)
  const std::vector<double> w = omegas(0.01, 100, 300);
  const std::vector<Eigen::MatrixXcd> truth = fullResponses(lm.second_order, w);
  for (int modes : {1, 4, 10, 12}) {
    SCOPED_TRACE(modes);
    expectSameReduction(lm.full, modes, w, truth);
  }
}

TEST(StateModes, LowestAndDenseReductionsAgreeOnAClosedTree) {
  ArticleScene s = loadArticleSceneFile(MMVLAB_SOURCE_DIR "/scenes/mmv-closed.yaml");
  overrideSegments(s, 16);
  DampingSpec d;
  d.kind = DampingSpec::Kind::HingeViscous;
  d.hinge_beta = 0.002;
  const LinearModel lm = buildLinearModel(s, defaultInputs(), defaultOutputs(s), d);
  ASSERT_GT(lm.Z.cols(), 0);
  ASSERT_LT(lm.Z.cols(), lm.Z.rows());  // the closure removes coordinates
  const std::vector<double> w = omegas(0.01, 100, 300);
  expectSameReduction(lm.full, 8, w, fullResponses(lm.second_order, w));
}

/// The reduction from a model's proportional modes (closed form) against the dense
/// solver's, on the model as the commands build it, for a count and for every mode.
void expectProportionalIsDense(const LinearModel& lm, int modes) {
  ASSERT_TRUE(lm.proportional);
  ReductionOptions o;
  o.modes = modes;
  o.proportional = lm.proportional;
  std::string why;
  const std::optional<detail::StateEigen> sm = detail::proportionalStateModes(lm.full, lm.proportional, modes, &why);
  ASSERT_TRUE(sm.has_value()) << why;
  EXPECT_FALSE(sm->every_mode);
  EXPECT_LT(worstResidual(lm.full, *sm), 1e-11);
  const ReducedModel closed = reduceModal(lm.full, o), dense = reduceWith(lm.full, modes, Solver::Dense);
  ASSERT_EQ(closed.kept_frequencies_hz.size(), dense.kept_frequencies_hz.size());
  for (std::size_t k = 0; k < dense.kept_frequencies_hz.size(); ++k) {
    EXPECT_NEAR(closed.kept_frequencies_hz[k], dense.kept_frequencies_hz[k], 1e-7 * dense.kept_frequencies_hz[k]) << k;
    EXPECT_NEAR(closed.kept_damping[k], dense.kept_damping[k], 1e-7) << k;
  }
  ASSERT_EQ(closed.model.numStates(), dense.model.numStates());
  const std::vector<double> w = omegas(0.01, 100, 300);
  const std::vector<Eigen::MatrixXcd> truth = fullResponses(lm.second_order, w);
  const double apart = compareResponses(dense.model, closed.model, w).max_relative;
  EXPECT_LT(apart, 1e-7);
  // The closed form is as good as the dense solver's: its error from the full model is
  // the dense one's within the distance between the two (relative to the dense model's
  // peak, at most 1 + e_dense times the full model's), not to a fixed 1e-9 that two
  // code paths' round-off may exceed on another machine.
  const double e_dense = compareResponses(truth, dense.model, w).max_relative;
  EXPECT_LE(compareResponses(truth, closed.model, w).max_relative, e_dense + apart * (1 + e_dense) + 1e-15);
  // Every mode (a band, or dropping the unseen ones, needs them): W V = I, to the dense
  // symmetric solver's M-orthogonality (1e-13) times the ratio of the stiffest hinge's
  // omega to the first mode's (1e4 at 16 segments), which w_i v_j carries.
  const std::optional<detail::StateEigen> all = detail::proportionalStateModes(lm.full, lm.proportional, 0);
  ASSERT_TRUE(all.has_value());
  EXPECT_TRUE(all->every_mode);
  ASSERT_EQ(all->V.cols(), lm.full.numStates());
  const Eigen::MatrixXcd WV = all->W * all->V;
  EXPECT_LT((WV - Eigen::MatrixXcd::Identity(WV.rows(), WV.cols())).cwiseAbs().maxCoeff(), 1e-7);
  o.modes = 0;
  o.band_min_hz = 0, o.band_max_hz = 30;
  o.drop_unseen = true;
  ReductionOptions od = o;
  od.proportional = nullptr;
  const ReducedModel band = reduceModal(lm.full, o), band_dense = reduceModal(lm.full, od);
  EXPECT_EQ(band.kept_modes, band_dense.kept_modes);
  EXPECT_EQ(band.unseen_modes, band_dense.unseen_modes);
  EXPECT_LT(compareResponses(band_dense.model, band.model, w).max_relative, 1e-7);
}

// frf and rom take the state matrix's modes of a proportionally damped model (modal or
// Rayleigh: the scenes' default) in closed form from its undamped ones: the same reduced
// model as the dense solver's, with Rayleigh's overdamped low roots (alpha = 40 /s:
// below 3.2 Hz c > 2 omega) among the kept.
TEST(StateModes, ProportionalModesGiveTheDenseSolversReduction) {
  ArticleScene s = loadDefaultScene();
  overrideSegments(s, 16);
  DampingSpec modal;
  modal.modal_ratio = 0.02;
  expectProportionalIsDense(buildLinearModel(s, defaultInputs(), defaultOutputs(s), modal), 8);
  DampingSpec rayleigh;
  rayleigh.kind = DampingSpec::Kind::Rayleigh;
  rayleigh.alpha = 40;
  rayleigh.beta = 1e-5;
  const LinearModel lm = buildLinearModel(s, defaultInputs(), defaultOutputs(s), rayleigh);
  const std::optional<detail::StateEigen> sm = detail::proportionalStateModes(lm.full, lm.proportional, 6);
  ASSERT_TRUE(sm.has_value());
  int real_roots = 0;
  for (const auto& m : sm->modes) real_roots += m.pair ? 0 : 1;
  EXPECT_GE(real_roots, 2);
  expectProportionalIsDense(lm, 6);
}

// The closed form applies only where it is exact: modes of another model, a critically
// damped mode (a defective eigenvalue) or a rigid-body mode are declined, and the
// reduction is then the solvers'.
TEST(StateModes, ProportionalModesThatDoNotFitAreDeclined) {
  ArticleScene s = loadDefaultScene();
  overrideSegments(s, 4);
  const LinearModel lm = buildLinearModel(s, defaultInputs(), defaultOutputs(s), DampingSpec{});
  ASSERT_TRUE(lm.proportional);
  std::string why;
  ProportionalModes other = *lm.proportional;
  other.omega2[3] *= 1.001;
  EXPECT_FALSE(detail::proportionalStateModes(lm.full, std::make_shared<const ProportionalModes>(other), 4, &why).has_value());
  EXPECT_NE(why.find("do not solve"), std::string::npos) << why;
  ProportionalModes critical = *lm.proportional;
  critical.c[0] = 2 * std::sqrt(critical.omega2[0]);
  EXPECT_FALSE(detail::proportionalStateModes(lm.full, std::make_shared<const ProportionalModes>(critical), 4, &why).has_value());
  EXPECT_NE(why.find("critically damped"), std::string::npos) << why;
  // A rigid-body mode (no gravity, joint 1 free): its omega^2 is round-off, so the model
  // keeps no proportional modes and residualization refuses it, as with the solvers.
  ArticleScene free = s;
  free.gravity = {0, 0, 0};
  free.article.joints[0].hold = JointHold::Free;
  const LinearModel rigid = buildLinearModel(free, defaultInputs(), defaultOutputs(free), DampingSpec{});
  EXPECT_FALSE(rigid.proportional);
  ReductionOptions o;
  o.modes = 4;
  EXPECT_THROW(reduceModal(rigid.full, o), NumericalError);
  o.proportional = std::make_shared<const ProportionalModes>(other);
  const ReducedModel fallback = reduceModal(lm.full, o), dense = reduceWith(lm.full, 4, Solver::Dense);
  const std::vector<double> w = omegas(0.01, 100, 200);
  EXPECT_LT(compareResponses(dense.model, fallback.model, w).max_relative, 1e-7);
  // Right on the kept modes and off outside them: M^-1 and K^-1 come from every mode, so
  // what the residual check on the kept ones cannot see is checked where they are
  // applied; the reduction is the solvers' (the static residual 1 % off before).
  ProportionalModes outside = *lm.proportional;
  outside.shapes.rightCols(outside.shapes.cols() - 12) *= 1.01;
  o.proportional = std::make_shared<const ProportionalModes>(outside);
  EXPECT_LT(compareResponses(dense.model, reduceModal(lm.full, o).model, w).max_relative, 1e-7);
  EXPECT_FALSE(detail::proportionalStateModes(lm.full, o.proportional, 4, &why).has_value());
  EXPECT_NE(why.find("M-orthonormal"), std::string::npos) << why;
}

/// M q'' + C q' + K q = B u over a chain of n unit masses with springs k between them
/// and to ground, damping c_i on each mass, force on the last, displacement of the first.
StateSpace chain(int n, const Eigen::VectorXd& c, double k = 1e4) {
  MatrixXd M = MatrixXd::Identity(n, n), K = MatrixXd::Zero(n, n), B = MatrixXd::Zero(n, 1), Cd = MatrixXd::Zero(1, n);
  for (int i = 0; i < n; ++i) {
    K(i, i) += 2 * k;
    if (i + 1 < n) K(i, i + 1) = K(i + 1, i) = -k;
  }
  B(n - 1, 0) = 1;
  Cd(0, 0) = 1;
  return secondOrderModel(M, MatrixXd(c.asDiagonal()), K, B, Cd, MatrixXd(), MatrixXd(), MatrixXd());
}

// An overdamped mass gives two real roots below the second pair: they are kept, and the
// Arnoldi run must reach past them to find the pairs.
TEST(StateModes, RealRootsBelowTheKeptPairsAreFoundAndKept) {
  Eigen::VectorXd c = Eigen::VectorXd::Constant(30, 0.5);
  c[0] = 2000;
  const StateSpace full = chain(30, c);
  const Eigen::VectorXcd poles = full.poles();
  int real_below = 0;
  for (Eigen::Index i = 0; i < poles.size(); ++i) real_below += std::abs(poles[i].imag()) < 1e-9 && std::abs(poles[i]) < 100;
  ASSERT_GE(real_below, 1);
  const std::vector<double> w = omegas(0.01, 30, 200);
  std::vector<Eigen::MatrixXcd> truth;
  for (double x : w) truth.push_back(full.response(x));
  expectSameReduction(full, 3, w, truth);
}

/// Two identical, uncoupled oscillators (2 rad/s, slightly damped) below a stiff chain
/// of n - 2 masses; the input drives and the output sees each.
StateSpace twinOscillators(int n) {
  MatrixXd M = MatrixXd::Identity(n, n), K = MatrixXd::Zero(n, n), C = MatrixXd::Zero(n, n), B = MatrixXd::Zero(n, 2),
           Cd = MatrixXd::Zero(2, n);
  for (int i = 0; i < 2; ++i) K(i, i) = 4.0, C(i, i) = 0.02, B(i, i) = 1, Cd(i, i) = 1;
  for (int i = 2; i < n; ++i) K(i, i) = 1e4 * (i + 1), C(i, i) = 0.5;
  return secondOrderModel(M, C, K, B, Cd, MatrixXd(), MatrixXd(), MatrixXd());
}

// A repeated eigenvalue: Arnoldi from a random start finds both copies (round-off
// brings the second in) and the reduction keeps them, as the dense one does.
TEST(StateModes, BothCopiesOfARepeatedEigenvalueAreKept) {
  const StateSpace full = twinOscillators(30);
  const ReducedModel lowest = reduceWith(full, 2, Solver::Lowest);
  ASSERT_EQ(lowest.kept_frequencies_hz.size(), 2u);
  for (double f : lowest.kept_frequencies_hz) EXPECT_NEAR(f * 2 * M_PI, 2.0, 1e-9);
  // The dense solver's eigenvectors keep the oscillators apart, Arnoldi's mix them, so
  // the pairs that are zero by symmetry hold round-off (1e-13 of the peak) in one and
  // exact zeros in the other: compared against the largest response.
  const ReducedModel dense = reduceWith(full, 2, Solver::Dense);
  double diff = 0, peak = 0;
  for (double x : omegas(0.01, 1, 100)) {
    diff = std::max(diff, (dense.model.response(x) - lowest.model.response(x)).cwiseAbs().maxCoeff());
    peak = std::max(peak, dense.model.response(x).cwiseAbs().maxCoeff());
  }
  EXPECT_LT(diff, 1e-11 * peak);
}

// From a start vector with equal components on the two oscillators the Krylov space
// holds only their symmetric motion, so the first run misses the antisymmetric copy and
// keeps the chain's lowest pair instead: the deflation check must see the missed copy,
// and the automatic choice then keeps both copies by the dense solver.
TEST(StateModes, TheDeflationCheckCatchesAModeArnoldiMissed) {
  const StateSpace full = twinOscillators(30);
  Eigen::VectorXd start = Eigen::VectorXd::LinSpaced(60, 1.0, 2.0);
  start[1] = start[0];    // q
  start[31] = start[30];  // q'
  std::string why;
  EXPECT_FALSE(detail::lowestStateModes(full, 2, &why, &start).has_value());
  EXPECT_EQ(why, "the deflated operator has a mode as low as the kept ones");
  const ReducedModel automatic = reduceWith(full, 2, Solver::Automatic);
  ASSERT_EQ(automatic.kept_frequencies_hz.size(), 2u);
  for (double f : automatic.kept_frequencies_hz) EXPECT_NEAR(f * 2 * M_PI, 2.0, 1e-6);
}

// A circulatory (non-symmetric) stiffness: the left eigenvectors are not the right
// ones, so the partial solver does not apply; Automatic uses the dense one.
TEST(StateModes, NonSymmetricStiffnessUsesTheDenseSolver) {
  StateSpace full = chain(20, Eigen::VectorXd::Constant(20, 0.3));
  full.A(20 + 0, 1) -= 50.0;  // -K(0, 1) without -K(1, 0)
  std::string why;
  EXPECT_FALSE(detail::lowestStateModes(full, 3, &why).has_value());
  EXPECT_EQ(why, "not the first-order form of a second-order model with symmetric M, C, K");
  EXPECT_TRUE(reduceWith(full, 3, Solver::Automatic).every_mode_computed);
  EXPECT_THROW(reduceWith(full, 3, Solver::Lowest), NumericalError);
}

// A rigid-body mode (K singular): no shift-invert at zero; the dense path names the
// singularity when residualization is asked.
TEST(StateModes, ASingularStiffnessFallsBackToTheDenseSolver) {
  StateSpace full = chain(20, Eigen::VectorXd::Constant(20, 0.3));
  full.A.bottomLeftCorner(20, 20).setZero();
  std::string why;
  EXPECT_FALSE(detail::lowestStateModes(full, 3, &why).has_value());
  EXPECT_EQ(why, "K is singular (a rigid-body mode)");
  EXPECT_THROW(reduceWith(full, 3, Solver::Automatic), NumericalError);
}

TEST(StateModes, CanonicalScalingIsTheSameForAnyPhase) {
  Eigen::MatrixXcd V = Eigen::MatrixXcd::Random(12, 3);
  Eigen::MatrixXcd U = V;
  U.col(0) *= std::complex<double>(0.3, -2.0);
  U.col(2) *= -7.0;
  detail::normalizeEigenvectors(V);
  detail::normalizeEigenvectors(U);
  EXPECT_LT((U - V).cwiseAbs().maxCoeff(), 1e-14);
}

}  // namespace
}  // namespace mmv
