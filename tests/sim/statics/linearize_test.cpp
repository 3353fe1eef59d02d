#include "sim/statics/linearize.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "sim/model/article_builder.hpp"
#include "sim/scene/scene.hpp"
#include "support/scenes.hpp"

namespace mmv {
namespace {

// Double pendulum of point masses m1 (end of link 1) and m2 (end of link 2) on
// near-massless rigid links, at an arbitrary (non-equilibrium) configuration
// theta1 (from hanging) and theta2 (relative). Analytic:
//   V = -m1 g l1 cos t1 - m2 g (l1 cos t1 + l2 cos(t1 + t2))
//   K = Hessian of V, M from the kinetic energy.
// The rods weigh 1e-9 of the point masses, so 1e-7 relative is the stated tolerance;
// the finite-difference error of K is ~1e-10.
TEST(Linearize, DoublePendulumMassAndStiffnessMatchAnalytic) {
  const double l = 0.8, m1 = 1.5, m2 = 0.7, g = 9.81, t1 = 0.3, t2 = -0.5;
  ArticleScene s = testing::chainScene(2, 2 * l, 1e-9, g, m1, m2);
  const auto model = buildArticleModel(s);
  SimTK::State st = model->getReferenceState();
  model->setQ(st, Eigen::Vector2d(t1, t2));
  const std::vector<int> dofs{0, 1};
  const Eigen::MatrixXd K = calcStiffness(*model, st, dofs);
  const Eigen::MatrixXd M = calcMass(*model, st, dofs);

  const double c1 = std::cos(t1), c12 = std::cos(t1 + t2), c2 = std::cos(t2);
  Eigen::Matrix2d Ka, Ma;
  Ka << m1 * g * l * c1 + m2 * g * (l * c1 + l * c12), m2 * g * l * c12,  //
      m2 * g * l * c12, m2 * g * l * c12;
  Ma << m1 * l * l + m2 * (2 * l * l + 2 * l * l * c2), m2 * (l * l + l * l * c2),  //
      m2 * (l * l + l * l * c2), m2 * l * l;
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) {
      EXPECT_NEAR(K(i, j), Ka(i, j), 1e-7 * Ka.norm()) << i << j;
      EXPECT_NEAR(M(i, j), Ma(i, j), 1e-7 * Ma.norm()) << i << j;
    }
}

// The closed-form stiffness and central differences are independent evaluations of
// the same K: they must agree to the differences' truncation error (~1e-9 relative)
// on the default MMV article (branches, torquers, gravity) at its deflected
// equilibrium and at an arbitrary bent state.
TEST(Linearize, ClosedFormStiffnessEqualsFiniteDifferences) {
  const auto model = buildArticleModel(loadDefaultScene());
  ASSERT_TRUE(model->hasClosedFormForces());
  SimTK::State st = model->getReferenceState();
  Eigen::VectorXd q = model->getQ(st);
  for (int i = 0; i < q.size(); ++i) q[i] += 0.02 * std::sin(1.7 * i);  // bend everything
  model->setQ(st, q);
  const Eigen::MatrixXd Kc = calcStiffnessClosedForm(*model, st, model->getDofs());
  const Eigen::MatrixXd Kd = calcStiffnessByDifferences(*model, st, model->getDofs());
  EXPECT_LT((Kc - Kd).cwiseAbs().maxCoeff(), 1e-9 * Kc.cwiseAbs().maxCoeff());
  // The gravity part alone (springs removed) must agree as well, relative to its size.
  Eigen::MatrixXd Gc = Kc, Gd = Kd;
  for (int a = 0; a < Gc.rows(); ++a) {
    const double k = model->getCoordinates()[model->getDofs()[a]].stiffness;
    Gc(a, a) -= k;
    Gd(a, a) -= k;
  }
  EXPECT_LT((Gc - Gd).cwiseAbs().maxCoeff(), 1e-6 * Gc.cwiseAbs().maxCoeff());
}

// Springs give the elastic part exactly; with gravity off the geometric part vanishes.
TEST(Linearize, ElasticPartIsTheSpringStiffness) {
  testing::Beam b;
  ArticleScene s = testing::cantileverScene(b, 8, 0.0);
  const auto model = buildArticleModel(s);
  const LinearizedModel lin = linearize(*model, model->getReferenceState());
  ASSERT_EQ(lin.dofs.size(), 8u);
  const double k = b.bendingStiffness() / (b.length / 8);
  for (int i = 0; i < 8; ++i) EXPECT_NEAR(lin.K_elastic(i, i), k, 1e-12 * k);
  EXPECT_LT(lin.K_geometric.cwiseAbs().maxCoeff(), 1e-8 * k);
  EXPECT_LT(lin.asymmetry, 1e-8);
}

}  // namespace
}  // namespace mmv
