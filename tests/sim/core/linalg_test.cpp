#include "sim/core/linalg.hpp"

#include <gtest/gtest.h>

namespace mmv {
namespace {

// The aliased expression it replaces leaves the matrix unsymmetric; this one must not.
TEST(Linalg, SymmetrizeAveragesEachPairOnce) {
  Eigen::MatrixXd A = Eigen::MatrixXd::Random(37, 37);
  const Eigen::MatrixXd expected = 0.5 * (A + Eigen::MatrixXd(A.transpose()));
  symmetrize(A);
  EXPECT_EQ((A - A.transpose()).cwiseAbs().maxCoeff(), 0.0);
  EXPECT_LT((A - expected).cwiseAbs().maxCoeff(), 1e-15);
}

// A chain whose stiffnesses span 13 decades is invertible once equilibrated; a zero
// column is singular.
TEST(Linalg, EquilibratedLuJudgesTheProblemNotTheRawPivots) {
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(3, 3);
  K << 4e13, -4e13, 0, -4e13, 4e13 + 2.6, -2.6, 0, -2.6, 5.2;
  const EquilibratedLu lu(K);
  ASSERT_TRUE(lu.isInvertible());
  const Eigen::MatrixXd b = Eigen::MatrixXd::Ones(3, 1);
  const Eigen::MatrixXd x = lu.solve(b);  // backward error at round-off
  EXPECT_LT((K * x - b).cwiseAbs().maxCoeff() / (K.cwiseAbs().maxCoeff() * x.cwiseAbs().maxCoeff()), 1e-15);
  K.col(1).setZero();
  EXPECT_FALSE(EquilibratedLu(K).isInvertible());
}

}  // namespace
}  // namespace mmv
