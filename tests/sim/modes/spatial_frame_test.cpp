// Coupled bending and torsion (docs/spatial.md): an L-shaped frame in the plane, member
// A clamped at its root, member B rigidly joined to A's tip at 90 deg and free at its
// end. Out of the plane, B's bending twists A and A's bending twists B. The spatial
// article model against an independently computed exact solution: the continuous
// Euler-Bernoulli members and St Venant shafts joined at the corner, the frequency
// equation a 12 x 12 determinant.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include <Eigen/Dense>

#include "article/beam_theory.hpp"
#include "sim/modes/planarity.hpp"
#include "sim/modes/system_modes.hpp"
#include "support/scenes.hpp"

namespace mmv {
namespace {

struct Frame {
  double a = 1.0, b = 0.8;                   // m, the members' lengths
  double rho = 2700, E = 70e9, G = 26e9;     // kg/m^3, Pa
  double A = 4e-4, I_in = 4e-9, I_out = 1e-9, J = 1.5e-9;  // m^2, m^4 (both members)
  double polar() const { return I_in + I_out; }           // the pieces' polar inertia per rho
};

ArticleScene frameScene(const Frame& f, int segments) {
  testing::Beam beam;
  beam.density = f.rho;
  beam.youngs = f.E;
  beam.length = f.a;
  beam.area = f.A;
  beam.second_moment = f.I_in;
  ArticleScene s = testing::cantileverScene(beam, segments, 0.0);
  s.name = "L-frame";
  s.article.model = ArticleModel::Spatial;
  s.article.materials[0].shear_modulus = f.G;
  s.article.sections[0].explicit_second_moment_out = f.I_out;
  s.article.sections[0].explicit_torsion_constant = f.J;
  JointSpec corner;
  corner.name = "corner";
  corner.parent = "link1";
  corner.angle = M_PI / 2;
  corner.range = M_PI;
  corner.hold = JointHold::Locked;
  s.article.joints.push_back(corner);
  LinkSpec b = s.article.links[0];
  b.name = "link2";
  b.joint = "corner";
  b.length = f.b;
  s.article.links.push_back(b);
  return s;
}

/// The exact frequency determinant at omega. Member A along x (0..a), member B along y
/// (0..b) from A's tip, w the deflection along z, theta the twist about each member's
/// axis: w = c1 cos + c2 sin + c3 cosh + c4 sinh (beta s), theta = d1 cos + d2 sin (kappa s),
/// beta^4 = rho A omega^2 / (E I_out), kappa = omega sqrt(rho I_p / G J). Rotations at the
/// corner: about x, theta_A = w_B'; about y, -w_A' = theta_B. Root of A clamped; B's
/// end free; at the corner the boundary terms of the energy's variation cancel:
///   -EI w_A''' + EI w_B''' = 0,  GJ theta_A' - EI w_B'' = 0,  -EI w_A'' - GJ theta_B' = 0.
double frameDeterminant(const Frame& f, double omega) {
  const double EI = f.E * f.I_out, GJ = f.G * f.J;
  const double beta = std::pow(f.rho * f.A * omega * omega / EI, 0.25);
  const double kappa = omega * std::sqrt(f.rho * f.polar() / GJ);
  // Derivative k of the bending basis at s: rows of [cos sin cosh sinh].
  auto w = [&](double s, int k) {
    Eigen::RowVector4d r;
    const double c = std::cos(beta * s), sn = std::sin(beta * s), ch = std::cosh(beta * s), sh = std::sinh(beta * s);
    const double p = std::pow(beta, k);
    switch (k % 4) {
      case 0: r << c, sn, ch, sh; break;
      case 1: r << -sn, c, sh, ch; break;
      case 2: r << -c, -sn, ch, sh; break;
      default: r << sn, -c, sh, ch; break;
    }
    return Eigen::RowVector4d(p * r);
  };
  auto t = [&](double s, int k) {
    Eigen::RowVector2d r;
    if (k == 0) r << std::cos(kappa * s), std::sin(kappa * s);
    else r << -kappa * std::sin(kappa * s), kappa * std::cos(kappa * s);
    return r;
  };
  // Unknowns: w_A (0-3), theta_A (4-5), w_B (6-9), theta_B (10-11).
  Eigen::MatrixXd D = Eigen::MatrixXd::Zero(12, 12);
  int row = 0;
  D.block<1, 4>(row++, 0) = w(0, 0);  // clamped root
  D.block<1, 4>(row++, 0) = w(0, 1);
  D.block<1, 2>(row++, 4) = t(0, 0);
  D.block<1, 4>(row, 0) = w(f.a, 0), D.block<1, 4>(row++, 6) = -w(0, 0);  // the corner moves as one
  D.block<1, 2>(row, 4) = t(f.a, 0), D.block<1, 4>(row++, 6) = -w(0, 1);
  D.block<1, 4>(row, 0) = -w(f.a, 1), D.block<1, 2>(row++, 10) = -t(0, 0);
  D.block<1, 4>(row, 0) = -EI * w(f.a, 3), D.block<1, 4>(row++, 6) = EI * w(0, 3);  // and is in equilibrium
  D.block<1, 2>(row, 4) = GJ * t(f.a, 1), D.block<1, 4>(row++, 6) = -EI * w(0, 2);
  D.block<1, 4>(row, 0) = -EI * w(f.a, 2), D.block<1, 2>(row++, 10) = -GJ * t(0, 1);
  D.block<1, 4>(row++, 6) = w(f.b, 2);  // free end of B
  D.block<1, 4>(row++, 6) = w(f.b, 3);
  D.block<1, 2>(row++, 10) = t(f.b, 1);
  // Scale each row to unit size so the determinant's sign changes are its roots.
  for (int r = 0; r < 12; ++r) D.row(r) /= D.row(r).norm();
  return D.determinant();
}

/// The frame's out-of-plane modes (no in-plane strain), Hz, from the spatial model.
std::vector<double> modelOutOfPlaneHz(const Frame& f, int segments, int count) {
  const SolvedScene s = solveScene(frameScene(f, segments));
  std::vector<double> out;
  for (int i = 0; i < s.modes.omega2.size() && static_cast<int>(out.size()) < count; ++i)
    if (classifyMode(*s.model, s.linearized.dofs, s.modes.shapes.col(i)).in_plane < 1e-9) out.push_back(s.modes.frequencyHz(i));
  return out;
}

// The first four coupled modes, extrapolated from 16 and 32 segments per member (finer, the pieces would need docs/spatial.md's inertia correction)
// (O(1/N^2)), against the exact ones to 1e-5 (they agree to 2e-6; 5 % more G J in the exact solution fails it).
TEST(SpatialFrame, LFrameCoupledBendingTorsionMatchesTheExactSolution) {
  const Frame f;
  const std::vector<double> w_exact =
      findRoots([&](double w) { return frameDeterminant(f, w); }, 1.0, 2 * M_PI * 400, 0.05, 4);
  ASSERT_EQ(w_exact.size(), 4u);
  const auto coarse = modelOutOfPlaneHz(f, 16, 4), fine = modelOutOfPlaneHz(f, 32, 4);
  ASSERT_EQ(fine.size(), 4u);
  for (int k = 0; k < 4; ++k) {
    const double exact = w_exact[k] / (2 * M_PI), richardson = (4 * fine[k] - coarse[k]) / 3;
    EXPECT_NEAR(richardson, exact, 1e-5 * exact) << "coupled mode " << k + 1 << " (model at 32: " << fine[k] << " Hz)";
  }
  // The coupling is real: with a torsion-free corner (B alone as a clamped cantilever
  // would give its own frequency) the first mode is not B's cantilever mode.
  const double b_alone = beamFrequencyHz(1.8751040687, f.b, f.E * f.I_out, f.rho * f.A);
  EXPECT_LT(w_exact[0] / (2 * M_PI), 0.9 * b_alone);
}

}  // namespace
}  // namespace mmv
