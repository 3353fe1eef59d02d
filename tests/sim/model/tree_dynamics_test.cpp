// The own inverse dynamics (sim/model/tree_dynamics.hpp) against Simbody's
// calcResidualForceIgnoringConstraints, both from the same coordinates, rates,
// accelerations and time: on every shipped article scene it takes, and on scenes built
// to reach what the shipped ones do not (a gimbal slewing under the article, the table
// moving in and across the plane, torque programs, a point load, a damping matrix),
// at random states far from the start, to 1e-10 of the residual's scale.
#include "sim/model/tree_dynamics.hpp"

#include <gtest/gtest.h>

#include <random>

#include "sim/model/article_builder.hpp"
#include "sim/scene/scene.hpp"
#include "support/scenes.hpp"

namespace mmv {
namespace {

/// The largest difference between the two residuals over `trials` random states, over
/// the largest residual; the model's damping matrix (if any) set to a random one first.
double worstDifference(Model& model, int trials, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> uni(-1.0, 1.0);
  SimTK::State s = model.getReferenceState();
  if (model.hasLinearDamper()) {
    std::vector<int> coords;
    for (int i = 0; i < model.getNumCoordinates(); i += 2) coords.push_back(i);
    Eigen::MatrixXd A(coords.size(), coords.size());
    for (Eigen::Index r = 0; r < A.rows(); ++r)
      for (Eigen::Index c = 0; c < A.cols(); ++c) A(r, c) = uni(rng);
    model.setLinearDamping(coords, A * A.transpose());
  }
  const TreeDynamics tree(model, s);
  const int n = model.getNumCoordinates();
  double worst = 0;
  for (int trial = 0; trial < trials; ++trial) {
    Eigen::VectorXd q(n), u(n), udot(n), r;
    SimTK::Vector knownUdot(s.getNU(), 0.0), simbody;
    const double t = 0.5 * (1 + uni(rng));
    for (int i = 0; i < n; ++i) {
      q[i] = s.getQ()[model.getQIndex(i)] + 0.3 * uni(rng);
      u[i] = 2 * uni(rng);
      udot[i] = 20 * uni(rng);
      s.updQ()[model.getQIndex(i)] = q[i];
      s.updU()[model.getUIndex(i)] = u[i];
      knownUdot[model.getUIndex(i)] = udot[i];
    }
    s.setTime(t);
    const SimTK::MultibodySystem& sys = model.getSystem();
    sys.realize(s, SimTK::Stage::Dynamics);
    model.getMatter().calcResidualForceIgnoringConstraints(s, sys.getMobilityForces(s, SimTK::Stage::Dynamics),
                                                           sys.getRigidBodyForces(s, SimTK::Stage::Dynamics), knownUdot,
                                                           simbody);
    tree.residual(t, q, u, udot, r);
    double scale = 0, diff = 0;
    for (int i = 0; i < n; ++i) {
      scale = std::max(scale, std::abs(simbody[model.getUIndex(i)]));
      diff = std::max(diff, std::abs(r[i] - simbody[model.getUIndex(i)]));
    }
    worst = std::max(worst, diff / scale);
  }
  return worst;
}

double worstFor(const ArticleScene& scene, unsigned seed) {
  const auto model = buildArticleModel(scene, ModelUse::TimeRun);
  std::string why;
  EXPECT_TRUE(TreeDynamics::supports(*model, &why)) << scene.source << ": " << why;
  return worstDifference(*model, 20, seed);
}

TEST(TreeDynamics, EqualsSimbodysInverseDynamicsOnEveryShippedArticleSceneItTakes) {
  for (const char* name : {"mmv.yaml", "mmv-slew.yaml", "mmv-table.yaml", "spin-up-beam.yaml", "two-link-demo.yaml"}) {
    const ArticleScene scene = loadArticleSceneFile(std::string(MMVLAB_SOURCE_DIR "/scenes/") + name);
    const double worst = worstFor(scene, 1);
    std::printf("%s: %.2e\n", name, worst);
    EXPECT_LT(worst, 1e-10) << name;
  }
}

TEST(TreeDynamics, EqualsSimbodysWithAGimbalATableAcrossThePlaneProgramsLoadsAndDamping) {
  ArticleScene gimbal = loadDefaultScene();
  gimbal.article.base.gimbal = GimbalSpec{};
  gimbal.article.base.gimbal->pitch.angle = 0.3;
  gimbal.article.base.gimbal->roll.angle = -0.2;
  gimbal.article.base.gimbal->yaw.angle = 0.1;
  EXPECT_LT(worstFor(gimbal, 2), 1e-10);

  ArticleScene table = loadArticleSceneFile(MMVLAB_SOURCE_DIR "/scenes/mmv-table.yaml");
  table.article.base.motion_z = table.article.base.motion;
  table.article.joints[1].torque_input = table.article.base.motion;  // a joint's torque program
  EXPECT_LT(worstFor(table, 3), 1e-10);

  ArticleScene damped = loadDefaultScene();
  damped.damping = DampingSpec{};  // modal: the linear damping matrix (a random one here)
  LoadSpec load;
  load.point = "link2.tip";
  load.force = {3, -40, 0};
  damped.article.loads.push_back(load);
  const auto model = buildArticleModel(damped, ModelUse::TimeRun);
  EXPECT_TRUE(model->hasLinearDamper());
  EXPECT_LT(worstDifference(*model, 20, 4), 1e-10);
}

TEST(TreeDynamics, RefusesWhatItDoesNotWriteOut) {
  std::string why;
  const auto closed = buildArticleModel(loadArticleSceneFile(MMVLAB_SOURCE_DIR "/scenes/mmv-closed.yaml"), ModelUse::TimeRun);
  EXPECT_FALSE(TreeDynamics::supports(*closed, &why));
  EXPECT_EQ(why, "it has closures");
  ArticleScene spatial = loadDefaultScene();
  spatial.article.model = ArticleModel::Spatial;
  const auto sp = buildArticleModel(spatial, ModelUse::TimeRun);
  EXPECT_FALSE(TreeDynamics::supports(*sp, &why));
  EXPECT_NE(why.find("rotation springs"), std::string::npos) << why;
}

}  // namespace
}  // namespace mmv
