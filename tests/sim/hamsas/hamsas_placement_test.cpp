// Sensor placement on the isolator's bodies: each candidate's row is the body's motion
// at that point (checked against the spatial model's own point Jacobian), and the
// chosen set tells the target modes apart.
#include <gtest/gtest.h>

#include "sim/core/errors.hpp"
#include "sim/hamsas/hamsas_placement.hpp"
#include "sim/hamsas/spatial_linear.hpp"
#include "sim/modes/tam.hpp"

namespace mmv {
namespace {

const HamsasScene& isolator() {
  static const HamsasScene scene = loadHamsasSceneFile(std::string(MMVLAB_SOURCE_DIR) + "/scenes/hamsas.yaml");
  return scene;
}

TEST(HamsasPlacement, RowsAreThePointJacobianTimesTheShapes) {
  const HamsasModes h = analyseHamsas(isolator().isolator);
  const std::vector<ModeNumber> targets = modeNumbers({1, 4, 5, 7, 9});
  std::vector<PlacementCandidate> candidates;
  const PlacementProblem p = hamsasCandidates(h, targets, false, candidates);
  const int bodies = static_cast<int>(h.model.bodies.size());
  ASSERT_EQ(static_cast<int>(candidates.size()), 27 * (bodies - 1));  // 9 points x 3 axes per moving body
  ASSERT_EQ(p.phi.rows(), static_cast<Eigen::Index>(candidates.size()));
  Eigen::MatrixXd shapes(h.solution.shapes.rows(), static_cast<Eigen::Index>(targets.size()));
  for (std::size_t j = 0; j < targets.size(); ++j) shapes.col(static_cast<Eigen::Index>(j)) = h.solution.shapes.col(targets[j].index());
  double worst = 0, scale = 0;
  for (Eigen::Index r = 0; r < p.phi.rows(); r += 3) {
    const PlacementCandidate& c = candidates[static_cast<std::size_t>(r)];
    const int body = h.model.bodyIndex(c.link);
    ASSERT_GT(body, 0) << c.link;
    const Eigen::MatrixXd J = spatialPointJacobian(h.model, body, {c.world_x, c.world_y, c.world_z});
    const Eigen::MatrixXd u = J.rightCols(shapes.rows()) * shapes;  // the base's columns are not coordinates
    worst = std::max(worst, (u - p.phi.middleRows(r, 3)).cwiseAbs().maxCoeff());
    scale = std::max(scale, u.cwiseAbs().maxCoeff());
  }
  EXPECT_LT(worst, 1e-12 * scale);
  EXPECT_GT(scale, 0.0);
}

TEST(HamsasPlacement, ChosenSetTellsTheLowModesApart) {
  const HamsasModes h = analyseHamsas(isolator().isolator);
  PlacementOptions o;
  o.below_hz = 5;  // the nine isolation modes, 0.05 to 0.34 Hz
  o.count = 12;
  const PlacementStudy s = runHamsasPlacement(isolator(), h, o);
  EXPECT_EQ(s.target_modes.size(), 9u);
  EXPECT_EQ(s.result.kept_blocks.size(), 12u);
  EXPECT_GT(s.result.fisher_determinant, 0.0);
  EXPECT_LT(s.result.max_offdiagonal_mac, 0.1);
  o.triaxial = true;
  o.count = 4;
  const PlacementStudy t = runHamsasPlacement(isolator(), h, o);
  EXPECT_EQ(t.candidates.size(), 9u * (h.model.bodies.size() - 1));
  for (int b : t.result.kept_blocks) EXPECT_EQ(t.candidates[static_cast<std::size_t>(b)].axis, "triaxial");
  o.count = 1000;
  EXPECT_THROW(runHamsasPlacement(isolator(), h, o), UsageError);
}

// The isolator's test-analysis models (issue 34: --tam was refused on HAM-SAS). Each
// candidate's reading row times the shapes is its placement row (the TAM observes what
// the placement chose by); on nine sensors for the nine modes below 5 Hz, SEREP
// reproduces the targets (frequencies, self- and cross-orthogonality 1) and Guyan's
// frequencies lie at or above them (a Ritz reduction's upper bound). Twelve read only nine
// independent motions of the rigid bodies: a TAM needs independent directions, and says
// so by name.
TEST(HamsasPlacement, TamsOnTheChosenSensorsMeetTheirIdentities) {
  const HamsasModes h = analyseHamsas(isolator().isolator);
  const std::vector<ModeNumber> targets = modeNumbers({1, 2, 3});
  std::vector<PlacementCandidate> candidates;
  std::vector<Eigen::RowVectorXd> readings;
  const PlacementProblem p = hamsasCandidates(h, targets, false, candidates, &readings);
  ASSERT_EQ(readings.size(), static_cast<std::size_t>(p.phi.rows()));
  double worst = 0;
  for (std::size_t r = 0; r < readings.size(); ++r)
    for (std::size_t j = 0; j < targets.size(); ++j)
      worst = std::max(worst, std::abs(readings[r].dot(h.solution.shapes.col(targets[j].index())) - p.phi(static_cast<Eigen::Index>(r), static_cast<Eigen::Index>(j))));
  EXPECT_LT(worst, 1e-12 * p.phi.cwiseAbs().maxCoeff());
  PlacementOptions o;
  o.below_hz = 5;
  o.count = 12;
  o.tam = {TamMethod::Guyan, TamMethod::Serep};
  try {
    runHamsasPlacement(isolator(), h, o);
    ADD_FAILURE() << "twelve dependent directions made a TAM";
  } catch (const NumericalError& e) {
    EXPECT_NE(std::string(e.what()).find("are dependent"), std::string::npos) << e.what();
  }
  o.count = 9;
  const PlacementStudy s = runHamsasPlacement(isolator(), h, o);
  ASSERT_EQ(s.tams.size(), 2u);
  EXPECT_EQ(s.channels.size(), 9u);
  const TamResult& guyan = s.tams[0];
  const TamResult& serep = s.tams[1];
  ASSERT_EQ(serep.modes.size(), s.target_modes.size());
  for (std::size_t j = 0; j < serep.modes.size(); ++j) {
    EXPECT_NEAR(serep.modes[j].frequency_error, 0.0, 1e-6) << j;
    EXPECT_NEAR(serep.modes[j].self_diagonal, 1.0, 1e-6) << j;
    EXPECT_NEAR(serep.modes[j].cross_diagonal, 1.0, 1e-6) << j;
    EXPECT_GE(guyan.modes[j].frequency_error, -1e-6) << j;
  }
  EXPECT_TRUE(serep.pass);
}

}  // namespace
}  // namespace mmv
