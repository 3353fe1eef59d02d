// Stations (sim/scene/stations.hpp, sim/model/stations.hpp): names by position,
// interpolation with the beam's shape functions that converges with the mesh, and
// kinematics that are each other's derivatives.

#include "sim/model/stations.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "sim/model/article_builder.hpp"
#include "sim/modes/system_modes.hpp"
#include "support/scenes.hpp"
#include "support/spatial_scenes.hpp"

namespace mmv {
namespace {

TEST(Stations, NamesByDistanceFractionAndOffset) {
  const ArticleScene s = loadDefaultScene();  // link1 is 2.44 m
  std::string error;
  auto st = parseStation("link1@1.83m", s.article, error);
  ASSERT_TRUE(st) << error;
  EXPECT_EQ(st->link, "link1");
  EXPECT_DOUBLE_EQ(st->x, 1.83);
  st = parseStation("link1@0.75", s.article, error);
  ASSERT_TRUE(st) << error;
  EXPECT_DOUBLE_EQ(st->x, 0.75 * 2.44);
  st = parseStation("link1@0.75+0.0127m", s.article, error);
  ASSERT_TRUE(st) << error;
  EXPECT_DOUBLE_EQ(st->offset, 0.0127);
  st = parseStation("link3a@1e-1m-0.002m", s.article, error);
  ASSERT_TRUE(st) << error;
  EXPECT_DOUBLE_EQ(st->x, 0.1);
  EXPECT_DOUBLE_EQ(st->offset, -0.002);
  EXPECT_FALSE(parseStation("link9@0.5", s.article, error));
  EXPECT_NE(error.find("unknown link 'link9' (known: link1, link2, link3a, link3b)"), std::string::npos) << error;
  EXPECT_FALSE(parseStation("link1@3m", s.article, error));
  EXPECT_NE(error.find("outside link1 (0 to 2.44 m)"), std::string::npos) << error;
  EXPECT_FALSE(parseStation("link1@1.5", s.article, error));
  EXPECT_FALSE(parseStation("link1@abc", s.article, error));
  EXPECT_FALSE(parseStation("link1@0.5+2", s.article, error));  // an offset needs its unit
}

/// The first clamped-free Euler-Bernoulli mode shape at x over its value at the tip.
double cantileverShapeRatio(double x_over_l) {
  const double bl = 1.875104068711961;
  const double sigma = (std::cosh(bl) + std::cos(bl)) / (std::sinh(bl) + std::sin(bl));
  auto phi = [&](double z) { return std::cosh(bl * z) - std::cos(bl * z) - sigma * (std::sinh(bl * z) - std::sin(bl * z)); };
  return phi(x_over_l) / phi(1.0);
}

// A station's mode-shape value converges at second order to the Euler-Bernoulli shape
// at that point (a hinge name would sit at a different place on each mesh). Stations
// between nodes of the coarsest mesh are chosen so the interpolation, not the nodes,
// is tested. Measured: 4.8e-3, 1.2e-3, 3.0e-4, 7.4e-5 at 0.37 L for 8..64 segments
// (order 2.00). Tolerances: observed order 2 +- 0.3 (the model's own error is O(h^2));
// 2e-4 absolute at 64 segments.
TEST(Stations, ModeShapeConvergesAtSecondOrder) {
  const testing::Beam beam;
  for (double frac : {0.37, 0.81}) {
    std::vector<double> err;
    for (int n : {8, 16, 32, 64}) {
      ArticleScene s = testing::cantileverScene(beam, n, 0.0);
      const SolvedScene solved = solveScene(s);
      SimTK::State st = solved.equilibrium.state;
      solved.model->getSystem().realize(st, SimTK::Stage::Position);
      std::string error;
      const auto at = PointRef::resolve(*solved.model, s.article, "link1@" + std::to_string(frac), error);
      const auto tip = PointRef::resolve(*solved.model, s.article, "link1.tip", error);
      ASSERT_TRUE(at && tip) << error;
      const Eigen::VectorXd phi = solved.modes.shapes.col(0);
      const double ratio = (at->translationJacobian(st, solved.linearized.dofs) * phi)[1] /
                           (tip->translationJacobian(st, solved.linearized.dofs) * phi)[1];
      err.push_back(std::abs(ratio - cantileverShapeRatio(frac)));
    }
    for (std::size_t k = 1; k + 1 < err.size(); ++k) {
      const double order = std::log2(err[k] / err[k + 1]);
      EXPECT_NEAR(order, 2.0, 0.3) << "at " << frac << " L, errors " << err[k] << " -> " << err[k + 1];
    }
    EXPECT_LT(err.back(), 2e-4) << frac;
  }
}

// Velocity, acceleration and the Jacobian (`rows` of it) of station `name` of `s` are
// its position's derivatives (central differences: step 1e-6, truncation ~1e-12
// relative; tolerance 1e-6 relative), in an arbitrary moving state.
void expectConsistentKinematics(ArticleScene s, const std::string& name, int rows) {
  s.article.joints[0].hold = JointHold::Free;
  const auto model = buildArticleModel(s);
  SimTK::State st = model->getReferenceState();
  const int nq = model->getNumCoordinates();
  for (int i = 0; i < nq; ++i) {
    st.updQ()[model->getQIndex(i)] = 0.1 * std::sin(1.0 + i);
    st.updU()[model->getUIndex(i)] = 0.7 * std::cos(2.0 + i);
  }
  model->getSystem().realize(st, SimTK::Stage::Acceleration);
  std::string error;
  const auto p = PointRef::resolve(*model, s.article, name, error);
  ASSERT_TRUE(p) << error;
  const double dt = 1e-6;
  auto shifted = [&](double h) {
    SimTK::State x = st;
    for (int i = 0; i < nq; ++i) {
      x.updQ()[model->getQIndex(i)] += h * st.getU()[model->getUIndex(i)] + 0.5 * h * h * st.getUDot()[model->getUIndex(i)];
      x.updU()[model->getUIndex(i)] += h * st.getUDot()[model->getUIndex(i)];
    }
    model->getSystem().realize(x, SimTK::Stage::Velocity);
    return x;
  };
  const SimTK::State plus = shifted(dt), minus = shifted(-dt);
  const SimTK::Vec3 v_fd = (p->position(plus) - p->position(minus)) / (2 * dt);
  const SimTK::Vec3 a_fd = (p->velocity(plus) - p->velocity(minus)) / (2 * dt);
  EXPECT_LT((v_fd - p->velocity(st)).norm(), 1e-6 * p->velocity(st).norm());
  EXPECT_LT((a_fd - p->acceleration(st)).norm(), 1e-5 * p->acceleration(st).norm());
  std::vector<int> all(nq);
  for (int i = 0; i < nq; ++i) all[i] = i;
  const Eigen::MatrixXd J = p->translationJacobian(st, all, rows);
  ASSERT_EQ(J.rows(), rows);
  for (int c = 0; c < nq; ++c) {
    SimTK::State a = st, b = st;
    a.updQ()[model->getQIndex(c)] += dt;
    b.updQ()[model->getQIndex(c)] -= dt;
    model->getSystem().realize(a, SimTK::Stage::Position);
    model->getSystem().realize(b, SimTK::Stage::Position);
    const SimTK::Vec3 d = (p->position(a) - p->position(b)) / (2 * dt);
    for (int r = 0; r < rows; ++r) EXPECT_NEAR(J(r, c), d[r], 1e-6 * (1 + std::abs(d[r]))) << "row " << r << ", q " << c;
  }
  // The same formula as weighted body points (the shaker's stinger holds it between
  // nodes): its sum and its velocity are the station's, and its weights sum to 1.
  const StationPoint station(*model, *parseStation(name, s.article, error));
  const std::vector<WeightedPoint> w = station.weightedPoints();
  double total = 0;
  for (const WeightedPoint& x : w) total += x.weight;
  EXPECT_NEAR(total, 1.0, 1e-14);
  EXPECT_LT((model->findWeightedLocation(st, w) - p->position(st)).norm(), 1e-14);
  EXPECT_LT((model->findWeightedVelocity(st, w) - p->velocity(st)).norm(), 1e-12 * p->velocity(st).norm());
}

TEST(Stations, KinematicsAreConsistent) {
  expectConsistentKinematics(testing::cantileverScene(testing::Beam{}, 6, 9.81), "link1@0.43+0.01m", 2);
}

/// A spatial cantilever (support/spatial_scenes.hpp) of `segments` with a thick
/// rectangular-like section, so offsets of a centimetre are on its faces. Soft (E = 70
/// MPa): the differences above shift q by h^2 qdd / 2, whose error grows with the hinges'
/// stiffness (a torsion hinge of aluminium would give qdd ~ 1e7 rad/s^2).
ArticleScene spatialBeam(int segments) {
  return testing::spatialCantilever(testing::explicitSection(2e-4, 1e-9, 4e-9, 2e-9), 2700, 7e7, 2.6e7, 1.0,
                                    segments);
}

// On the spatial model, with offsets across the section and along its normal, in a
// state where every hinge twists and bends both ways.
TEST(Stations, KinematicsAreConsistentOutOfThePlane) {
  expectConsistentKinematics(spatialBeam(6), "link1@0.43+0.01m-0.02m", 3);
  expectConsistentKinematics(spatialBeam(6), "link1@0.43+0m+0.02m", 3);
}

// An offset point turns with the section: twisting the first hinge by theta rotates
// everything outboard rigidly about the link's axis, so a station at (y, z) on the
// section of an outboard piece goes to (y cos - z sin, y sin + z cos), exactly. (The
// planar model's offset, z x e, would not have turned.)
TEST(Stations, AnOffsetTurnsWithTheSectionsTwist) {
  const ArticleScene s = spatialBeam(4);
  const auto model = buildArticleModel(s);
  SimTK::State st = model->getReferenceState();
  const double theta = 0.3;
  for (int i = 0; i < model->getNumCoordinates(); ++i)
    if (model->getCoordinates()[i].name == "link1.h1.twist") st.updQ()[model->getQIndex(i)] = theta;
  model->getSystem().realize(st, SimTK::Stage::Position);
  std::string error;
  const double y = 0.01, z = -0.02;
  const auto p = PointRef::resolve(*model, s.article, "link1@0.6+0.01m-0.02m", error);
  ASSERT_TRUE(p) << error;
  const SimTK::Vec3 x = p->position(st);
  EXPECT_NEAR(x[0], 0.6, 1e-12);
  EXPECT_NEAR(x[1], y * std::cos(theta) - z * std::sin(theta), 1e-12);
  EXPECT_NEAR(x[2], y * std::sin(theta) + z * std::cos(theta), 1e-12);
}

TEST(Stations, OffsetsAlongTheNormalNeedTheSpatialModel) {
  const ArticleScene planar = loadDefaultScene();
  ArticleScene spatial = planar;
  spatial.article.model = ArticleModel::Spatial;
  std::string error;
  const auto st = parseStation("link3a@0.5+0m+0.004m", spatial.article, error);
  ASSERT_TRUE(st) << error;
  EXPECT_DOUBLE_EQ(st->offset, 0.0);
  EXPECT_DOUBLE_EQ(st->offset_z, 0.004);
  const auto both = parseStation("link3a@0.5-1e-3m-2e-3m", spatial.article, error);
  ASSERT_TRUE(both) << error;
  EXPECT_DOUBLE_EQ(both->offset, -1e-3);
  EXPECT_DOUBLE_EQ(both->offset_z, -2e-3);
  EXPECT_FALSE(parseStation("link3a@0.5+0m+0.004m", planar.article, error));
  EXPECT_NE(error.find("an offset out of the plane (+0.004m) needs model: spatial"), std::string::npos) << error;
  EXPECT_FALSE(parseStation("link3a@0.5+0m+0.004", spatial.article, error));  // the second needs its unit too
  EXPECT_NE(error.find("the offset along the section's normal is a signed distance in m"), std::string::npos) << error;
  EXPECT_FALSE(parseStation("link3a@0.5+0m0.004m", spatial.article, error));  // and its sign
}

// On a rigid link a station moves with the link exactly.
TEST(Stations, RigidLinkStationIsABodyPoint) {
  ArticleScene s = testing::cantileverScene(testing::Beam{}, 4, 9.81, 0.0, 0.0, true);
  const auto model = buildArticleModel(s);
  SimTK::State st = model->getReferenceState();
  st.updQ()[model->getQIndex(0)] = 0.4;
  model->getSystem().realize(st, SimTK::Stage::Position);
  std::string error;
  const auto p = PointRef::resolve(*model, s.article, "link1@0.3m", error);
  ASSERT_TRUE(p) << error;
  const SimTK::Vec3 x = p->position(st);
  EXPECT_NEAR(x[0], 0.3 * std::cos(0.4), 1e-12);
  EXPECT_NEAR(x[1], 0.3 * std::sin(0.4), 1e-12);
}

}  // namespace
}  // namespace mmv
