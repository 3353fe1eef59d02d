#include "sim/statics/tree_operator.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "sim/model/article_builder.hpp"
#include "sim/scene/scene.hpp"
#include "sim/statics/linearize.hpp"
#include "sim/statics/statics.hpp"
#include "support/scenes.hpp"
#include "support/spatial_scenes.hpp"

namespace mmv {
namespace {

/// A state away from equilibrium (every coordinate moved), so no term vanishes by
/// balance: the operator must agree with Simbody's M and the closed-form K anywhere.
SimTK::State bentState(const Model& model) {
  SimTK::State st = model.getReferenceState();
  Eigen::VectorXd q = model.getQ(st);
  for (int i = 0; i < q.size(); ++i) q[i] += 0.03 * std::sin(1.3 * i + 0.4);
  model.setQ(st, q);
  model.getSystem().realize(st, SimTK::Stage::Position);
  return st;
}

double relativeGap(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
  return (a - b).cwiseAbs().maxCoeff() / b.cwiseAbs().maxCoeff();
}

/// The operator against the dense matrices of sim/statics/linearize.hpp (Simbody's
/// calcM and the closed-form stiffness), its products against dense products, and its
/// factorization against a dense solve and a dense LDL^T's inertia.
void expectAgreesWithDense(const ArticleScene& scene, const std::string& what) {
  SCOPED_TRACE(what);
  const auto model = buildArticleModel(scene);
  ASSERT_TRUE(TreeOperator::appliesTo(*model));
  const SimTK::State st = bentState(*model);
  const std::vector<int>& dofs = model->getDofs();
  const TreeOperator op(*model, st, dofs);
  const Eigen::MatrixXd M = calcMass(*model, st, dofs), K = calcStiffnessClosedForm(*model, st, dofs);
  const int n = op.size();
  ASSERT_EQ(n, static_cast<int>(dofs.size()));
  EXPECT_LT(relativeGap(op.denseM(), M), 1e-12);
  EXPECT_LT(relativeGap(op.denseK(), 0.5 * (K + K.transpose())), 1e-12);
  EXPECT_LT(relativeGap(op.diagonalM(), M.diagonal()), 1e-12);
  EXPECT_LT(relativeGap(op.diagonalK(), K.diagonal()), 1e-12);
  Eigen::VectorXd x(n);
  for (int i = 0; i < n; ++i) x[i] = std::cos(0.7 * i) + 0.1 * i / n;
  EXPECT_LT(relativeGap(op.multiplyM(x), M * x), 1e-12);
  EXPECT_LT(relativeGap(op.multiplyK(x), K * x), 1e-11);
  // Shifts below, between and above eigenvalues: the solve and the inertia.
  const Eigen::MatrixXd Ks = 0.5 * (K + K.transpose());
  const double scale = (Ks.diagonal().array() / M.diagonal().array()).abs().maxCoeff();
  for (double sigma : {-1e-3 * scale, 1e-5 * scale, 3e-3 * scale}) {
    const TreeFactor f = op.factor(sigma);
    ASSERT_TRUE(f.invertible()) << sigma;
    const Eigen::MatrixXd A = Ks - sigma * M;
    const Eigen::VectorXd y = f.solve(x);
    EXPECT_LT((A * y - x).norm(), 1e-9 * x.norm()) << sigma;
    const Eigen::LDLT<Eigen::MatrixXd> ldlt(A);
    EXPECT_EQ(f.negativePivots(), static_cast<int>((ldlt.vectorD().array() < 0).count())) << sigma;
    // L D L^T: backward(D^-1 forward(r)) is the solve; forward and backward are adjoint.
    const Eigen::VectorXd r = Eigen::VectorXd::LinSpaced(n, -1.0, 2.0);
    EXPECT_NEAR(f.forward(x).dot(r), x.dot(f.backward(r)), 1e-9 * x.norm() * r.norm() * n) << sigma;
  }
}

TEST(TreeOperator, EqualsTheDenseMatricesOnTheDefaultArticle) {
  ArticleScene s = loadDefaultScene();
  overrideSegments(s, 6);
  expectAgreesWithDense(s, "default article, 6 segments");
}

TEST(TreeOperator, EqualsTheDenseMatricesOnTheTableAndTheGimbal) {
  expectAgreesWithDense(loadArticleSceneFile(std::string(MMVLAB_SOURCE_DIR) + "/scenes/mmv-table.yaml"), "table");
  expectAgreesWithDense(loadArticleSceneFile(std::string(MMVLAB_SOURCE_DIR) + "/scenes/mmv-slew.yaml"), "gimbal");
}

TEST(TreeOperator, EqualsTheDenseMatricesOnAFloatingLinkAndFreePins) {
  ArticleScene floating = testing::cantileverScene(testing::Beam{}, 8, 9.81, 30.0);
  floating.article.base.type = BaseType::Floating;
  expectAgreesWithDense(floating, "floating link (planar mobilizer)");
  expectAgreesWithDense(testing::chainScene(5, 1.0, 1.0, 9.81, 0.4, 0.2), "chain of free pins");
}

// The spatial model: gimbal hinges (three angles per mobilizer, one block pivot each)
// whose rotation springs couple the angles; and a closed loop, which the operator cannot
// represent and refuses.
TEST(TreeOperator, EqualsTheDenseMatricesOnSpatialHingesAndRefusesClosedLoops) {
  const ArticleScene cantilever =
      testing::spatialCantilever(testing::explicitSection(1e-4, 1e-8, 2e-8, 1e-8), 2700, 70e9, 26e9, 1.0, 4);
  ASSERT_FALSE(buildArticleModel(cantilever)->getRotationSprings().empty());
  expectAgreesWithDense(cantilever, "spatial cantilever");
  ArticleScene spatial = testing::spatialDefault(4);
  spatial.gravity = {0, -9.81, 0};
  expectAgreesWithDense(spatial, "spatial default article");
  const auto closed = buildArticleModel(loadArticleSceneFile(std::string(MMVLAB_SOURCE_DIR) + "/scenes/mmv-closed.yaml"));
  EXPECT_FALSE(TreeOperator::appliesTo(*closed));
  // A free-floating spatial link (a component's free-free root): six coordinates on one
  // mobilizer, more than a node holds (it overran them: a crash in linearize). Refused,
  // and linearize takes Simbody's M and the closed-form K.
  ArticleScene floating = cantilever;
  floating.article.base.type = BaseType::Floating;
  const auto free_body = buildArticleModel(floating);
  EXPECT_FALSE(TreeOperator::appliesTo(*free_body));
  const SimTK::State st = bentState(*free_body);
  const LinearizedModel lin = linearize(*free_body, st);
  EXPECT_LT(relativeGap(lin.M, calcMass(*free_body, st, free_body->getDofs())), 1e-15);
}

// linearize's dense matrices on an open tree come from the operators (the tree's
// recursions): the same as Simbody's M and the closed-form K, at any size.
TEST(TreeOperator, LinearizeOnAnOpenTreeIsTheDenseMatrices) {
  ArticleScene s = loadDefaultScene();
  overrideSegments(s, 3);
  const auto model = buildArticleModel(s);
  const SimTK::State st = bentState(*model);
  const LinearizedModel lin = linearize(*model, st);
  const Eigen::MatrixXd K = calcStiffnessClosedForm(*model, st, model->getDofs());
  EXPECT_LT(relativeGap(lin.M, calcMass(*model, st, model->getDofs())), 1e-12);
  EXPECT_LT(relativeGap(lin.K, 0.5 * (K + K.transpose())), 1e-12);
  EXPECT_LT(relativeGap(lin.K_elastic + lin.K_geometric, lin.K), 1e-15);
  EXPECT_EQ(lin.Z.cols(), lin.M.rows());
}

// The pivots count the eigenvalues below a shift (the Sturm check of the partial eigen
// solution): at shifts between modes 1-2, 5-6 and 17-18 of the default article's
// equilibrium, and below all, against the dense solver's eigenvalues.
TEST(TreeOperator, PivotsCountTheModesBelowAShift) {
  ArticleScene s = loadDefaultScene();
  overrideSegments(s, 12);
  const auto model = buildArticleModel(s);
  const EquilibriumResult eq = solveEquilibrium(*model);
  ASSERT_TRUE(eq.converged);
  const TreeOperator op(*model, eq.state, model->getDofs());
  const Eigen::MatrixXd M = op.denseM(), K = op.denseK();
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> es(K, M, Eigen::EigenvaluesOnly);
  const Eigen::VectorXd w2 = es.eigenvalues();
  for (int k : {1, 5, 17}) {
    const double tau = 0.5 * (w2[k - 1] + w2[k]);
    EXPECT_EQ(op.factor(tau).negativePivots(), k) << k;
  }
  EXPECT_EQ(op.factor(-1.0).negativePivots(), 0);
}

}  // namespace
}  // namespace mmv
