// Model::calcFrameJacobians (by the tree, sim/model/frame_jacobians.cpp) against
// Simbody's own SimbodyMatterSubsystem::calcFrameJacobian: the same matrix two ways, on
// the planar article, the spatial article and the table scene with its shaker armature,
// in states where every coordinate is away from zero.
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
}

TEST(FrameJacobians, AreSimbodysOnThePlanarArticle) {
  ArticleScene s = loadDefaultScene();
  overrideSegments(s, 4);
  expectSimbodysJacobian(s);
}

TEST(FrameJacobians, AreSimbodysOnTheSpatialArticle) { expectSimbodysJacobian(testing::spatialDefault(3)); }

TEST(FrameJacobians, AreSimbodysOnTheTableWithItsShaker) {
  ArticleScene s = loadArticleSceneFile(std::string(MMVLAB_SOURCE_DIR) + "/scenes/mmv-table.yaml");
  overrideSegments(s, 3);
  expectSimbodysJacobian(s);
}

}  // namespace
}  // namespace mmv
