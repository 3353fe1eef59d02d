// Sensor placement (sim/modes/sensor_placement.hpp) on textbook cases whose answers
// are computed here independently.

#include "sim/modes/sensor_placement.hpp"
#include "sim/modes/place_sensors.hpp"
#include "sim/scene/scene.hpp"

#include <gtest/gtest.h>

#include "article/section.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace mmv {
namespace {

/// The first k clamped-free Euler-Bernoulli mode shapes at m equally spaced stations
/// (x = L/m .. L): the cantilever case of Kammer's paper.
Eigen::MatrixXd cantileverShapes(int m, int k) {
  const double bl[] = {1.875104068711961, 4.694091132974175, 7.854757438237613, 10.99554073487547};
  Eigen::MatrixXd phi(m, k);
  for (int j = 0; j < k; ++j) {
    const double b = bl[j], s = (std::cosh(b) + std::cos(b)) / (std::sinh(b) + std::sin(b));
    for (int i = 0; i < m; ++i) {
      const double z = b * (i + 1.0) / m;
      phi(i, j) = std::cosh(z) - std::cos(z) - s * (std::sinh(z) - std::sin(z));
    }
  }
  return phi;
}

PlacementProblem uniaxial(const Eigen::MatrixXd& phi) {
  PlacementProblem p;
  p.phi = phi;
  p.block.resize(phi.rows());
  std::iota(p.block.begin(), p.block.end(), 0);
  p.row_mass = Eigen::VectorXd::Ones(phi.rows());
  p.omega = Eigen::VectorXd::LinSpaced(phi.cols(), 1.0, phi.cols());
  return p;
}

// Kammer's iterative deletion, written out independently: recompute the projector's
// diagonal from scratch and drop the smallest, until `count` remain.
std::vector<int> kammerByHand(const Eigen::MatrixXd& phi, int count, std::vector<int>& order) {
  std::vector<int> kept(phi.rows());
  std::iota(kept.begin(), kept.end(), 0);
  while (static_cast<int>(kept.size()) > count) {
    Eigen::MatrixXd A(kept.size(), phi.cols());
    for (std::size_t i = 0; i < kept.size(); ++i) A.row(i) = phi.row(kept[i]);
    const Eigen::MatrixXd E = A * (A.transpose() * A).inverse() * A.transpose();
    Eigen::Index worst;
    E.diagonal().minCoeff(&worst);
    order.push_back(kept[worst]);
    kept.erase(kept.begin() + worst);
  }
  return kept;
}

TEST(SensorPlacement, EffectiveIndependenceIsKammersDeletion) {
  const Eigen::MatrixXd phi = cantileverShapes(20, 3);
  for (int count : {3, 5, 8}) {
    std::vector<int> expected_order;
    const std::vector<int> expected = kammerByHand(phi, count, expected_order);
    const PlacementResult r = placeSensors(uniaxial(phi), PlacementMethod::EffectiveIndependence, count);
    EXPECT_EQ(r.kept_blocks, expected) << count;
    EXPECT_EQ(r.deletion_order, expected_order) << count;
    // The EfI values of a final set add up to the number of target modes (trace of a
    // rank-k projector).
    EXPECT_NEAR(r.block_score.sum(), 3.0, 1e-9);
  }
}

// For a count as small as the modes, compare with every subset: iterative deletion is a
// heuristic, but on the cantilever it finds the best Fisher determinant of all
// C(20, 3) = 1140 sets, and the tip is always in it (the classic result).
TEST(SensorPlacement, SmallCountMatchesExhaustiveSearch) {
  const Eigen::MatrixXd phi = cantileverShapes(20, 3);
  const PlacementResult r = placeSensors(uniaxial(phi), PlacementMethod::EffectiveIndependence, 3);
  double best = 0;
  for (int a = 0; a < 20; ++a)
    for (int b = a + 1; b < 20; ++b)
      for (int c = b + 1; c < 20; ++c) {
        Eigen::MatrixXd A(3, 3);
        A << phi.row(a), phi.row(b), phi.row(c);
        best = std::max(best, (A.transpose() * A).determinant());
      }
  EXPECT_NEAR(r.fisher_determinant, best, 1e-9 * best);
  EXPECT_NE(std::find(r.kept_blocks.begin(), r.kept_blocks.end(), 19), r.kept_blocks.end());
}

TEST(SensorPlacement, AutoMacOfOrthogonalShapesIsTheIdentity) {
  Eigen::MatrixXd q = Eigen::MatrixXd::Random(12, 4);
  const Eigen::HouseholderQR<Eigen::MatrixXd> qr(q);
  const Eigen::MatrixXd Q = qr.householderQ() * Eigen::MatrixXd::Identity(12, 4);
  EXPECT_LT((autoMac(Q) - Eigen::MatrixXd::Identity(4, 4)).cwiseAbs().maxCoeff(), 1e-12);
  Eigen::MatrixXd same = Q;
  same.col(1) = -2.0 * Q.col(0);  // the same shape, scaled: MAC 1
  EXPECT_NEAR(autoMac(same)(0, 1), 1.0, 1e-12);
}

// A triaxial block (here two rows of one station) is kept or removed as a whole.
TEST(SensorPlacement, BlocksAreKeptWhole) {
  const Eigen::MatrixXd a = cantileverShapes(10, 3), b = 0.3 * cantileverShapes(10, 3).colwise().reverse();
  PlacementProblem p;
  p.phi.resize(20, 3);
  for (int i = 0; i < 10; ++i) {
    p.phi.row(2 * i) = a.row(i);
    p.phi.row(2 * i + 1) = b.row(i);
    p.block.push_back(i);
    p.block.push_back(i);
  }
  p.row_mass = Eigen::VectorXd::Ones(20);
  p.omega = Eigen::VectorXd::Ones(3);
  const PlacementResult r = placeSensors(p, PlacementMethod::EffectiveIndependence, 3);
  EXPECT_EQ(r.kept_blocks.size(), 3u);
  EXPECT_EQ(rowsOfBlocks(p, r.kept_blocks).rows(), 6);  // both rows of every kept block
  EXPECT_EQ(r.deletion_order.size(), 7u);
  // Each deletion cost the least information among the blocks then present: check the
  // first one by hand.
  const Eigen::MatrixXd Qinv = (p.phi.transpose() * p.phi).inverse();
  double best = -1;
  int first = -1;
  for (int blk = 0; blk < 10; ++blk) {
    const Eigen::MatrixXd B = p.phi.middleRows(2 * blk, 2);
    const double keep = (Eigen::MatrixXd::Identity(2, 2) - B * Qinv * B.transpose()).determinant();
    if (keep > best) best = keep, first = blk;
  }
  EXPECT_EQ(r.deletion_order.front(), first);
}

// The rankings keep the largest scores: kinetic energy m sum phi^2, residue sum phi^2 / w.
TEST(SensorPlacement, RankingsKeepTheLargestScores) {
  Eigen::MatrixXd phi(4, 2);
  phi << 1, 0, 0, 3, 2, 0, 0, 1;
  PlacementProblem p = uniaxial(phi);
  p.row_mass << 1, 1, 1, 10;  // kinetic energy: 1, 9, 4, 10
  p.omega << 1, 10;           // residue: 1, 0.9, 4, 0.1
  EXPECT_EQ(placeSensors(p, PlacementMethod::ModalKineticEnergy, 2).kept_blocks, (std::vector<int>{1, 3}));
  EXPECT_EQ(placeSensors(p, PlacementMethod::DrivingPointResidue, 2).kept_blocks, (std::vector<int>{0, 2}));
  // Two sensors that see only mode 1 cannot tell mode 2 apart: singular, reported as such.
  const PlacementResult r = placeSensors(p, PlacementMethod::DrivingPointResidue, 2);
  EXPECT_EQ(r.fisher_determinant, 0.0);
  EXPECT_TRUE(std::isinf(r.fisher_condition));
}

// Modal kinetic energy weighs each station by its tributary mass: a link's stations sum
// to its own mass plus the tip mass and torquers it carries (before: rho A spacing at
// every station, the torquers and tip masses left out, so MKE ranked the station under
// torquer 2's 4.67 kg like any other), and the last station carries the lumps.
TEST(SensorPlacement, TributaryMassesSumToTheLinkAndWhatItCarries) {
  ArticleScene s = loadDefaultScene();
  PlacementOptions o;
  o.modes = modeNumbers({1, 2});
  o.count = 2;
  o.spacing_m = 0.1;
  o.method = PlacementMethod::ModalKineticEnergy;
  const PlacementStudy p = runPlacement(s, o);
  for (const auto& link : s.article.links) {
    SCOPED_TRACE(link.name);
    double sum = 0, last = 0;
    for (const auto& c : p.candidates)
      if (c.link == link.name && c.axis == "axial") sum += c.mass_kg, last = c.mass_kg;
    double carried = link.tip_mass ? link.tip_mass->mass : 0.0;
    for (const auto& j : s.article.joints)
      if (j.parent == link.name && j.torquer) carried += j.torquer->mass;
    const double own = s.article.findMaterial(link.material)->density * sectionArea(*s.article.findSection(link.section)) * link.length;
    EXPECT_NEAR(sum, own + carried, 1e-12 * (own + carried));
    EXPECT_GT(last, carried);
    if (link.name == "link1") EXPECT_GT(carried, 4.6);  // torquer 2, 4.67 kg, at link 1's tip
  }
}

}  // namespace
}  // namespace mmv

