#include "sim/modes/cms.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "sim/modes/system_modes.hpp"
#include "support/scenes.hpp"

namespace mmv {
namespace {

/// A fixed-free chain of n masses m and springs k (the first spring to the ground).
void springMassChain(int n, Eigen::MatrixXd& M, Eigen::MatrixXd& K) {
  M = Eigen::MatrixXd::Zero(n, n);
  K = Eigen::MatrixXd::Zero(n, n);
  for (int i = 0; i < n; ++i) {
    M(i, i) = 1.0 + 0.1 * i;  // unequal masses: no accidental symmetry
    const double k = 100.0 * (1.0 + 0.05 * i);
    K(i, i) += k;
    if (i > 0) {
      K(i - 1, i - 1) += k;
      K(i - 1, i) -= k;
      K(i, i - 1) -= k;
    }
  }
}

/// Craig-Bampton of the chain split at DOF b: substructure A = DOFs 0..b, B = b..n-1
/// (b shared). Each substructure's own M and K come from its springs and masses (the
/// boundary mass and the spring ending at b belong to A); the global basis puts the
/// boundary DOF first, then A's and B's fixed-interface modes.
Eigen::MatrixXd chainCraigBampton(int n, int b, int ka, int kb) {
  Eigen::MatrixXd M, K;
  springMassChain(n, M, K);
  // Substructure A: DOFs 0..b with every spring up to and including the one into b.
  const int na = b + 1, nb = n - b;
  Eigen::MatrixXd Ka = K.topLeftCorner(na, na), Ma = M.topLeftCorner(na, na);
  const double k_out = -K(b, b + 1);  // the spring from b to b+1 belongs to B
  Ka(b, b) -= k_out;
  Eigen::MatrixXd Kb = K.bottomRightCorner(nb, nb), Mb = M.bottomRightCorner(nb, nb);
  Kb(0, 0) = k_out;
  Mb(0, 0) = 0.0;  // the boundary mass was counted in A
  Eigen::MatrixXd Ca = Eigen::MatrixXd::Zero(1, na), Cb = Eigen::MatrixXd::Zero(1, nb);
  Ca(0, b) = 1.0;
  Cb(0, 0) = 1.0;
  const Eigen::MatrixXd Ta = craigBamptonBasis(Ma, Ka, Ca, ka);  // [psi | phi]
  const Eigen::MatrixXd Tb = craigBamptonBasis(Mb, Kb, Cb, kb);
  Eigen::MatrixXd T = Eigen::MatrixXd::Zero(n, 1 + ka + kb);
  T.block(0, 0, na, 1) = Ta.col(0);
  T.block(b, 0, nb, 1) += Tb.col(0);
  T(b, 0) = 1.0;  // both constraint modes are 1 at the boundary
  T.block(0, 1, na, ka) = Ta.rightCols(ka);
  T.block(b, 1 + ka, nb, kb) = Tb.rightCols(kb);
  return T;
}

TEST(Cms, CraigBamptonWithAllInteriorModesIsExact) {
  const int n = 10, b = 4;
  Eigen::MatrixXd M, K;
  springMassChain(n, M, K);
  const ModalSolution exact = solveModes(M, K);
  const Eigen::MatrixXd T = chainCraigBampton(n, b, b, n - b - 1);  // all interior modes
  ASSERT_EQ(T.cols(), n);
  const ModalSolution cb = ritzModes(M, K, T, Eigen::MatrixXd());
  for (int i = 0; i < n; ++i) EXPECT_NEAR(cb.omega2[i] / exact.omega2[i], 1.0, 1e-9) << i;
}

TEST(Cms, TruncatedCraigBamptonBoundsFromAboveAndConverges) {
  const int n = 10, b = 4;
  Eigen::MatrixXd M, K;
  springMassChain(n, M, K);
  const ModalSolution exact = solveModes(M, K);
  double prev_err = 1e300;
  for (int k = 1; k <= 4; ++k) {
    const ModalSolution cb = ritzModes(M, K, chainCraigBampton(n, b, k, k), Eigen::MatrixXd());
    double err = 0;
    for (Eigen::Index i = 0; i < cb.omega2.size(); ++i) {
      EXPECT_GE(cb.omega2[i], exact.omega2[i] * (1 - 1e-12)) << "k " << k << " mode " << i;  // upper bound
      if (i < 3) err += cb.omega2[i] / exact.omega2[i] - 1;
    }
    EXPECT_LT(err, prev_err) << "k " << k;  // each added mode improves the first three
    prev_err = err;
  }
  // k = 4 keeps all of A's interior modes and 4 of B's 5: the summed relative error of
  // omega^2 for the first three modes is then 1.7e-4 (measured).
  EXPECT_LT(prev_err, 1e-3);
}

TEST(Cms, MacOfAModeSetWithItselfIsTheIdentity) {
  Eigen::MatrixXd M, K;
  springMassChain(8, M, K);
  const ModalSolution s = solveModes(M, K);
  // Mode shapes of a chain are M-orthogonal, not orthogonal: use the M^(1/2)-weighted
  // shapes, which are orthonormal, so the MAC is exactly the identity.
  const Eigen::MatrixXd W = M.diagonal().cwiseSqrt().asDiagonal() * s.shapes;
  const Eigen::MatrixXd mac = modalAssuranceCriterion(W, W);
  EXPECT_LT((mac - Eigen::MatrixXd::Identity(8, 8)).cwiseAbs().maxCoeff(), 1e-12);
  // A shape against a scaled copy of itself: 1.
  EXPECT_NEAR(modalAssuranceCriterion(s.shapes.col(2), -3.0 * s.shapes.col(2))(0, 0), 1.0, 1e-14);
}

// On the MMV article: the synthesis bounds the full model from above, Craig-Bampton
// with all hinge modes reproduces it, and assumed modes with the report's tip mass
// predict the first mode within 1 %.
TEST(Cms, ArticleSynthesis) {
  ArticleScene s = loadDefaultScene();
  overrideSegments(s, 8);
  SynthesisOptions o;
  o.compare_modes = 8;
  o.method = CmsMethod::AssumedModes;
  const SynthesisResult am = synthesize(s, o);
  ASSERT_EQ(am.rows.size(), 8u);
  for (const auto& r : am.rows) EXPECT_GE(r.synth_hz, r.full_hz * (1 - 1e-9)) << r.mode;
  EXPECT_EQ(am.rows[0].verdict, "predicted");
  o.method = CmsMethod::CraigBampton;
  o.modes_per_link = 8;  // constraint modes + all fixed-interface modes span each link
  const SynthesisResult cb = synthesize(s, o);
  EXPECT_EQ(cb.reduced_dofs, cb.full_dofs);
  for (const auto& r : cb.rows) {
    EXPECT_NEAR(r.relative_error, 0.0, 1e-9) << r.mode;
    EXPECT_NEAR(r.mac, 1.0, 1e-9) << r.mode;
  }
}

// A mechanism (free joint, no gravity) has a 0 Hz rigid-body mode: the synthesis must
// report it without an infinite or NaN error.
TEST(Cms, RigidBodyModeHasAFiniteError) {
  ArticleScene s = testing::cantileverScene(testing::Beam{}, 8, 0.0);
  s.article.joints[0].hold = JointHold::Free;
  SynthesisOptions o;
  o.compare_modes = 4;
  const SynthesisResult r = synthesize(s, o);
  ASSERT_FALSE(r.rows.empty());
  for (const auto& row : r.rows) EXPECT_TRUE(std::isfinite(row.relative_error)) << row.mode;
  EXPECT_EQ(r.rows[0].full_hz, 0.0);
  EXPECT_EQ(r.rows[0].verdict, "predicted");
}

}  // namespace
}  // namespace mmv
