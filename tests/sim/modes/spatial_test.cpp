// The spatial article model (`model: spatial`, docs/spatial.md): against the planar
// model it extends, the closed forms of out-of-plane bending and torsion, its own
// stiffness by differences, and the planarity report.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>

#include <Eigen/Eigenvalues>

#include "article/beam_theory.hpp"
#include "facility/slews.hpp"
#include "sim/model/article_builder.hpp"
#include "sim/modes/planarity.hpp"
#include "sim/modes/system_modes.hpp"
#include "sim/scene/scene.hpp"
#include "sim/time/simulation.hpp"
#include "support/record_column.hpp"
#include "support/scenes.hpp"
#include "support/spatial_scenes.hpp"

namespace mmv {
namespace {

/// The stable frequencies (Hz) of each mode family, ascending.
std::map<std::string, std::vector<double>> familyFrequencies(const ArticleScene& scene) {
  const SolvedScene s = solveScene(scene);
  std::map<std::string, std::vector<double>> out;
  for (int i = 0; i < s.modes.omega2.size(); ++i) {
    if (!s.modes.isStable(i) || s.modes.isRigidBody(i)) continue;
    out[classifyMode(*s.model, s.linearized.dofs, s.modes.shapes.col(i)).label].push_back(s.modes.frequencyHz(i));
  }
  return out;
}

/// Richardson's O(1/N^2) extrapolation of family `family`'s first `count` frequencies
/// from n and 2n segments.
std::vector<double> extrapolated(const std::function<ArticleScene(int)>& scene, int n, const std::string& family,
                                 int count) {
  const auto coarse = familyFrequencies(scene(n)).at(family), fine = familyFrequencies(scene(2 * n)).at(family);
  std::vector<double> out;
  for (int k = 0; k < count; ++k) out.push_back((4 * fine.at(k) - coarse.at(k)) / 3);
  return out;
}


ArticleScene shippedScene(const std::string& name) {
  return std::get<ArticleScene>(loadSceneFile(std::string(MMVLAB_SOURCE_DIR) + "/scenes/" + name));
}

/// With the out-of-plane and torsion coordinates held, the spatial model of `planar_scene`
/// is the planar one: the same equilibrium and the same modes.
void expectLockedSpatialIsPlanar(const ArticleScene& planar_scene) {
  ArticleScene locked = planar_scene;
  locked.article.model = ArticleModel::Spatial;
  locked.article.lock_out_of_plane = true;
  const SolvedScene planar = solveScene(planar_scene), spatial = solveScene(locked);
  ASSERT_EQ(planar.modes.omega2.size(), spatial.modes.omega2.size());
  for (int i = 0; i < planar.modes.omega2.size(); ++i)
    EXPECT_NEAR(spatial.modes.omega2[i], planar.modes.omega2[i], 1e-9 * planar.modes.omega2[i]) << "mode " << i + 1;
  SimTK::State a = planar.equilibrium.state, b = spatial.equilibrium.state;
  planar.model->getSystem().realize(a, SimTK::Stage::Position);
  spatial.model->getSystem().realize(b, SimTK::Stage::Position);
  for (const auto& p : planar.model->getPoints()) {
    const SimTK::Vec3 xa = planar.model->findPointLocation(a, p), xb = spatial.model->findPointLocation(b, *spatial.model->findPoint(p.name));
    EXPECT_LE((xa - xb).norm(), 1e-9 * std::max(xa.norm(), 1.0)) << p.name;
  }
}

// The default article, 16 segments, where the pieces need no inertia correction.
TEST(Spatial, LockedOutOfPlaneIsThePlanarModel) { expectLockedSpatialIsPlanar(loadDefaultScene()); }

// The closed tree (link 3a's tip pinned to a fixture): the closure's out-of-plane row
// has nothing to hold once the out-of-plane coordinates are, so the locked model has
// the planar closure.
TEST(Spatial, LockedClosedTreeIsThePlanarClosedTree) { expectLockedSpatialIsPlanar(shippedScene("mmv-closed.yaml")); }

// Free out of the plane, the closed tree's pin holds the point along z as well (a ball
// joint): its in-plane family is still the planar spectrum (the symmetric article does
// not couple them), the fixture's point stays on its anchor in all three directions in
// every mode, and the closure adds out-of-plane stiffness: link 3's first out-of-plane
// pair rises above that of the open tree, whose link-3a tip is free.
TEST(Spatial, ClosedTreeHoldsThePointOutOfThePlane) {
  const ArticleScene closed_planar = shippedScene("mmv-closed.yaml");
  ArticleScene closed = closed_planar;
  closed.article.model = ArticleModel::Spatial;
  const SolvedScene planar = solveScene(closed_planar), spatial = solveScene(closed);
  const auto families = familyFrequencies(closed);
  const auto& in_plane = families.at("in-plane");
  for (int i = 0; i < 8; ++i)
    EXPECT_NEAR(in_plane.at(i), planar.modes.frequencyHz(i), 1e-9 * planar.modes.frequencyHz(i)) << "mode " << i + 1;
  ASSERT_EQ(spatial.model->getClosures().size(), 1u);
  EXPECT_EQ(spatial.model->getClosures()[0].directions.size(), 3u);
  SimTK::State st = spatial.equilibrium.state;
  spatial.model->getSystem().realize(st, SimTK::Stage::Position);
  const auto tipMotion = [&](const std::string& name) {
    const NamedPoint& p = *spatial.model->findPoint(name);
    const Eigen::MatrixXd J = spatial.model->calcFrameJacobians(st, {p.mobod}, {p.station_B}, spatial.linearized.dofs);
    return Eigen::MatrixXd(J.middleRows(3, 3) * spatial.modes.shapes.leftCols(20));
  };
  const Eigen::MatrixXd held = tipMotion("link3a.tip"), free_tip = tipMotion("link3b.tip");
  for (int m = 0; m < 20; ++m)
    EXPECT_LE(held.col(m).norm(), 1e-9 * free_tip.col(m).norm()) << "mode " << m + 1;
  ArticleScene open = closed;
  open.article.closures.clear();
  const auto open_out = familyFrequencies(open).at("out-of-plane");
  const auto& closed_out = families.at("out-of-plane");
  EXPECT_GT(closed_out.at(0), open_out.at(0));
}
// Past 18 segments per link, link 1's half pieces are shorter than sqrt(6 (I + I_out) / A)
// and their bending moments get the least addition that keeps them rigid bodies
// (article_builder.cpp): the model still builds (Simbody checks every inertia), and the
// in-plane family stays within 1e-3 of the planar model at the same mesh (the addition
// is of the order of the section's rotary inertia).
TEST(Spatial, FineMeshesKeepThePiecesPhysicalAndThePlanarSpectrum) {
  ArticleScene spatial = testing::spatialDefault(), planar = loadDefaultScene();
  overrideSegments(spatial, 48);
  overrideSegments(planar, 48);
  const std::vector<double> in_plane = familyFrequencies(spatial).at("in-plane");
  const ModesSolve p = solveSceneModes(planar, {}, 8);
  for (int i = 0; i < 8; ++i) {
    EXPECT_NEAR(in_plane[i], p.frequencies_hz[i], 1e-3 * p.frequencies_hz[i]) << "mode " << i + 1;
    EXPECT_NE(in_plane[i], p.frequencies_hz[i]);  // the addition is there
  }
}

// Free to leave the plane, the symmetric planar article keeps every planar mode: its
// in-plane family is the planar spectrum (the families do not couple).
TEST(Spatial, InPlaneFamilyOfTheFreeModelIsThePlanarSpectrum) {
  const std::vector<double> in_plane = familyFrequencies(testing::spatialDefault()).at("in-plane");
  const SolvedScene planar = solveScene(loadDefaultScene());
  ASSERT_EQ(static_cast<Eigen::Index>(in_plane.size()), planar.modes.omega2.size());
  for (std::size_t i = 0; i < in_plane.size(); ++i)
    EXPECT_NEAR(in_plane[i], planar.modes.frequencyHz(static_cast<int>(i)), 1e-9 * in_plane[i]) << i;
}

// The closed form of the spatial stiffness (every rotation about its own axis,
// linearize.hpp) and central differences agree on the article rolled 20 deg by the
// gimbal (gravity out of its plane) and bent in all three directions.
TEST(Spatial, ClosedFormStiffnessEqualsFiniteDifferences) {
  ArticleScene scene = testing::spatialDefault();
  scene.article.base.gimbal = GimbalSpec{};
  scene.article.base.gimbal->roll.angle = 20 * M_PI / 180;
  const auto model = buildArticleModel(scene);
  ASSERT_TRUE(model->hasClosedFormForces() && model->isSpatial());
  SimTK::State st = model->getReferenceState();
  Eigen::VectorXd q = model->getQ(st);
  for (int i = 0; i < q.size(); ++i) q[i] += 0.02 * std::sin(1.7 * i);
  model->setQ(st, q);
  const Eigen::MatrixXd Kc = calcStiffnessClosedForm(*model, st, model->getDofs());
  const Eigen::MatrixXd Kd = calcStiffnessByDifferences(*model, st, model->getDofs());
  Eigen::MatrixXd Gc = Kc, Gd = Kd;  // the gravity part alone, relative to its own size
  for (int a = 0; a < Gc.rows(); ++a) {
    const double k = model->getCoordinates()[model->getDofs()[a]].stiffness;
    Gc(a, a) -= k;
    Gd(a, a) -= k;
  }
  EXPECT_LT((Gc - Gd).cwiseAbs().maxCoeff(), 1e-7 * Gc.cwiseAbs().maxCoeff());
  EXPECT_LT((Kc - Kd).cwiseAbs().maxCoeff(), 1e-9 * Kc.cwiseAbs().maxCoeff());
}

// Out-of-plane bending of a cantilever with a tip mass: the in-plane roots with I_out.
TEST(Spatial, OutOfPlaneCantileverWithTipMassMatchesTheClosedForm) {
  const double rho = 2700, E = 70e9, L = 1.0, A = 1e-3, I = 1e-9, I_out = 4e-9, mu = 0.5;
  const Section sec = testing::explicitSection(A, I, I_out, 2e-9);
  auto scene = [&](int n) { return testing::spatialCantilever(sec, rho, E, 26e9, L, n, mu * rho * A * L); };
  const std::vector<double> roots = cantileverTipMassRoots(mu, 3);
  const std::vector<double> out = extrapolated(scene, 32, "out-of-plane", 3), in = extrapolated(scene, 32, "in-plane", 3);
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(out[k], beamFrequencyHz(roots[k], L, E * I_out, rho * A), 1e-6 * out[k]) << "out-of-plane " << k + 1;
    EXPECT_NEAR(in[k], beamFrequencyHz(roots[k], L, E * I, rho * A), 1e-6 * in[k]) << "in-plane " << k + 1;
  }
}

// Free torsion of a uniform round shaft carrying a tip disk of polar inertia J_d about
// the shaft: beta tan beta = rho I_p L / J_d, omega = (beta / L) sqrt(G J / (rho I_p)).
TEST(Spatial, TorsionOfAShaftWithATipDiskMatchesTheTanRelation) {
  const double R = 0.005, rho = 2000, E = 60e9, G = 6e9, L = 1.0;
  Section rod;
  rod.shape = SectionShape::RoundRod;
  rod.radius = R;
  const double Ip = M_PI * std::pow(R, 4) / 2, disk = 2e-6;  // the lumped mass's rotary inertia about x is J/2
  auto scene = [&](int n) { return testing::spatialCantilever(rod, rho, E, G, L, n, 0.05, 2 * disk); };
  const double ratio = rho * Ip * L / disk;
  const std::vector<double> beta =
      findRoots([&](double b) { return b * std::sin(b) - ratio * std::cos(b); }, 1e-6, 12.0, 1e-3, 3);
  ASSERT_EQ(beta.size(), 3u);
  const std::vector<double> f = extrapolated(scene, 32, "torsion", 3);
  for (int k = 0; k < 3; ++k) {
    const double closed = beta[k] / L * std::sqrt(G * Ip / (rho * Ip)) / (2 * M_PI);
    EXPECT_NEAR(f[k], closed, 1e-6 * closed) << "torsion mode " << k + 1;
  }
}

// A round rod bends alike about both section axes: its in-plane and out-of-plane
// families pair to round-off.
TEST(Spatial, RoundRodBendingFamiliesPair) {
  Section rod;
  rod.shape = SectionShape::RoundRod;
  rod.radius = 0.00127;
  const auto f = familyFrequencies(testing::spatialCantilever(rod, 2110, 61e9, 6e9, 0.762, 16, 0.01));
  const auto& in = f.at("in-plane");
  const auto& out = f.at("out-of-plane");
  ASSERT_EQ(in.size(), out.size());
  for (std::size_t k = 0; k < in.size(); ++k) EXPECT_NEAR(out[k], in[k], 1e-9 * in[k]) << k;
}

// The planarity report: the symmetric planar article responds in its plane only (every
// excitation decoupled); rolled by the gimbal, gravity bends it out of the plane, and a
// base x excitation then reaches its out-of-plane modes.
TEST(Spatial, PlanarityReportSeesCouplingOnlyWhenTheArticleLeavesItsPlane) {
  ModesOptions opt;
  opt.max_modes = 12;
  const ModesReport flat = runModes(testing::spatialDefault(), opt);
  ASSERT_TRUE(flat.planarity.has_value());
  EXPECT_TRUE(flat.planarity->covers_band);
  EXPECT_FALSE(flat.planarity->others.empty());
  for (const auto& r : flat.planarity->responses) EXPECT_TRUE(r.decoupled) << r.excitation << " at " << r.point;
  ArticleScene rolled = testing::spatialDefault();
  rolled.article.base.gimbal = GimbalSpec{};
  rolled.article.base.gimbal->roll.angle = 20 * M_PI / 180;
  const ModesReport tilted = runModes(rolled, opt);
  bool coupled = false;
  for (const auto& r : tilted.planarity->responses)
    if (r.excitation == "base x" && !r.decoupled && r.ratio > 1e-4) coupled = true;
  EXPECT_TRUE(coupled);
  EXPECT_GT(std::abs(tilted.points.back().dz), 1e-3);  // gravity's out-of-plane part bends the tips (m)
}

using testing::column;

// A free spatial run: the article rolled 20 deg by the gimbal, released from its
// unbent shape, swings in and out of its plane with no dissipation; the energy balance
// holds at every sample (1e-6 of the peak kinetic energy; 3e-7 measured) and the tips
// leave the plane.
TEST(Spatial, FreeRunKeepsItsEnergyBalance) {
  ArticleScene s = testing::spatialDefault();
  for (auto& l : s.article.links) l.segments = 4;
  s.article.base.gimbal = GimbalSpec{};
  s.article.base.gimbal->roll.angle = 20 * M_PI / 180;
  s.simulation.from_equilibrium = false;
  s.simulation.duration = 0.5;
  s.simulation.sample_rate_hz = 500;
  s.simulation.integrator = "cvode_bdf";
  s.simulation.accuracy = 1e-7;
  const SimulationResult r = simulate(s);
  EXPECT_GT(r.peak_kinetic_energy_j, 0.5);  // J: it does move
  EXPECT_LT(std::abs(r.max_energy_balance_error_j), 1e-6 * r.peak_kinetic_energy_j);
  const int z = column(r.record, "link3b.tip_z_m");
  double z_range = 0;
  for (const auto& row : r.record.rows) z_range = std::max(z_range, std::abs(row[z] - r.record.rows.front()[z]));
  EXPECT_GT(z_range, 1e-3);  // m
}

// A roll slew swings a hanging link out of its plane. Rigid, its motor needs
//   tau = (I_link + J_ring) theta'' + m g (L / 2) sin theta
// (the roll ring turns with it), I_link = m L^2 / 3 about the axis through its root
// (plus m I / A in the planar model, whose pieces carry the section's gyration about
// that axis). The spatial link bends out of the plane: the slew's initial jerk sets it
// ringing at its first out-of-plane mode (123 Hz), about f_slew / f_1 = 1 % of the peak
// torque for this 0.75 s cycloidal slew, undamped, so the torque follows the rigid
// estimate to 2 % at every sample and to 1e-3 of the peak on average (the ringing
// averages out); held rigid out of the plane (planar model) it follows it to 1e-6.
TEST(Spatial, RollSlewTorqueFollowsTheRigidBodyEstimate) {
  const double m = 3.0, L = 1.0, g = 9.81, ring = 0.7;
  const Section sec = testing::explicitSection(1e-4, 2e-8, 2e-8, 4e-8);
  ArticleScene s = testing::spatialCantilever(sec, m / (1e-4 * L), 7e12, 2.7e12, L, 4);
  s.gravity = {0, -g, 0};
  s.article.base.direction = -M_PI / 2;  // hanging
  s.article.base.gimbal = GimbalSpec{};
  s.article.base.gimbal->ring_inertia = ring;
  SlewSpec slew;
  slew.to = 20 * M_PI / 180;
  s.article.base.gimbal->roll.slew = slew;
  s.simulation.duration = 1.0;
  s.simulation.sample_rate_hz = 200;
  s.simulation.integrator = "cvode_bdf";
  s.simulation.accuracy = 1e-7;
  const facility::Slew model = facility::makeSlew(facility::SlewShape::Cycloidal, 0, slew.to, 0,
                                                  {90 * M_PI / 180, slew.max_rate, slew.max_acceleration});
  for (const bool spatial : {true, false}) {
    ArticleScene run = s;
    if (!spatial) run.article.model = ArticleModel::Planar;
    const SimulationResult r = simulate(run);
    const int t = column(r.record, "gimbal.roll_torque_n_m");
    double peak = 0, worst = 0, mean_error = 0;
    for (const auto& row : r.record.rows) {
      const facility::SlewState st = model.at(row[0]);
      const double inertia = m * L * L / 3 + (spatial ? 0.0 : m * 2e-8 / 1e-4) + ring;
      const double expected = inertia * st.acceleration + m * g * (L / 2) * std::sin(st.angle);
      peak = std::max(peak, std::abs(expected));
      worst = std::max(worst, std::abs(std::abs(row[t]) - std::abs(expected)));
      mean_error += std::abs(row[t]) - std::abs(expected);
    }
    EXPECT_LT(worst, (spatial ? 2e-2 : 1e-6) * peak) << (spatial ? "spatial" : "planar");
    EXPECT_LT(std::abs(mean_error) / static_cast<double>(r.record.rows.size()), 1e-3 * peak);
    if (spatial) {
      const int z = column(r.record, "link1.tip_z_m");
      EXPECT_NEAR(std::abs(r.record.rows.back()[z]), L * std::sin(slew.to), 1e-3);  // swung out of the plane
    }
  }
}

const PointMotion& shapeAt(const ModeInfo& m, const std::string& point) {
  for (const auto& p : m.shape)
    if (p.point == point) return p;
  throw std::runtime_error("no point " + point);
}

// Symmetry of the double branch spread out of the plane (mirror z -> -z): in every mode
// the two branch tips move alike or mirrored (equal amplitude). A small tip mass dm on
// one branch breaks it; perturbation theory predicts the shifts: within each cluster of
// modes closer than 3 % (the branches' near-degenerate pairs), the eigenvalues of
// Lambda q = omega^2 (I + D) q with D_ij = dm d_i . d_j (d: the mass-normalised shape's
// tip motion); alone, d(omega^2) = -omega^2 dm |d|^2 to first order. No gravity, so the
// mass changes no preload.
TEST(Spatial, BranchAsymmetrySplitsModesAsPerturbationPredicts) {
  ArticleScene sym = testing::spatialDefault();
  sym.gravity = {0, 0, 0};
  for (auto& l : sym.article.links)
    if (l.name == "link3a" || l.name == "link3b") std::swap(l.mount_angle, l.tilt);
  ModesOptions opt;
  opt.max_modes = 14;
  const ModesReport base = runModes(sym, opt);
  const double dm = 2e-6;  // kg, 0.025 % of a branch
  ArticleScene asym = sym;
  for (auto& l : asym.article.links)
    if (l.name == "link3b") l.tip_mass = LumpedMass{dm, 0.0};
  const ModesReport shifted = runModes(asym, opt);
  const int n = static_cast<int>(base.modes.size()) - 1;  // the last one's cluster may reach past the list
  std::vector<Eigen::Vector3d> d;
  for (int i = 0; i <= n; ++i) {
    const PointMotion &a = shapeAt(base.modes[i], "link3a.tip"), &b = shapeAt(base.modes[i], "link3b.tip");
    EXPECT_NEAR(std::hypot(a.ux, a.uy, a.uz), std::hypot(b.ux, b.uy, b.uz), 1e-6 * std::hypot(b.ux, b.uy, b.uz) + 1e-12)
        << "mode " << i + 1 << " is not symmetric";
    d.emplace_back(b.ux, b.uy, b.uz);
  }
  int checked = 0, split = 0;
  for (int first = 0; first < n;) {
    int last = first;
    while (last + 1 < n && base.modes[last + 1].frequency_hz < 1.03 * base.modes[last].frequency_hz) ++last;
    const int c = last - first + 1;
    Eigen::MatrixXd L = Eigen::MatrixXd::Zero(c, c), B = Eigen::MatrixXd::Identity(c, c);
    for (int i = 0; i < c; ++i) {
      L(i, i) = base.modes[first + i].omega2;
      for (int j = 0; j < c; ++j) B(i, j) += dm * d[first + i].dot(d[first + j]);
    }
    const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> es(L, B);
    for (int i = 0; i < c; ++i) {
      const double f = base.modes[first + i].frequency_hz, predicted = std::sqrt(es.eigenvalues()[i]) / (2 * M_PI) - f;
      const double actual = shifted.modes[first + i].frequency_hz - f;
      if (std::abs(predicted) < 1e-7 * f) continue;  // the branch tip hardly moves: nothing to compare
      EXPECT_NEAR(actual, predicted, 0.01 * std::abs(predicted)) << "mode " << first + i + 1;
      ++checked;
    }
    split += c > 1;
    first = last + 1;
  }
  EXPECT_GE(checked, 8);
  EXPECT_GE(split, 1);  // a near-degenerate pair was split
}

}  // namespace
}  // namespace mmv