namespace mmv {
namespace {

// On the spatial article every station is a candidate along its normal too (3 per
// station), and for the out-of-plane target modes effective independence can only pick
// normal axes: the in-plane axes see nothing of them (the symmetric article does not
// couple the families). A triaxial block is all three axes.
TEST(SensorPlacement, SpatialCandidatesHaveANormalAxisThatOutOfPlaneModesNeed) {
  ArticleScene planar = loadDefaultScene();
  ArticleScene spatial = planar;
  spatial.article.model = ArticleModel::Spatial;
  PlacementOptions o;
  o.modes = modeNumbers({1});
  o.count = 1;
  const std::size_t planar_candidates = runPlacement(planar, o).candidates.size();
  o.modes = modeNumbers({2, 4, 6});  // link 1's and link 3's out-of-plane modes (3.05, 3.33, 3.45 Hz)
  o.count = 3;
  const PlacementStudy s = runPlacement(spatial, o);
  EXPECT_EQ(s.candidates.size(), planar_candidates / 2 * 3);
  ASSERT_EQ(s.result.kept_blocks.size(), 3u);
  for (int b : s.result.kept_blocks) EXPECT_EQ(s.candidates[b].axis, "normal") << s.candidates[b].station;
  o.triaxial = true;
  o.count = 3;  // their in-plane axes see nothing of these modes: one block per mode
  const PlacementStudy t = runPlacement(spatial, o);
  EXPECT_EQ(t.candidates.size(), planar_candidates / 2);
  EXPECT_EQ(t.candidates[0].axis, "triaxial");
}

}  // namespace
}  // namespace mmv
