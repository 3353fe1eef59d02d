// A model per link (`links[i].model`, docs/spatial.md): a planar link of a spatial
// article bends in its plane only. Its hinges are pins, which is the spatial link with
// its out-of-plane and torsion coordinates held: checked here against the full spatial
// model's own linearization with those rows and columns removed.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include <Eigen/Eigenvalues>

#include "sim/model/article_builder.hpp"
#include "sim/modes/cms.hpp"
#include "sim/modes/planarity.hpp"
#include "sim/modes/system_modes.hpp"
#include "sim/scene/scene.hpp"
#include "support/scenes.hpp"

namespace mmv {
namespace {

ArticleScene withPlanarLinks(ArticleScene s, const std::set<std::string>& planar) {
  s.article.model = ArticleModel::Spatial;
  for (auto& l : s.article.links)
    if (planar.count(l.name)) l.model = ArticleModel::Planar;
  return s;
}

/// omega^2 (ascending) of (M, K) restricted to the rows and columns `keep`.
Eigen::VectorXd restrictedSpectrum(const LinearizedModel& lin, const std::vector<int>& keep) {
  const Eigen::Index n = static_cast<Eigen::Index>(keep.size());
  Eigen::MatrixXd M(n, n), K(n, n);
  for (Eigen::Index i = 0; i < n; ++i)
    for (Eigen::Index j = 0; j < n; ++j) {
      M(i, j) = lin.M(keep[i], keep[j]);
      K(i, j) = 0.5 * (lin.K(keep[i], keep[j]) + lin.K(keep[j], keep[i]));
    }
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> es(K, M);
  return es.eigenvalues();
}

// Links 1 and 2 planar, link 3's branches spatial: the spectrum is the full spatial
// model's with links 1 and 2's twist and out-of-plane hinges held (their rows and
// columns removed from its M and K at the same equilibrium, where the symmetric article
// has them at zero), to 1e-9; the model carries 2 x 2 x 16 fewer coordinates.
TEST(SpatialLinks, APlanarLinkIsTheSpatialLinkWithItsOutOfPlaneHingesHeld) {
  ArticleScene full = loadDefaultScene();
  full.article.model = ArticleModel::Spatial;
  const ArticleScene mixed = withPlanarLinks(full, {"link1", "link2"});
  const SolvedScene f = solveScene(full), m = solveScene(mixed);
  std::vector<int> keep;
  for (std::size_t a = 0; a < f.linearized.dofs.size(); ++a) {
    const Coordinate& c = f.model->getCoordinates()[f.linearized.dofs[a]];
    const bool held = c.kind == CoordinateKind::Hinge && c.axis != HingeAxis::InPlane &&
                      (c.part == "link1" || c.part == "link2");
    if (!held) keep.push_back(static_cast<int>(a));
  }
  ASSERT_EQ(f.linearized.dofs.size() - keep.size(), 2u * 2u * 16u);
  ASSERT_EQ(m.linearized.dofs.size(), keep.size());
  const Eigen::VectorXd expected = restrictedSpectrum(f.linearized, keep);
  ASSERT_EQ(expected.size(), m.modes.omega2.size());
  for (Eigen::Index i = 0; i < expected.size(); ++i)
    EXPECT_NEAR(m.modes.omega2[i], expected[i], 1e-9 * std::abs(expected[i]) + 1e-9) << "mode " << i + 1;
  // Links 1 and 2 carry in-plane hinges only; link 3's out-of-plane family is still there.
  for (const auto& c : m.model->getCoordinates())
    if (c.kind == CoordinateKind::Hinge && (c.part == "link1" || c.part == "link2"))
      EXPECT_EQ(c.axis, HingeAxis::InPlane) << c.name;
  std::set<std::string> families;
  for (int i = 0; i < 12; ++i) families.insert(classifyMode(*m.model, m.linearized.dofs, m.modes.shapes.col(i)).label);
  EXPECT_TRUE(families.count("out-of-plane"));
}

// Every link planar: nothing can leave the plane, so a spatial article is the planar
// model (1e-9), open or closed; the closed tree's fixture then holds its point in the
// plane only (along z nothing moves it, and holding it there would over-constrain).
TEST(SpatialLinks, EveryLinkPlanarIsThePlanarModel) {
  for (const std::string file : {"", "mmv-closed.yaml"}) {
    const ArticleScene planar =
        file.empty() ? loadDefaultScene()
                     : std::get<ArticleScene>(loadSceneFile(std::string(MMVLAB_SOURCE_DIR) + "/scenes/" + file));
    std::set<std::string> all;
    for (const auto& l : planar.article.links) all.insert(l.name);
    const SolvedScene p = solveScene(planar), s = solveScene(withPlanarLinks(planar, all));
    EXPECT_TRUE(s.model->isSpatial());
    ASSERT_EQ(p.modes.omega2.size(), s.modes.omega2.size()) << file;
    for (Eigen::Index i = 0; i < p.modes.omega2.size(); ++i)
      EXPECT_NEAR(s.modes.omega2[i], p.modes.omega2[i], 1e-9 * p.modes.omega2[i]) << file << " mode " << i + 1;
    for (const auto& c : s.model->getClosures()) EXPECT_EQ(c.directions.size(), 2u) << file;
  }
}

// Craig-Bampton synthesis over a mixed article: each link's component is built with its
// own model (a planar link's interface is its in-plane rotation and deflection only), and
// with every component mode kept the synthesis is exact.
TEST(SpatialLinks, SynthesisWithEveryComponentModeIsExactOnAMixedArticle) {
  ArticleScene s = withPlanarLinks(loadDefaultScene(), {"link1", "link2"});
  for (auto& l : s.article.links) l.segments = 4;
  SynthesisOptions o;
  o.method = CmsMethod::CraigBampton;
  o.modes_per_link = 100;  // all of them
  o.compare_modes = 10;
  const SynthesisResult r = synthesize(s, o);
  ASSERT_EQ(r.rows.size(), 10u);
  for (const auto& row : r.rows)
    EXPECT_NEAR(row.synth_hz, row.full_hz, 1e-7 * row.full_hz) << "mode " << row.mode;
}

// A spatial link on a planar article is a contradiction the builder names.
TEST(SpatialLinks, ASpatialLinkNeedsASpatialArticle) {
  ArticleScene s = loadDefaultScene();
  s.article.links.back().model = ArticleModel::Spatial;
  EXPECT_THROW(buildArticleModel(s), std::invalid_argument);
}

}  // namespace
}  // namespace mmv
