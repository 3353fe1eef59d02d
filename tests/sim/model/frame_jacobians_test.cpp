// Model::calcFrameJacobians (by the tree, sim/model/frame_jacobians.cpp) against
// Simbody's own SimbodyMatterSubsystem::calcFrameJacobian: the same matrix two ways, on
// the planar article, the spatial article and the table scene with its shaker armature,
// in states where every coordinate is away from zero. And Model::calcMassCentreCoupling
// (subtree masses and moments) against the sum of m_b J_b^T over Simbody's Jacobians of
// the bodies' mass centres.
#include <gtest/gtest.h>

#include <cmath>

#include "sim/model/article_builder.hpp"
#include "sim/scene/scene.hpp"
#include "support/scenes.hpp"
#include "support/spatial_scenes.hpp"

namespace mmv {
namespace {

void expectSimbodysJacobian(ArticleScene s) {
  for (auto& j : s.article.joints) j.hold = JointHold::Free;
  const auto model = buildArticleModel(s);
  SimTK::State st = model->getReferenceState();
  const int nq = model->getNumCoordinates();
  for (int i = 0; i < nq; ++i) st.updQ()[model->getQIndex(i)] += 0.2 * std::sin(1.0 + 0.7 * i);
  model->getSystem().realize(st, SimTK::Stage::Position);
  const SimTK::SimbodyMatterSubsystem& matter = model->getMatter();
  // Every body, at a point off its origin, and every other coordinate as the columns (a
  // column left out must not shift the others).
  std::vector<SimTK::MobilizedBodyIndex> bodies;
  std::vector<SimTK::Vec3> stations;
  for (int b = 1; b < matter.getNumBodies(); ++b) {
    bodies.push_back(SimTK::MobilizedBodyIndex(b));
    stations.push_back(SimTK::Vec3(0.03 * b, -0.02, 0.01 * (b % 3)));
  }
  std::vector<int> cols;
  for (int i = 0; i < nq; i += (i % 3 == 2 ? 2 : 1)) cols.push_back(i);
  const Eigen::MatrixXd J = model->calcFrameJacobians(st, bodies, stations, cols);
  SimTK::Array_<SimTK::MobilizedBodyIndex> b(bodies.begin(), bodies.end());
  SimTK::Array_<SimTK::Vec3> p(stations.begin(), stations.end());
  SimTK::Matrix ref;
  matter.calcFrameJacobian(st, b, p, ref);
  ASSERT_EQ(J.rows(), ref.nrow());
  ASSERT_EQ(J.cols(), static_cast<Eigen::Index>(cols.size()));
  double largest = 0, worst = 0;
  for (Eigen::Index j = 0; j < J.cols(); ++j)
    for (Eigen::Index i = 0; i < J.rows(); ++i) {
      const double r = ref(static_cast<int>(i), model->getUIndex(cols[static_cast<std::size_t>(j)]));
      largest = std::max(largest, std::abs(r));
      worst = std::max(worst, std::abs(J(i, j) - r));
    }
  EXPECT_GT(largest, 0.5);
  EXPECT_LT(worst, 1e-12 * largest) << bodies.size() << " frames, " << cols.size() << " columns";

  // The mass-centre coupling: sum_b m_b J_b^T e_a, Simbody's Jacobian rows summed.
  std::vector<SimTK::MobilizedBodyIndex> owners;
  std::vector<SimTK::Vec3> centres;
  std::vector<double> masses;
  for (const BodyInfo& body : model->getBodies()) {
    const SimTK::MassProperties mp = matter.getMobilizedBody(body.mobod).getBodyMassProperties(st);
    owners.push_back(body.mobod);
    centres.push_back(mp.getMassCenter());
    masses.push_back(mp.getMass());
  }
  SimTK::Array_<SimTK::MobilizedBodyIndex> ob(owners.begin(), owners.end());
  SimTK::Array_<SimTK::Vec3> oc(centres.begin(), centres.end());
  SimTK::Matrix Jc;
  matter.calcFrameJacobian(st, ob, oc, Jc);
  const Eigen::MatrixXd coupling = model->calcMassCentreCoupling(st, cols);
  ASSERT_EQ(coupling.rows(), static_cast<Eigen::Index>(cols.size()));
  ASSERT_EQ(coupling.cols(), 3);
  double big = 0, off = 0;
  for (std::size_t j = 0; j < cols.size(); ++j)
    for (int a = 0; a < 3; ++a) {
      double sum = 0;
      for (std::size_t b = 0; b < owners.size(); ++b)
        sum += masses[b] * Jc(static_cast<int>(6 * b + 3 + a), model->getUIndex(cols[j]));
      big = std::max(big, std::abs(sum));
      off = std::max(off, std::abs(coupling(static_cast<Eigen::Index>(j), a) - sum));
    }
  EXPECT_GT(big, 1.0);
  EXPECT_LT(off, 1e-12 * big) << owners.size() << " bodies";
}

TEST(FrameJacobians, AreSimbodysOnThePlanarArticle) {
  ArticleScene s = loadDefaultScene();
  overrideSegments(s, 4);
  expectSimbodysJacobian(s);
}

TEST(FrameJacobians, AreSimbodysOnTheSpatialArticle) { expectSimbodysJacobian(testing::spatialDefault(3)); }

TEST(FrameJacobians, AreSimbodysOnTheGimbal) {
  ArticleScene s = loadArticleSceneFile(std::string(MMVLAB_SOURCE_DIR) + "/scenes/mmv-slew.yaml");
  overrideSegments(s, 3);
  expectSimbodysJacobian(s);
}

TEST(FrameJacobians, AreSimbodysOnTheTableWithItsShaker) {
  ArticleScene s = loadArticleSceneFile(std::string(MMVLAB_SOURCE_DIR) + "/scenes/mmv-table.yaml");
  overrideSegments(s, 3);
  expectSimbodysJacobian(s);
}

}  // namespace
}  // namespace mmv
