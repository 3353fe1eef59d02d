// Test-analysis models (sim/modes/tam.hpp): the known answers of each reduction on a
// spring-mass chain, where the exact modes are a dense eigensolution away.
#include "sim/modes/tam.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "sim/core/errors.hpp"

namespace mmv {
namespace {

using Eigen::MatrixXd;
using Eigen::VectorXd;

/// A fixed-free chain of n masses `m` joined by springs `k` (the first to the ground).
struct Chain {
  MatrixXd M, K;
  VectorXd omega2;
  MatrixXd phi;  ///< mass-normalised, ascending
};

Chain chain(const VectorXd& m, const VectorXd& k) {
  const Eigen::Index n = m.size();
  Chain c;
  c.M = m.asDiagonal();
  c.K = MatrixXd::Zero(n, n);
  for (Eigen::Index i = 0; i < n; ++i) {
    c.K(i, i) += k[i];
    if (i + 1 < n) {
      c.K(i, i) += k[i + 1];
      c.K(i, i + 1) = c.K(i + 1, i) = -k[i + 1];
    }
  }
  const Eigen::GeneralizedSelfAdjointEigenSolver<MatrixXd> g(c.K, c.M);
  c.omega2 = g.eigenvalues();
  c.phi = g.eigenvectors();
  return c;
}

TamInput input(const Chain& c, const MatrixXd& P, int targets) {
  return {c.M, c.K, P, c.phi.leftCols(targets), c.omega2.head(targets)};
}

/// Rows of the identity: sensors reading the chosen coordinates.
MatrixXd reading(int n, const std::vector<int>& coordinates) {
  MatrixXd P = MatrixXd::Zero(static_cast<Eigen::Index>(coordinates.size()), n);
  for (std::size_t r = 0; r < coordinates.size(); ++r) P(static_cast<Eigen::Index>(r), coordinates[r]) = 1;
  return P;
}

double worstFrequencyError(const TamResult& t) {
  double worst = 0;
  for (const auto& m : t.modes) worst = std::max(worst, std::abs(m.frequency_error));
  return worst;
}

TEST(Tam, EveryCoordinateMeasuredReproducesTheModelExactly) {
  const Chain c = chain(VectorXd::LinSpaced(8, 1.0, 2.4), VectorXd::LinSpaced(8, 900.0, 200.0));
  // Sensors that read combinations of the coordinates (as a translation reads hinge
  // angles), one per coordinate: an invertible 8 x 8 P.
  MatrixXd P = MatrixXd::Identity(8, 8);
  for (int i = 0; i + 1 < 8; ++i) P(i, i + 1) = 0.7;
  for (TamMethod method : {TamMethod::Guyan, TamMethod::Irs, TamMethod::Serep}) {
    const TamResult t = buildTam(input(c, P, 8), method);
    ASSERT_EQ(t.tam_omega2.size(), 8) << tamMethodName(method);
    for (int i = 0; i < 8; ++i) EXPECT_NEAR(t.tam_omega2[i] / c.omega2[i], 1.0, 1e-10) << tamMethodName(method) << " mode " << i + 1;
    EXPECT_TRUE(t.pass) << tamMethodName(method);
    EXPECT_LT((t.self - MatrixXd::Identity(8, 8)).cwiseAbs().maxCoeff(), 1e-10) << tamMethodName(method);
    for (const auto& m : t.modes) EXPECT_NEAR(m.cross_diagonal, 1.0, 1e-10) << tamMethodName(method);
  }
}

TEST(Tam, SerepReproducesTheTargetModesAtASensorSubsetExactly) {
  const Chain c = chain(VectorXd::Constant(12, 1.5), VectorXd::Constant(12, 500.0));
  const MatrixXd P = reading(12, {2, 5, 8, 11});
  const TamResult t = buildTam(input(c, P, 3), TamMethod::Serep);
  EXPECT_TRUE(t.pass);
  for (int j = 0; j < 3; ++j) {
    EXPECT_NEAR(t.modes[j].frequency_error, 0.0, 1e-10) << j;
    EXPECT_NEAR(t.modes[j].self_diagonal, 1.0, 1e-10) << j;  // the TAM carries each target's whole mass
    EXPECT_NEAR(t.modes[j].cross_diagonal, 1.0, 1e-10) << j;
  }
  EXPECT_EQ(t.tam_omega2.size(), 3);  // M_tam has rank 3 over 4 sensors: the TAM's modes are the targets
  // Guyan on the same four sensors is only approximate: the known answer above is not
  // the reduction's by construction.
  EXPECT_GT(worstFrequencyError(buildTam(input(c, P, 3), TamMethod::Guyan)), 1e-3);
}

TEST(Tam, GuyanIsExactWhenTheMassLiesOnTheKeptSet) {
  // Masses on the even coordinates, next to none on the odd ones: static condensation of
  // the odd ones loses no inertia.
  VectorXd m(10), k = VectorXd::LinSpaced(10, 800.0, 300.0);
  for (int i = 0; i < 10; ++i) m[i] = i % 2 == 0 ? 2.0 : 2e-12;
  const Chain c = chain(m, k);
  const MatrixXd P = reading(10, {0, 2, 4, 6, 8});
  const TamResult exact = buildTam(input(c, P, 5), TamMethod::Guyan);
  EXPECT_LT(worstFrequencyError(exact), 1e-9);
  EXPECT_TRUE(exact.pass);
  // With the mass spread over every coordinate Guyan errs, and IRS, which restores the
  // omitted inertia to first order, errs less on the lowest modes (the worst of the
  // first three: 11.9 % against 1.4 %).
  const Chain spread = chain(VectorXd::Constant(10, 1.0), k);
  const double guyan = worstFrequencyError(buildTam(input(spread, P, 3), TamMethod::Guyan));
  const double irs = worstFrequencyError(buildTam(input(spread, P, 3), TamMethod::Irs));
  EXPECT_GT(guyan, 1e-2);
  EXPECT_LT(irs, 0.25 * guyan);
}

TEST(Tam, AFailingModeIsNamedWithItsCriterion) {
  // Two sensors at the chain's root see its higher modes too little to separate them.
  const Chain c = chain(VectorXd::Constant(10, 1.0), VectorXd::Constant(10, 400.0));
  const TamResult t = buildTam(input(c, reading(10, {0, 1}), 2), TamMethod::Guyan);
  EXPECT_FALSE(t.pass);
  bool named = false;
  for (const auto& m : t.modes)
    if (!m.pass) named = named || m.reason.find("orthogonality") != std::string::npos;
  EXPECT_TRUE(named);
}

TEST(Tam, WhatCannotBeReducedIsANamedNumericalError) {
  const Chain c = chain(VectorXd::Constant(6, 1.0), VectorXd::Constant(6, 400.0));
  MatrixXd twice = reading(6, {1, 3});
  twice.row(1) = 2 * twice.row(0);  // two sensors reading one motion
  EXPECT_THROW(
      {
        try {
          buildTam(input(c, twice, 1), TamMethod::Guyan);
        } catch (const NumericalError& e) {
          EXPECT_NE(std::string(e.what()).find("dependent"), std::string::npos) << e.what();
          throw;
        }
      },
      NumericalError);
  EXPECT_THROW(buildTam(input(c, reading(6, {1, 3}), 3), TamMethod::Serep), OptionError);  // 2 sensors, 3 modes
  // A free end the sensors do not see: the omitted stiffness is singular.
  Chain free = c;
  free.K = MatrixXd::Zero(6, 6);
  free.K.topLeftCorner(3, 3) = c.K.topLeftCorner(3, 3);
  EXPECT_THROW(buildTam(input(free, reading(6, {0, 1, 2}), 2), TamMethod::Guyan), NumericalError);
}

}  // namespace
}  // namespace mmv
