// Bounded Levenberg-Marquardt and identifiability (sim/core/least_squares.hpp) on
// problems whose answers are known in closed form.
#include "sim/core/least_squares.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace mmv {
namespace {

/// y = a exp(-b t) at 12 times, weighted 1 / sigma.
LeastSquaresProblem decay(double a, double b, const std::vector<double>& noise = {}, double sigma = 1) {
  LeastSquaresProblem p;
  p.residuals = [=](const Eigen::VectorXd& q) -> std::optional<Eigen::VectorXd> {
    Eigen::VectorXd r(12);
    for (int k = 0; k < 12; ++k) {
      const double t = 0.25 * k, y = a * std::exp(-b * t) + (noise.empty() ? 0 : noise[static_cast<std::size_t>(k)]);
      r(k) = (q(0) * std::exp(-q(1) * t) - y) / sigma;
    }
    return r;
  };
  p.start = Eigen::Vector2d(1, 1);
  p.lower = Eigen::Vector2d(0.1, 0.01);
  p.upper = Eigen::Vector2d(10, 10);
  p.scale = Eigen::Vector2d(1, 1);
  return p;
}

TEST(LeastSquares, RecoversAnExactFitFromAFarStart) {
  const LeastSquaresResult r = solveBoundedLeastSquares(decay(3.0, 0.7));
  EXPECT_TRUE(r.converged) << r.stop;
  EXPECT_NEAR(r.p(0), 3.0, 1e-9);
  EXPECT_NEAR(r.p(1), 0.7, 1e-9);
  EXPECT_FALSE(r.at_bound[0]);
  EXPECT_TRUE(r.identifiability.undetermined.empty());
  EXPECT_GT(r.iterations.size(), 2u);  // it had to iterate: the start is far
  for (std::size_t k = 1; k < r.iterations.size(); ++k) EXPECT_LT(r.iterations[k].cost, r.iterations[k - 1].cost);
}

// The unconstrained minimum (b = 0.7) lies above the upper bound 0.5: the fit stops on
// the bound, says so, and the other parameter is the best one given it.
TEST(LeastSquares, AMinimumOutsideTheBoxEndsOnTheBoundFlagged) {
  LeastSquaresProblem p = decay(3.0, 0.7);
  p.upper(1) = 0.5;
  const LeastSquaresResult r = solveBoundedLeastSquares(p);
  EXPECT_TRUE(r.converged) << r.stop;
  EXPECT_DOUBLE_EQ(r.p(1), 0.5);
  EXPECT_TRUE(r.at_bound[1]);
  EXPECT_FALSE(r.at_bound[0]);
  // Given b = 0.5, the best a minimises sum (a e^{-0.5t} - 3 e^{-0.7t})^2: closed form.
  double num = 0, den = 0;
  for (int k = 0; k < 12; ++k) {
    const double t = 0.25 * k;
    num += std::exp(-0.5 * t) * 3 * std::exp(-0.7 * t);
    den += std::exp(-t);
  }
  EXPECT_NEAR(r.p(0), num / den, 1e-7);
}

// Residuals that depend on the product q0 q1 alone: one combination (the log-sum) is
// determined, the other (the ratio) not; neither parameter is reported as determined.
TEST(LeastSquares, AProductOfTwoParametersIsNamedAsUndetermined) {
  LeastSquaresProblem p;
  p.residuals = [](const Eigen::VectorXd& q) -> std::optional<Eigen::VectorXd> {
    Eigen::VectorXd r(5);
    for (int k = 0; k < 5; ++k) r(k) = 100 * (q(0) * q(1) * (1 + k) - 6.0 * (1 + k));
    return r;
  };
  p.start = Eigen::Vector2d(2, 2);
  p.lower = Eigen::Vector2d(0.5, 0.5);
  p.upper = Eigen::Vector2d(8, 8);
  p.scale = Eigen::Vector2d(2, 2);
  const LeastSquaresResult r = solveBoundedLeastSquares(p);
  EXPECT_NEAR(r.p(0) * r.p(1), 6.0, 1e-9);  // the product is fitted ...
  ASSERT_EQ(r.identifiability.undetermined.size(), 1u);  // ... the ratio is not
  const Eigen::Index u = r.identifiability.undetermined[0];
  // Along the ratio: relative changes of opposite signs, equal at the solution's scale.
  const Eigen::Vector2d v = r.identifiability.directions.col(u);
  EXPECT_LT(v(0) * v(1), 0);
  EXPECT_FALSE(r.identifiability.determined[0]);
  EXPECT_FALSE(r.identifiability.determined[1]);
  EXPECT_TRUE(std::isnan(r.identifiability.interval_half_width(0)));
}

// A linear model: the standard errors equal the textbook s sqrt(diag((X^T X)^-1)), and
// the interval's t is Student's for m - n degrees of freedom.
TEST(LeastSquares, LinearRegressionIntervalsMatchTheTextbook) {
  std::mt19937_64 rng(7);
  std::normal_distribution<double> n01(0, 1);
  const int m = 9;
  Eigen::MatrixXd X(m, 2);
  Eigen::VectorXd y(m);
  for (int k = 0; k < m; ++k) X(k, 0) = 1, X(k, 1) = k, y(k) = 2 + 0.5 * k + 0.3 * n01(rng);
  LeastSquaresProblem p;
  p.residuals = [&](const Eigen::VectorXd& q) -> std::optional<Eigen::VectorXd> { return Eigen::VectorXd(X * q - y); };
  p.start = Eigen::Vector2d(1, 1);
  p.lower = Eigen::Vector2d(-100, -100);
  p.upper = Eigen::Vector2d(100, 100);
  p.scale = Eigen::Vector2d(1, 1);
  LeastSquaresOptions o;
  o.undetermined_below = 0;  // the residuals carry no stated uncertainty here
  const LeastSquaresResult r = solveBoundedLeastSquares(p, o);
  const Eigen::Vector2d beta = (X.transpose() * X).ldlt().solve(X.transpose() * y);
  EXPECT_NEAR(r.p(0), beta(0), 1e-8);
  EXPECT_NEAR(r.p(1), beta(1), 1e-8);
  const double s2 = (X * beta - y).squaredNorm() / (m - 2);
  const Eigen::Matrix2d C = s2 * (X.transpose() * X).inverse();
  ASSERT_TRUE(r.identifiability.residual_variance.has_value());
  EXPECT_NEAR(*r.identifiability.residual_variance, s2, 1e-9 * s2);
  EXPECT_NEAR(r.identifiability.standard_error(0), std::sqrt(C(0, 0)), 1e-6 * std::sqrt(C(0, 0)));
  EXPECT_NEAR(r.identifiability.standard_error(1), std::sqrt(C(1, 1)), 1e-6 * std::sqrt(C(1, 1)));
  EXPECT_NEAR(r.identifiability.interval_half_width(1), 2.365 * std::sqrt(C(1, 1)), 1e-5);  // t(0.975, 7)
  EXPECT_NEAR(r.identifiability.correlation(0, 1), C(0, 1) / std::sqrt(C(0, 0) * C(1, 1)), 1e-6);
}

// A point the residual function refuses is never taken: the step shrinks instead.
TEST(LeastSquares, ARefusedRegionIsNeverSteppedInto) {
  LeastSquaresProblem p = decay(3.0, 0.7);
  int refused = 0;
  const auto inner = p.residuals;
  p.residuals = [&](const Eigen::VectorXd& q) -> std::optional<Eigen::VectorXd> {
    if (q(1) > 0.9) return ++refused, std::nullopt;  // e.g. no equilibrium there
    return inner(q);
  };
  p.start = Eigen::Vector2d(1, 0.05);  // unrefused, the first step goes to b = 0.935
  const LeastSquaresResult r = solveBoundedLeastSquares(p);
  EXPECT_NEAR(r.p(0), 3.0, 1e-8);
  EXPECT_NEAR(r.p(1), 0.7, 1e-8);
  for (const auto& it : r.iterations) EXPECT_LE(it.p(1), 0.9);
  EXPECT_GT(refused, 0);  // the region was met, and stepped around
}

// The pull toward the start: a weight w adds w (u - u0) rows; on a linear problem the
// answer is the ridge estimate (X^T X + w^2 I)^-1 (X^T y + w^2 u0), in closed form.
TEST(LeastSquares, RegularizationGivesTheRidgeEstimate) {
  Eigen::MatrixXd X(4, 2);
  X << 1, 0, 1, 1, 1, 2, 1, 3;
  const Eigen::Vector4d y(1.0, 2.9, 5.1, 7.0);
  LeastSquaresProblem p;
  p.residuals = [&](const Eigen::VectorXd& q) -> std::optional<Eigen::VectorXd> { return Eigen::VectorXd(X * q - y); };
  p.start = Eigen::Vector2d(0.5, 0.5);
  p.lower = Eigen::Vector2d(-10, -10);
  p.upper = Eigen::Vector2d(10, 10);
  p.scale = Eigen::Vector2d(1, 1);
  p.regularization = 2;
  const LeastSquaresResult r = solveBoundedLeastSquares(p);
  const Eigen::Vector2d ridge = (X.transpose() * X + 4 * Eigen::Matrix2d::Identity()).ldlt().solve(X.transpose() * y + 4 * p.start);
  EXPECT_NEAR(r.p(0), ridge(0), 1e-8);
  EXPECT_NEAR(r.p(1), ridge(1), 1e-8);
  EXPECT_EQ(r.residuals.size(), 4);  // the data's residuals, without the pull's rows
}

TEST(LeastSquares, StudentTQuantiles) {
  EXPECT_NEAR(studentT975(1), 12.706, 1e-3);
  EXPECT_NEAR(studentT975(30), 2.042, 1e-3);
  EXPECT_NEAR(studentT975(40), 2.021, 2e-3);   // tables: 2.021
  EXPECT_NEAR(studentT975(120), 1.980, 1e-3);  // tables: 1.980
  EXPECT_NEAR(studentT975(100000), 1.95996, 1e-4);
}

}  // namespace
}  // namespace mmv
