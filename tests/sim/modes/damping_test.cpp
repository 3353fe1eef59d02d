// Modal damping ratios (sim/modes/damping.hpp) against closed forms (modal and Rayleigh
// damping), against the eigenvalues of the full first-order matrix (the hinge dampers,
// not proportional), and the projection on the lowest modes against the exact solution.
#include "sim/modes/damping.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>

#include "sim/modes/system_modes.hpp"

namespace mmv {
namespace {

ArticleScene tableScene(int segments) {
  ArticleScene s = std::get<ArticleScene>(loadSceneFile(std::string(MMVLAB_SOURCE_DIR) + "/scenes/mmv-table.yaml"));
  for (auto& l : s.article.links)
    if (!l.rigid) l.segments = segments;
  return s;
}

/// The table scene's damping: c = 2 ms * k in every bending hinge.
DampingSpec hingeDamping() {
  DampingSpec d;
  d.kind = DampingSpec::Kind::HingeViscous;
  d.hinge_beta = 0.002;
  return d;
}

TEST(Damping, ModalAndRayleighGiveTheirClosedForms) {
  const ArticleScene scene = tableScene(8);
  const SolvedScene s = solveScene(scene);
  DampingSpec modal;
  modal.modal_ratio = 0.013;
  const ModalDamping m = modalDamping(*s.model, s.linearized, s.modes, modal, 10);
  DampingSpec ray;
  ray.kind = DampingSpec::Kind::Rayleigh;
  ray.alpha = 0.3;
  ray.beta = 2e-4;
  const ModalDamping r = modalDamping(*s.model, s.linearized, s.modes, ray, 10);
  EXPECT_TRUE(m.exact);
  for (int k = 0; k < 10; ++k) {
    const double w = std::sqrt(s.modes.omega2[k]);
    EXPECT_NEAR(m.ratio[k], 0.013, 1e-12) << k;
    EXPECT_NEAR(r.ratio[k], 0.3 / (2 * w) + 2e-4 * w / 2, 1e-10) << k;
    // |lambda| = omega_n for a proportionally damped mode
    EXPECT_NEAR(m.natural_hz[k], s.modes.frequencyHz(k), 1e-9 * s.modes.frequencyHz(k)) << k;
  }
}

// Rayleigh damping heavy enough that the lowest mode is overdamped (alpha = 20/s: zeta
// about 1.2 at 1.3 Hz, 0.5 at 3.2 Hz): the closed form's roots, the slower real root of an
// overdamped mode included, against the eigenvalues of the full first-order matrix over
// the DOFs (no modal basis).
TEST(Damping, RayleighRootsMatchTheFullFirstOrderEigenvaluesOverdampedToo) {
  const ArticleScene scene = tableScene(4);
  const SolvedScene s = solveScene(scene);
  DampingSpec ray;
  ray.kind = DampingSpec::Kind::Rayleigh;
  ray.alpha = 20;
  ray.beta = 1e-4;
  const ModalDamping r = modalDamping(*s.model, s.linearized, s.modes, ray, 8);
  const Eigen::MatrixXd& M = s.linearized.M;
  const Eigen::MatrixXd K = s.linearized.K, C = ray.alpha * M + ray.beta * K;
  const Eigen::Index n = M.rows();
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(2 * n, 2 * n);
  A.topRightCorner(n, n).setIdentity();
  const Eigen::LLT<Eigen::MatrixXd> llt(M);
  A.bottomLeftCorner(n, n) = -llt.solve(K);
  A.bottomRightCorner(n, n) = -llt.solve(C);
  const Eigen::VectorXcd lambda = Eigen::EigenSolver<Eigen::MatrixXd>(A, false).eigenvalues();
  int overdamped = 0;
  for (int k = 0; k < 8; ++k) {
    const double wn = 2 * M_PI * r.natural_hz[k];
    std::complex<double> expect(-r.ratio[k] * wn, wn * std::sqrt(1 - r.ratio[k] * r.ratio[k]));
    if (r.ratio[k] == 1.0) expect = -wn, ++overdamped;  // the slower real root
    double best = INFINITY;
    for (Eigen::Index j = 0; j < lambda.size(); ++j) best = std::min(best, std::abs(lambda[j] - expect) / std::abs(expect));
    EXPECT_LT(best, 1e-8) << "mode " << k + 1;
  }
  EXPECT_GE(overdamped, 1);
  EXPECT_LT(overdamped, 8);
}

TEST(Damping, HingeDampersMatchTheFullFirstOrderEigenvalues) {
  const ArticleScene scene = tableScene(8);
  const SolvedScene s = solveScene(scene);
  const DampingSpec d = hingeDamping();
  const ModalDamping md = modalDamping(*s.model, s.linearized, s.modes, d, 8);
  // The same physics without the modal basis: A = [0 I; -M^-1 K, -M^-1 C] over the DOFs.
  const Eigen::MatrixXd& M = s.linearized.M;
  const Eigen::MatrixXd C = hingeDampers(*s.model, s.linearized.dofs, d.hinge_beta).asDiagonal();
  const Eigen::Index n = M.rows();
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(2 * n, 2 * n);
  A.topRightCorner(n, n).setIdentity();
  const Eigen::LLT<Eigen::MatrixXd> llt(M);
  A.bottomLeftCorner(n, n) = -llt.solve(Eigen::MatrixXd(s.linearized.K));
  A.bottomRightCorner(n, n) = -llt.solve(C);
  const Eigen::VectorXcd lambda = Eigen::EigenSolver<Eigen::MatrixXd>(A, false).eigenvalues();
  for (int k = 0; k < 8; ++k) {
    // the full eigenvalue nearest to the one the modal solution found
    const double wn = 2 * M_PI * md.natural_hz[k];
    const std::complex<double> expect(-md.ratio[k] * wn, wn * std::sqrt(1 - md.ratio[k] * md.ratio[k]));
    double best = INFINITY;
    for (Eigen::Index j = 0; j < lambda.size(); ++j) best = std::min(best, std::abs(lambda[j] - expect) / std::abs(expect));
    EXPECT_LT(best, 1e-8) << "mode " << k + 1;
  }
  // The numbers: 0.8 % in the first mode.
  EXPECT_NEAR(md.ratio[0], 0.008, 0.0005);
  // Not proportional: the ratio is not beta * omega / 2 in every mode (gravity's share).
  double largest_departure = 0;
  for (int k = 0; k < 8; ++k)
    largest_departure = std::max(largest_departure, std::abs(md.ratio[k] - d.hinge_beta * std::sqrt(s.modes.omega2[k]) / 2) / md.ratio[k]);
  EXPECT_GT(largest_departure, 1e-3);
}

TEST(Damping, ProjectionOnTheLowestModesIsWithinATenthOfAPercent) {
  // 32 segments per link: 128 DOF, where `modes` solves only the lowest (2 x 12) modes.
  const ArticleScene scene = tableScene(32);
  const SolvedScene s = solveScene(scene);
  const DampingSpec d = hingeDamping();
  const ModalDamping exact = modalDamping(*s.model, s.linearized, s.modes, d, 12);
  ASSERT_TRUE(exact.exact);
  ModalSolution lowest = s.modes;
  lowest.omega2 = s.modes.omega2.head(32);
  lowest.shapes = s.modes.shapes.leftCols(32);
  const ModalDamping projected = modalDamping(*s.model, s.linearized, lowest, d, 12);
  EXPECT_FALSE(projected.exact);
  EXPECT_EQ(projected.basis_modes, 32);
  for (int k = 0; k < 12; ++k) EXPECT_LT(std::abs(projected.ratio[k] / exact.ratio[k] - 1), 1e-3) << "mode " << k + 1;
  // And runModes reports what the exact solution gives, through its own partial solve.
  ModesOptions o;
  o.max_modes = 12;
  o.with_shapes = false;
  o.damping = d;
  const ModesReport rep = runModes(scene, o);
  ASSERT_TRUE(rep.damped);
  EXPECT_FALSE(rep.damping_exact);
  for (int k = 0; k < 12; ++k) EXPECT_LT(std::abs(rep.modes[k].damping_ratio / exact.ratio[k] - 1), 1e-3) << "mode " << k + 1;
}

TEST(Damping, ABasisPastTheCapKeepsTheLowestModesAndSaysSo) {
  // 101 segments per link: 404 DOF, every mode solved, more than kMaxDampingBasis.
  const ArticleScene scene = tableScene(101);
  const SolvedScene s = solveScene(scene);
  ASSERT_GT(s.modes.shapes.cols(), kMaxDampingBasis);
  const ModalDamping capped = modalDamping(*s.model, s.linearized, s.modes, hingeDamping(), 300);
  EXPECT_EQ(capped.basis_modes, kMaxDampingBasis);
  EXPECT_FALSE(capped.exact);
  ASSERT_EQ(capped.ratio.size(), static_cast<std::size_t>(kMaxDampingBasis / 2));  // the lower half only
  ModalSolution lowest = s.modes;
  lowest.omega2 = s.modes.omega2.head(40);
  lowest.shapes = s.modes.shapes.leftCols(40);
  const ModalDamping small = modalDamping(*s.model, s.linearized, lowest, hingeDamping(), 12);
  for (int k = 0; k < 12; ++k) EXPECT_LT(std::abs(capped.ratio[k] / small.ratio[k] - 1), 1e-3) << "mode " << k + 1;
}

}  // namespace
}  // namespace mmv
