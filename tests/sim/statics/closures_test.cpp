#include "sim/statics/closures.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "sim/model/article_builder.hpp"
#include "sim/modes/system_modes.hpp"
#include "sim/statics/statics.hpp"
#include "support/scenes.hpp"

namespace mmv {
namespace {

using testing::Beam;

/// A horizontal beam on a free (pinned) root joint whose tip slides along the beam's
/// axis (held transversely): simply supported. An axial load -N at the tip compresses
/// it uniformly.
ArticleScene simplySupported(const Beam& b, int segments, double n_axial) {
  ArticleScene s = testing::cantileverScene(b, segments, 0.0);
  s.article.joints[0].hold = JointHold::Free;
  ClosureSpec c;
  c.name = "roller";
  c.point = "link1.tip";
  c.type = ClosureType::Slider;
  c.direction = 0.0;  // slides along +x, the beam's axis
  c.where = "<test>";
  s.article.closures.push_back(c);
  if (n_axial != 0) s.article.loads.push_back({"link1.tip", {-n_axial, 0, 0}, "<test>"});
  return s;
}

// docs/sources.md section 4 and the slides' validation example: a simply supported beam under
// axial compression N has f1(N) = f1(0) sqrt(1 - N/N_cr), N_cr = pi^2 E I / L^2, and
// f1(0) = (pi^2 / (2 pi L^2)) sqrt(E I / (rho A)). Measured at 64 segments: 0.000 %,
// 0.004 %, 0.015 %, 0.09 % at N/N_cr = 0, 0.3, 0.6, 0.9 (and 1 % at 0.99, where the
// sqrt magnifies the chain's small error in N_cr), so the test stops at 0.9 N_cr with
// the 0.5 %.
TEST(Closures, AxiallyLoadedSimplySupportedBeam) {
  const Beam b;
  const double ncr = M_PI * M_PI * b.bendingStiffness() / (b.length * b.length);
  const double f0 = M_PI * M_PI / (2 * M_PI * b.length * b.length) * std::sqrt(b.bendingStiffness() / b.massPerLength());
  for (double ratio : {0.0, 0.3, 0.6, 0.9}) {
    const ModesReport r = runModes(simplySupported(b, 64, ratio * ncr));
    ASSERT_TRUE(r.equilibrium_converged);
    ASSERT_EQ(r.closures.size(), 1u);
    const double expected = f0 * std::sqrt(1.0 - ratio);
    EXPECT_NEAR(r.modes[0].frequency_hz / expected, 1.0, 5e-3) << "N/Ncr = " << ratio;
    // The root pin and the roller give one fewer DOF than hinges + joint.
    EXPECT_EQ(static_cast<int>(r.modes.size()), r.model.num_dofs - 1);
  }
  // Past N_cr the straight beam is unstable, and says so.
  const ModesReport over = runModes(simplySupported(b, 64, 1.05 * ncr));
  EXPECT_FALSE(over.modes[0].stable);
}

// A preloaded closure: a cantilever under gravity whose tip is pinned where it would
// be unbent carries the load the tip would otherwise sag under. For a uniform
// clamped-pinned beam under its own weight w the tip reaction is 3 w L / 8
// (propped cantilever), within the discretization's O(1/N^2) error.
TEST(Closures, ProppedCantileverReaction) {
  const Beam b;
  ArticleScene s = testing::cantileverScene(b, 64, 9.81);
  ClosureSpec c;
  c.name = "prop";
  c.point = "link1.tip";
  c.type = ClosureType::Slider;  // a roller: holds y only (the beam is inextensible)
  c.where = "<test>";
  s.article.closures.push_back(c);
  const ModesReport r = runModes(s);
  const double w = b.massPerLength() * 9.81;
  EXPECT_NEAR(r.closures[0].fy / (3 * w * b.length / 8), 1.0, 1e-3);
  EXPECT_LT(r.closures[0].error_m, 1e-12);
  // The holding torque at the clamp drops from w L^2/2 to w L^2/8.
  EXPECT_NEAR(r.joints[0].torque_nm / (w * b.length * b.length / 8), 1.0, 1e-3);
}

// A pin closure (both directions) at the tip of a straight pinned beam: the axial
// direction cannot move (inextensible links), so the axial force is indeterminate.
// That must be named as over-constraining, with the closure's position.
TEST(Closures, PinAlongAStraightLinkIsOverConstrained) {
  ArticleScene s = simplySupported(Beam{}, 8, 0.0);
  s.article.closures[0].type = ClosureType::Pin;
  s.article.closures[0].where = "s.yaml:12:5";
  const auto model = buildArticleModel(s);
  try {
    solveEquilibrium(*model);
    FAIL() << "expected an over-constraint error";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("s.yaml:12:5: closures[0] 'roller' over-constrains the article"),
              std::string::npos)
        << e.what();
  }
}

TEST(Closures, DuplicateClosureIsOverConstrained) {
  ArticleScene s = simplySupported(Beam{}, 8, 0.0);
  s.article.closures.push_back(s.article.closures[0]);
  s.article.closures[1].name = "again";
  const auto model = buildArticleModel(s);
  EXPECT_THROW(solveEquilibrium(*model), SceneError);
}

// The closure Jacobian against central differences of the closure errors.
TEST(Closures, JacobianMatchesDifferences) {
  ArticleScene s = testing::cantileverScene(Beam{}, 6, 9.81);
  s.article.joints[0].hold = JointHold::Free;
  ClosureSpec c;
  c.name = "pin";
  c.point = "link1.tip";
  c.where = "<test>";
  s.article.closures.push_back(c);
  const auto model = buildArticleModel(s);
  SimTK::State st = model->getReferenceState();
  Eigen::VectorXd q = model->getQ(st);
  for (int i = 0; i < q.size(); ++i) q[i] += 0.1 * std::cos(2.3 * i);
  model->setQ(st, q);
  model->getSystem().realize(st, SimTK::Stage::Position);
  const Eigen::MatrixXd G = calcClosureJacobian(*model, st, model->getDofs());
  const double h = 1e-6;
  for (int j = 0; j < q.size(); ++j) {
    Eigen::VectorXd qp = q, qm = q;
    qp[j] += h;
    qm[j] -= h;
    SimTK::State sp = st, sm = st;
    model->setQ(sp, qp);
    model->setQ(sm, qm);
    model->getSystem().realize(sp, SimTK::Stage::Position);
    model->getSystem().realize(sm, SimTK::Stage::Position);
    const Eigen::VectorXd d = (calcClosureErrors(*model, sp) - calcClosureErrors(*model, sm)) / (2 * h);
    EXPECT_LT((d - G.col(j)).norm(), 1e-8) << "column " << j;
  }
}

}  // namespace
}  // namespace mmv
