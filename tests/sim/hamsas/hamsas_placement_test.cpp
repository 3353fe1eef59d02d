// Sensor placement on the isolator's bodies: each candidate's row is the body's motion
// at that point (checked against the spatial model's own point Jacobian), and the
// chosen set tells the target modes apart.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>

#include "sim/core/errors.hpp"
#include "sim/hamsas/hamsas_placement.hpp"
#include "sim/hamsas/spatial_linear.hpp"
#include "sim/io/placement_geometry.hpp"
#include "sim/io/tam_report.hpp"
#include "sim/io/uff_read.hpp"
#include "sim/modes/tam.hpp"

namespace mmv {
namespace {

const HamsasScene& isolator() {
  static const HamsasScene scene = loadHamsasSceneFile(std::string(MMVLAB_SOURCE_DIR) + "/scenes/hamsas.yaml");
  return scene;
}

/// kg per sensor for the iterated placement's test: heavy enough that the passes move
/// sensors for real before a set carries itself (measured: 4 moved, then 1, then a tie).
constexpr double kIteratedSensorKg = 1.0;

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

// The isolator's test geometry (issue 34): a node per chosen point, numbered by body and
// point whatever else the run chose, read back from the UFF at the points and with the
// predicted shapes the placement chose by; a channel per chosen direction, and the TAM's
// .mat holding those channels (it held none before the isolator's directions were listed).
TEST(HamsasPlacement, TheTestGeometryHoldsTheChosenPointsByStableNodes) {
  const HamsasModes h = analyseHamsas(isolator().isolator);
  PlacementOptions o;
  o.below_hz = 5;
  o.count = 9;
  o.tam = {TamMethod::Serep};
  const PlacementStudy s = runHamsasPlacement(isolator(), h, o);
  const std::vector<PlacementChannel> channels = placementChannels(s);
  ASSERT_EQ(channels.size(), 9u);
  const uff::File back = uff::read(uff::write(placementGeometry(s, "hamsas")), "geometry.uff");
  std::map<int, std::array<double, 3>> nodes;
  for (const auto& n : back.nodes) nodes[n.label] = n.xyz;
  ASSERT_EQ(back.modes.size(), s.target_modes.size());
  for (const PlacementChannel& c : channels) {
    const PlacementCandidate& p = *c.candidate;
    const int body = h.model.bodyIndex(p.link);
    const bool corner = p.station.find(".corner") != std::string::npos;
    const int point = corner ? std::stoi(p.station.substr(p.station.find(".corner") + 7)) : 0;
    EXPECT_EQ(p.node, body * 100 + point) << p.station;
    ASSERT_TRUE(nodes.count(p.node)) << p.station;
    EXPECT_NEAR(nodes[p.node][0], p.world_x, 1e-9);
    EXPECT_NEAR(nodes[p.node][1], p.world_y, 1e-9);
    EXPECT_NEAR(nodes[p.node][2], p.world_z, 1e-9);
    // The channel's direction is its axis; the shape read back is the placement's row.
    const int a = c.direction->axis == "x" ? 0 : c.direction->axis == "y" ? 1 : 2;
    EXPECT_EQ(c.direction->world[static_cast<std::size_t>(a)], 1.0);
    for (std::size_t j = 0; j < back.modes.size(); ++j) {
      const auto& m = back.modes[j];
      const auto at = std::find(m.nodes.begin(), m.nodes.end(), p.node) - m.nodes.begin();
      ASSERT_LT(static_cast<std::size_t>(at), m.nodes.size());
      double scale = 0;  // the UFF's shape fields hold 6 significant digits
      for (const auto& t : m.translations) scale = std::max({scale, std::abs(t[0]), std::abs(t[1]), std::abs(t[2])});
      EXPECT_NEAR(m.translations[static_cast<std::size_t>(at)][static_cast<std::size_t>(a)], p.shape[j][static_cast<std::size_t>(a)],
                  1e-5 * scale);
    }
  }
  // The same point has the same node in a run that chooses differently.
  o.count = 12;
  const PlacementStudy more = runHamsasPlacement(isolator(), h, o);
  for (const auto& c : more.candidates)
    for (const auto& d : s.candidates)
      if (c.station == d.station) EXPECT_EQ(c.node, d.node);
  const MatContents mat = tamMat(s);
  for (const auto& [name, m] : mat.matrices)
    if (name == "ChannelNode" || name == "PhiA") EXPECT_EQ(m.rows(), 9) << name;
}

// The sensors' masses on the isolator (issue 34: --sensor-mass was refused on HAM-SAS).
// Without gravity the loading is the inertia's alone, so rebuilding the bodies (mass,
// mass centre, inertia) must give what adding each sensor's m J^T J to the mass matrix
// gives, and a light set's shift must be first-order perturbation theory's. With
// gravity the springs carry the added weight too.
TEST(HamsasPlacement, SensorMassesLoadTheIsolatorAsPointMassesOnItsBodies) {
  HamsasModes h = analyseHamsas(isolator().isolator);
  PlacementOptions o;
  o.below_hz = 5;
  o.count = 9;
  const PlacementStudy s = runHamsasPlacement(isolator(), h, o);
  // The rebuilt bodies hold the sensors' mass and first moment.
  const double m = 2.0;
  const SpatialSpec rebuilt = isolatorWithSensors(h.model, s, m);
  double before = 0, after = 0;
  Eigen::Vector3d moment_before = Eigen::Vector3d::Zero(), moment_after = Eigen::Vector3d::Zero();
  for (std::size_t b = 1; b < h.model.bodies.size(); ++b) {
    before += h.model.bodies[b].mass, after += rebuilt.bodies[b].mass;
    moment_before += h.model.bodies[b].mass * h.model.bodies[b].com;
    moment_after += rebuilt.bodies[b].mass * rebuilt.bodies[b].com;
  }
  for (int b : s.result.kept_blocks) {
    const PlacementCandidate& c = s.candidates[static_cast<std::size_t>(b)];
    moment_before += m * Eigen::Vector3d(c.world_x, c.world_y, c.world_z);
  }
  EXPECT_NEAR(after, before + 9 * m, 1e-9);
  EXPECT_LT((moment_after - moment_before).norm(), 1e-9 * before);

  // Weightless: the rebuilt isolator against the mass matrix plus m J^T J.
  h.model.gravity.setZero();
  h.lin = linearizeSpatial(h.model, h.spec.ideal_joints);
  h.solution = spatialModes(h.lin);
  // Weightless, the pendulums have no stiffness: their modes fall to zero. The targets
  // are the first six that keep a stiffness of their own.
  std::vector<int> stiff;
  for (int i = 0; i < static_cast<int>(h.solution.omega2.size()) && stiff.size() < 6; ++i)
    if (h.solution.frequencyHz(i) > 0.02) stiff.push_back(i + 1);
  PlacementOptions ow;
  ow.modes = modeNumbers(stiff);
  ow.count = 9;
  const PlacementStudy w = runHamsasPlacement(isolator(), h, ow);
  SpatialLinearization added = h.lin;
  for (int b : w.result.kept_blocks) {
    const PlacementCandidate& c = w.candidates[static_cast<std::size_t>(b)];
    const Eigen::MatrixXd J = spatialPointJacobian(h.model, h.model.bodyIndex(c.link), {c.world_x, c.world_y, c.world_z})
                                  .rightCols(added.num_free);
    added.M += m * J.transpose() * J;
  }
  added.Mz = added.Z.transpose() * added.M * added.Z;
  const ModalSolution by_matrix = spatialModes(added);
  const SensorLoading heavy = hamsasSensorLoading(h, w, m);
  ASSERT_EQ(heavy.modes.size(), 6u);
  for (const auto& mode : heavy.modes) {
    EXPECT_GT(mode.mac, 0.5);  // 18 kg on the bodies mixes a close pair (0.88)
    EXPECT_NEAR(mode.loaded_hz, by_matrix.frequencyHz(mode.loaded_mode.index()), 1e-8 * mode.loaded_hz);
  }
  const SensorLoading light = hamsasSensorLoading(h, w, 1e-3);
  for (const auto& mode : light.modes) {
    EXPECT_LT(mode.shift, 0.0);
    EXPECT_NEAR(mode.shift, mode.first_order, 0.01 * std::abs(mode.first_order)) << "mode " << mode.mode.number();
    EXPECT_FALSE(mode.beyond_first_order);
  }
  std::printf("[hamsas loading] weightless, 1 g sensors: mode 1 %.4g against first order %.4g\n", light.modes[0].shift,
              light.modes[0].first_order);
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

// --iterate-loaded on the isolator (issue 34): each pass places on the isolator rebuilt
// with the last set's masses. The candidates stay the bare isolator's points while the
// loaded bodies' mass centres move: a loaded pass's rows are the loaded model's own point
// Jacobian at those points times its shapes. The symmetric isolator's mirror points tie
// (nine sensors for nine modes: every kept one has EfI 1), so a pass that only swaps
// points as informative as the carried ones settles (LoadedIteration::tie); a set that
// settled, carried and placed once more by the placement's own core, comes back as
// informative; weightless sensors settle at once on the bare choice's information.
TEST(HamsasPlacement, AnIteratedSetCarriesItselfOnTheLoadedIsolator) {
  const HamsasModes h = analyseHamsas(isolator().isolator);
  PlacementOptions o;
  o.below_hz = 5;
  o.count = 9;
  o.sensor_mass_kg = kIteratedSensorKg;
  o.iterate_loaded = true;
  const PlacementStudy p = runHamsasPlacement(isolator(), h, o);
  ASSERT_TRUE(p.loading.has_value());
  const auto& it = p.loading->iterations;
  ASSERT_FALSE(it.empty());
  ASSERT_TRUE(it.back().settled) << "pass " << it.back().pass << ": " << it.back().changed << " changed";
  EXPECT_GE(it.size(), 2u);
  EXPECT_GT(it.front().changed, 0);
  EXPECT_FALSE(it.front().tie);  // the first pass moved sensors for real
  EXPECT_EQ(p.loading->sensors, 9);  // the loading is the final set's on the bare isolator, each sensor once
  EXPECT_TRUE(p.loading->weight_in_stiffness);

  // The isolator carrying the final set, its candidates at the bare points.
  const HamsasModes carrying = isolatorCarrying(h, p, o.sensor_mass_kg);
  const std::vector<ModeNumber> targets = placementTargets(carrying.solution, o);
  std::vector<PlacementCandidate> candidates;
  const PlacementProblem q = hamsasCandidates(carrying, targets, false, candidates, nullptr, &h.model);
  // The iterated study's target modes are those of the isolator carrying its set.
  for (std::size_t j = 0; j < targets.size(); ++j)
    EXPECT_NEAR(p.target_frequencies_hz[j], carrying.solution.frequencyHz(targets[j].index()), 1e-12 * p.target_frequencies_hz[j]);
  // Placed once more by the placement's core: the same set, or one as informative.
  const PlacementResult again = placeSensors(q, o.method, o.count);
  auto determinant = [&](const std::vector<int>& blocks) {  // det(A^T A) over the blocks' rows of q
    Eigen::MatrixXd Q = Eigen::MatrixXd::Zero(q.phi.cols(), q.phi.cols());
    for (Eigen::Index r = 0; r < q.phi.rows(); ++r)
      if (std::find(blocks.begin(), blocks.end(), q.block[static_cast<std::size_t>(r)]) != blocks.end())
        Q += q.phi.row(r).transpose() * q.phi.row(r);
    return Q.determinant();
  };
  std::vector<int> mine;
  for (int b : p.result.kept_blocks) {
    const PlacementCandidate& c = p.candidates[static_cast<std::size_t>(b)];
    const auto at = std::find_if(candidates.begin(), candidates.end(),
                                 [&](const PlacementCandidate& d) { return d.station == c.station && d.axis == c.axis; });
    ASSERT_NE(at, candidates.end());
    mine.push_back(static_cast<int>(at - candidates.begin()));
  }
  EXPECT_NEAR(determinant(mine), again.fisher_determinant, kTiedInformation * again.fisher_determinant);
  EXPECT_NEAR(p.result.fisher_determinant, determinant(mine), 1e-9 * determinant(mine));  // the study's own, on that model

  // Loaded rows at the bare points: the loaded model's point Jacobian there times its shapes.
  std::vector<PlacementCandidate> bare_points;
  hamsasCandidates(h, targets, false, bare_points);
  ASSERT_EQ(bare_points.size(), candidates.size());
  Eigen::MatrixXd shapes(carrying.solution.shapes.rows(), static_cast<Eigen::Index>(targets.size()));
  for (std::size_t j = 0; j < targets.size(); ++j) shapes.col(static_cast<Eigen::Index>(j)) = carrying.solution.shapes.col(targets[j].index());
  double worst = 0, scale = 0, moved = 0;
  for (std::size_t r = 0; r < candidates.size(); r += 3) {
    const PlacementCandidate &c = candidates[r], &b = bare_points[r];
    EXPECT_EQ(c.station, b.station);
    EXPECT_EQ(c.world_x, b.world_x);
    EXPECT_EQ(c.world_y, b.world_y);
    EXPECT_EQ(c.world_z, b.world_z);
    const int body = carrying.model.bodyIndex(c.link);
    moved = std::max(moved, (carrying.model.bodies[static_cast<std::size_t>(body)].com - h.model.bodies[static_cast<std::size_t>(body)].com).norm());
    const Eigen::MatrixXd u = spatialPointJacobian(carrying.model, body, {c.world_x, c.world_y, c.world_z}).rightCols(shapes.rows()) * shapes;
    worst = std::max(worst, (u - q.phi.middleRows(static_cast<Eigen::Index>(r), 3)).cwiseAbs().maxCoeff());
    scale = std::max(scale, u.cwiseAbs().maxCoeff());
  }
  EXPECT_GT(moved, 1e-4);  // the loaded mass centres did move: the check is not the bare one again
  EXPECT_LT(worst, 1e-12 * scale);

  // Weightless sensors settle at once, on a set as informative as the bare choice.
  o.sensor_mass_kg = 1e-9;
  const PlacementStudy light = runHamsasPlacement(isolator(), h, o);
  ASSERT_EQ(light.loading->iterations.size(), 1u);
  EXPECT_TRUE(light.loading->iterations[0].settled);
  PlacementOptions once = o;
  once.sensor_mass_kg = 0;
  once.iterate_loaded = false;
  const PlacementStudy bare = runHamsasPlacement(isolator(), h, once);
  EXPECT_NEAR(light.result.fisher_determinant, bare.result.fisher_determinant, 1e-6 * bare.result.fisher_determinant);
  std::printf("[hamsas iterate] %g kg sensors: %zu passes (first changed %d, last %d%s); mass centres moved up to %.3g m\n",
              kIteratedSensorKg, it.size(), it.front().changed, it.back().changed, it.back().tie ? ", a tie" : "", moved);
}
}  // namespace
}  // namespace mmv