namespace mmv {
namespace {

// A mass offset across the section (tip_mass.offset: [y, z]): hung at e out of the
// plane at a horizontal cantilever's tip, its weight twists the link by m g e L / (G J)
// (the hinges' torsion compliances add up to L / (G J)); on the axis it twists nothing.
TEST(Spatial, AnOffsetTipMassTwistsTheLinkByItsWeightsMoment) {
  const double L = 1.2, G = 2.6e10, J = 4e-9, m = 0.8, e = 0.03, g = 9.81;
  const Section sec = testing::explicitSection(1e-4, 1e-8, 1e-8, J);
  for (const double offset : {e, 0.0}) {
    ArticleScene s = testing::spatialCantilever(sec, 2700, 7e11, G, L, 8, m);
    s.gravity = {0, -g, 0};
    s.article.links[0].tip_mass->offset = {0, offset};
    const SolvedScene solved = solveScene(s);
    double twist = 0;
    for (std::size_t c = 0; c < solved.model->getCoordinates().size(); ++c)
      if (solved.model->getCoordinates()[c].axis == HingeAxis::Torsion) twist += solved.equilibrium.q[c];
    EXPECT_NEAR(std::abs(twist), m * g * offset * L / (G * J), 1e-3 * m * g * e * L / (G * J)) << "offset " << offset;
  }
}

}  // namespace
}  // namespace mmv
