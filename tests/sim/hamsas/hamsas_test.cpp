// HAM-SAS (article/hamsas.hpp, sim/hamsas/spatial_linear.hpp, sim/hamsas/hamsas_modes.hpp): the
// spatial linearization against an independent nonlinear potential, the shipped scene
// against the measured frequencies, symmetry, transmissibility physics, stiff springs
// against ideal joints, and the control model.

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include "sim/hamsas/hamsas_modes.hpp"
#include "sim/scene/scene.hpp"
#include "sim/statics/statics.hpp"

namespace mmv {
namespace {

HamsasSpec shippedScene() {
  return loadHamsasSceneFile(std::string(MMVLAB_SOURCE_DIR) + "/scenes/hamsas.yaml").isolator;
}

const FeatureMatch& feature(const HamsasModes& h, const std::string& name) {
  for (const auto& f : h.features)
    if (f.feature == name) return f;
  throw std::runtime_error("no feature " + name);
}

Eigen::Matrix3d expm(const Eigen::Vector3d& th) {
  const double a = th.norm();
  return a > 0 ? Eigen::AngleAxisd(a, th / a).toRotationMatrix() : Eigen::Matrix3d::Identity();
}

Eigen::Vector3d logm(const Eigen::Matrix3d& R) {
  const Eigen::AngleAxisd aa(R);
  return aa.angle() * aa.axis();
}

/// The potential energy written independently of the linearization: exact rotations,
/// springs with the rest offsets that make their design forces the computed preloads.
double potential(const SpatialSpec& s, const SpatialLinearization& lin, const Eigen::VectorXd& q) {
  const int nb = static_cast<int>(s.bodies.size());
  std::vector<Eigen::Vector3d> x(nb);
  std::vector<Eigen::Matrix3d> R(nb);
  x[0] = s.reference;
  R[0].setIdentity();
  double V = 0;
  for (int b = 1; b < nb; ++b) {
    x[b] = s.bodies[b].com + q.segment<3>(6 * (b - 1));
    R[b] = expm(q.segment<3>(6 * (b - 1) + 3));
    V -= s.bodies[b].mass * s.gravity.dot(x[b]);
  }
  auto point = [&](int b, const Eigen::Vector3d& p0) {
    const Eigen::Vector3d o = b == 0 ? s.reference : s.bodies[b].com;
    return Eigen::Vector3d(x[b] + R[b] * (p0 - o));
  };
  for (std::size_t e = 0; e < s.springs.size(); ++e) {
    const PointSpring& sp = s.springs[e];
    // Energy 1/2 (d - d0)^T K (d - d0) with K (0 - d0) = g: its gradient at the design is g.
    const Eigen::Vector3d d0 = -lin.spring_force[e].cwiseQuotient(sp.stiffness);
    const Eigen::Vector3d dd = point(sp.b, sp.point) - point(sp.a, sp.point) - d0;
    V += 0.5 * dd.dot(sp.stiffness.cwiseProduct(dd));
  }
  for (std::size_t e = 0; e < s.angular.size(); ++e) {
    const AngularSpring& as = s.angular[e];
    const Eigen::Vector3d phi = logm(R[as.b] * R[as.a].transpose());
    for (int k = 0; k < 3; ++k) {
      if (as.stiffness[k] == 0) {
        EXPECT_NEAR(lin.angular_moment[e][k], 0.0, 1e-12);
        continue;
      }
      const double phi0 = -lin.angular_moment[e][k] / as.stiffness[k];
      V += 0.5 * as.stiffness[k] * (phi[k] - phi0) * (phi[k] - phi0);
    }
  }
  return V;
}

TEST(Hamsas, StiffnessIsTheHessianOfAnIndependentNonlinearPotential) {
  // Softer joints (1e5 N/m) and a counterweight off the tuning so every geometric term
  // is a visible part of its entry; the formula is the same at 1e8.
  HamsasSpec spec = shippedScene();
  spec.joint_stiffness = 1e5;
  spec.counterweight_mass = 1.0;
  spec.ot_com_above_mgas = 0.05;
  const SpatialSpec model = buildHamsas(spec);
  const SpatialLinearization lin = linearizeSpatial(model, false);
  const int n = lin.num_free;
  const double h = 1e-4;
  Eigen::MatrixXd K_fd(n, n);
  Eigen::VectorXd grad(n);
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(n);
  for (int i = 0; i < n; ++i) {
    Eigen::VectorXd ei = zero;
    ei[i] = h;
    grad[i] = (potential(model, lin, ei) - potential(model, lin, -ei)) / (2 * h);
    for (int j = 0; j <= i; ++j) {
      Eigen::VectorXd ej = zero;
      ej[j] = h;
      K_fd(i, j) = K_fd(j, i) = (potential(model, lin, ei + ej) - potential(model, lin, ei - ej) -
                                 potential(model, lin, ej - ei) + potential(model, lin, -ei - ej)) /
                                (4 * h * h);
    }
  }
  double weight = 0;
  for (std::size_t b = 1; b < model.bodies.size(); ++b) weight += model.bodies[b].mass * 9.80665;
  EXPECT_LT(grad.cwiseAbs().maxCoeff(), 1e-6 * weight) << "the design must be the equilibrium";
  // Entries by entry, against the entry's own size (geometric terms are 1e-2..1 of it).
  const double scale = lin.K.cwiseAbs().maxCoeff();
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      EXPECT_NEAR(lin.K(i, j), K_fd(i, j), 1e-6 * scale + 1e-4 * std::abs(K_fd(i, j))) << "entry " << i << "," << j;
  // The geometric part is really there: dropping it changes the entries above the tolerance.
  Eigen::MatrixXd K_el = Eigen::MatrixXd::Zero(n, n);
  for (const auto& e : lin.elements) K_el += e.K;
  EXPECT_GT((K_el - K_fd).cwiseAbs().maxCoeff(), 100 * (lin.K - K_fd).cwiseAbs().maxCoeff());
}

TEST(Hamsas, ShippedSceneReproducesTheMeasuredFrequencies) {
  // 5 %: the slides give the frequencies to 2-3 digits, read from measured spectra.
  const HamsasModes h = analyseHamsas(shippedScene());
  ASSERT_EQ(h.model.bodies.size(), 11u);
  int springs = 0;
  for (const auto& s : h.model.springs) springs += s.joint;
  EXPECT_EQ(springs, 12);
  EXPECT_EQ(h.model.angular.size() - 4, 4u);  // 4 flex joints (+ 4 wire torsions)
  EXPECT_EQ(h.model.sensors.size(), 8u);
  ASSERT_EQ(h.features.size(), 9u);
  for (const auto& f : h.features) {
    ASSERT_TRUE(f.mode) << f.feature;
    EXPECT_NEAR(f.model_hz / f.measured_hz, 1.0, 0.05) << f.feature;
    EXPECT_GT(f.shape_match, 0.8) << f.feature;
  }
  for (int i = 0; i < h.solution.omega2.size(); ++i) EXPECT_TRUE(h.solution.isStable(i)) << "mode " << i;
}

TEST(Hamsas, HorizontalModesPairAndVerticalDecouples) {
  const HamsasModes h = analyseHamsas(shippedScene());
  EXPECT_NEAR(feature(h, "IP (horizontal) x").model_hz, feature(h, "IP (horizontal) y").model_hz, 1e-6);
  // (to the eigen solution's accuracy at a 1e10 eigenvalue span: relative 1e-4)
  EXPECT_NEAR(feature(h, "horizontal GAS x").model_hz / feature(h, "horizontal GAS y").model_hz, 1.0, 1e-4);
  // The MGAS vertical mode carries no horizontal or tilting motion (the slides: vertical
  // decouples from horizontal), and no horizontal mode carries vertical motion.
  const SpatialMode& v = h.modes[feature(h, "MGAS vertical").mode->index()];
  double lateral = 0;
  for (const char* k : {"ot.x", "ot.y", "ot.rx", "ot.ry", "sb.x", "sb.y"}) lateral += v.kinetic_share.at(k);
  EXPECT_LT(lateral, 1e-12);
  const SpatialMode& ip = h.modes[feature(h, "IP (horizontal) x").mode->index()];
  EXPECT_LT(ip.kinetic_share.at("ot.z") + ip.kinetic_share.at("sb.z"), 1e-12);
  // The tilt pair splits only because the layout is rectangular: made square, it pairs.
  HamsasSpec sq = shippedScene();
  sq.ip_diamond_y = sq.ip_diamond_x;
  sq.mgas_rect_y = sq.mgas_rect_x;
  sq.ot_size_y = sq.ot_size_x;
  sq.sb_size_y = sq.sb_size_x;
  const HamsasModes hs = analyseHamsas(sq);
  EXPECT_GT(std::abs(feature(h, "DOF cross-coupling rx").model_hz - feature(h, "DOF cross-coupling ry").model_hz), 1e-3);
  EXPECT_NEAR(feature(hs, "DOF cross-coupling rx").model_hz, feature(hs, "DOF cross-coupling ry").model_hz, 1e-7);
}

TEST(Hamsas, TransmissibilityUnityResonancesAndSlope) {
  const HamsasModes h = analyseHamsas(shippedScene());
  auto T = [&](double hz) { return spatialTransmissibility(h.model, h.lin, 2 * M_PI * hz); };
  const Eigen::MatrixXcd dc = T(1e-5);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(std::abs(dc(k, k)), 1.0, 1e-6) << "translation " << k;
  EXPECT_NEAR(std::abs(dc(5, 5)), 1.0, 1e-6);  // yaw: gravity does not act on it
  // Resonances: the magnitude peaks at the IP and MGAS modes.
  auto peak = [&](int k, double f0, double f1) {
    double best = f0, mag = 0;
    for (double f = f0; f <= f1; f *= 1.0005)
      if (std::abs(T(f)(k, k)) > mag) mag = std::abs(T(f)(k, k)), best = f;
    return best;
  };
  EXPECT_NEAR(peak(0, 0.03, 0.1) / feature(h, "IP (horizontal) x").model_hz, 1.0, 0.005);
  EXPECT_NEAR(peak(2, 0.05, 0.2) / feature(h, "MGAS vertical").model_hz, 1.0, 0.005);
  // Above the MGAS resonance the vertical path falls as f^-2: -40 dB per decade.
  const double slope_z = 20 * std::log10(std::abs(T(10)(2, 2)) / std::abs(T(1)(2, 2)));
  EXPECT_NEAR(slope_z, -40.0, 0.5);
  // Horizontally two stages in series (IP, then the MGAS springs' horizontal stiffness):
  // with the counterweight near its tuning the slope between 3 and 10 Hz is steeper than
  // one stage's -40 dB/decade; without it the IP's plateau leaves one stage: -40.
  const double decade = std::log10(10.0 / 3.0);
  const double slope_x = 20 * std::log10(std::abs(T(10)(0, 0)) / std::abs(T(3)(0, 0))) / decade;
  EXPECT_LT(slope_x, -55.0);
  HamsasSpec untuned = shippedScene();
  untuned.counterweight_mass = 0;
  const HamsasModes hu = analyseHamsas(untuned);
  auto Tu = [&](double hz) { return std::abs(spatialTransmissibility(hu.model, hu.lin, 2 * M_PI * hz)(0, 0)); };
  EXPECT_NEAR(20 * std::log10(Tu(10) / Tu(3)) / decade, -40.0, 2.0);
  // 70-80 dB of attenuation at 10 Hz, horizontal and vertical (the design goal).
  EXPECT_LT(20 * std::log10(std::abs(T(10)(0, 0))), -70.0);
  EXPECT_LT(20 * std::log10(std::abs(T(10)(2, 2))), -70.0);
}

TEST(Hamsas, CounterweightTunesTheInvertedPendulumPlateau) {
  // A rigid IP leg (pivot inertia I_p, mass m, mass centre s above the pivot, length L)
  // under a payload M transmits x/x0 -> (I_p - m s L) / (M L^2 + I_p) = beta/M_eff far
  // above its resonance, plus -(f_IP/f)^2: the plateau that a counterweight below the
  // pivot cancels. Checked on the spring box (the IP stage's payload), with short little
  // pendulums so their own compliance (the scene's are 22 Hz) stays out of the formula.
  for (double cw : {0.0, 7.0}) {
    HamsasSpec spec = shippedScene();
    spec.counterweight_mass = cw;
    spec.lp_length = 0.01;
    const HamsasModes h = analyseHamsas(spec);
    SpatialSpec sb_out = h.model;
    sb_out.output_body = 2;  // the spring box
    ASSERT_EQ(sb_out.bodies[2].group, "sb");
    const double L = spec.ip_length, d = spec.counterweight_depth;
    const double mt = spec.ip_leg_mass, r = spec.ip_leg_radius, rc = spec.counterweight_radius;
    const double Ip = mt * (L * L / 3 + r * r / 2) + cw * (d * d + rc * rc / 4);
    const double msL = (mt * L / 2 - cw * d) * L;
    const double M = (spec.sb_mass + 4 * spec.lp_mass) / 4;
    const double plateau = (Ip - msL) / (M * L * L + Ip);
    // Far above the horizontal GAS resonance the table no longer moves with the spring
    // box, but its weight still loads the legs: the IP stage's own frequency is the IP
    // mode's scaled by the inertia it lost.
    const double f = 5.0, f_ip = feature(h, "IP (horizontal) x").model_hz;
    const double f_stage2 = f_ip * f_ip * (spec.sb_mass + spec.ot_mass + 4 * spec.lp_mass) / (spec.sb_mass + 4 * spec.lp_mass);
    const double expected = plateau - f_stage2 / (f * f);
    const Eigen::MatrixXcd T = spatialTransmissibility(sb_out, h.lin, 2 * M_PI * f);
    // 5 %: the table's pull through the MGAS springs, the little pendulums' compliance
    // and the flex damping are outside the rigid-IP formula (measured 2.2 % and 0.7 %).
    EXPECT_NEAR(std::abs(T(0, 0)) / std::abs(expected), 1.0, 0.05) << "counterweight " << cw;
  }
  // The optical table's attenuation at 10 Hz is best at the centre-of-percussion mass.
  HamsasSpec spec = shippedScene();
  const double L = spec.ip_length, d = spec.counterweight_depth, mt = spec.ip_leg_mass;
  const double tuned = (mt * L * L / 6 - mt * spec.ip_leg_radius * spec.ip_leg_radius / 2) /
                       (d * (d + L) + spec.counterweight_radius * spec.counterweight_radius / 4);
  auto at10 = [&](double cw) {
    spec.counterweight_mass = cw;
    const HamsasModes h = analyseHamsas(spec);
    return std::abs(spatialTransmissibility(h.model, h.lin, 2 * M_PI * 10)(0, 0));
  };
  double lo = 0, hi = 7;
  for (int it = 0; it < 40; ++it) {
    const double a = lo + 0.382 * (hi - lo), b = lo + 0.618 * (hi - lo);
    (at10(a) < at10(b) ? hi : lo) = at10(a) < at10(b) ? b : a;
  }
  EXPECT_NEAR(0.5 * (lo + hi) / tuned, 1.0, 0.05);
  EXPECT_LT(at10(tuned), 0.1 * at10(0.0));  // at least 20 dB from the counterweight
}

TEST(Hamsas, StiffSpringsAgainstIdealJoints) {
  HamsasSpec spec = shippedScene();
  const HamsasModes stiff = analyseHamsas(spec);
  spec.ideal_joints = true;
  const HamsasModes ideal = analyseHamsas(spec);
  EXPECT_EQ(ideal.lin.redundant_constraints, 1);  // the spring box on four rigid supports
  EXPECT_FALSE(feature(ideal, "effective spherical joints").mode);
  EXPECT_NEAR(feature(stiff, "effective spherical joints").model_hz, 60.0, 3.0);
  // Every ideal-joint mode has its stiff-spring twin: below 1 Hz within 1e-5 (the joint
  // compliance is (f/60 Hz)^2 of the joints' share), the 22 Hz family within 0.1 %.
  for (int i = 0; i < ideal.solution.omega2.size() && ideal.modes[i].frequency_hz < 30; ++i) {
    const double fi = ideal.modes[i].frequency_hz, fs = stiff.modes[i].frequency_hz;
    EXPECT_NEAR(fs / fi, 1.0, fi < 1 ? 1e-5 : 1e-3) << "mode " << i + 1 << " at " << fi << " Hz";
  }
  EXPECT_LT(stiff.max_relative_residual, 1e-5);  // despite a 1e10 eigenvalue span
  EXPECT_LT(ideal.max_relative_residual, 1e-7);
  EXPECT_LT(stiff.solution.orthogonality_error, 1e-10);
}

TEST(Hamsas, ControlModelIsCollocatedAndItsReductionKeepsDcGains) {
  const HamsasModes h = analyseHamsas(shippedScene());
  const StateSpace full = hamsasControlModel(h);
  ASSERT_EQ(full.B.cols(), 8);
  ASSERT_EQ(full.C.rows(), 8);
  const Eigen::MatrixXd g0 = full.response(0.0).real();
  EXPECT_LT((g0 - g0.transpose()).cwiseAbs().maxCoeff(), 1e-9 * g0.cwiseAbs().maxCoeff());  // co-located
  // Eight sensors on one rigid body see its six motions: the compliance is semi-definite
  // of rank 6.
  const Eigen::VectorXd ev = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(g0).eigenvalues();
  EXPECT_GT(ev.minCoeff(), -1e-12 * ev.maxCoeff());
  EXPECT_EQ((ev.array() > 1e-9 * ev.maxCoeff()).count(), 6);
  ReductionOptions o;
  o.band_min_hz = 0;
  o.band_max_hz = 80;
  const ReducedModel all = reduceModal(full, o);
  o.drop_unseen = true;
  const ReducedModel seen = reduceModal(full, o);
  EXPECT_GT(seen.unseen_modes, 0);
  EXPECT_LT(seen.model.numStates(), all.model.numStates());
  const std::vector<double> w = [] {
    std::vector<double> v;
    for (double f : logFrequencies(0.01, 100, 300)) v.push_back(2 * M_PI * f);
    return v;
  }();
  const double e_all = compareResponses(full, all.model, w).max_relative;
  const double e_seen = compareResponses(full, seen.model, w).max_relative;
  EXPECT_LT(e_seen, 5e-3);
  EXPECT_NEAR(e_seen, e_all, 1e-6);  // the dropped modes contributed nothing
  const Eigen::MatrixXd r0 = seen.model.response(0.0).real();
  EXPECT_LT((r0 - g0).cwiseAbs().maxCoeff(), 1e-9 * g0.cwiseAbs().maxCoeff());
}

TEST(Hamsas, LoadedMechanismIsNamed) {
  // Without the flex joints' bending stiffness the IP stage has none: with gravity on
  // its inverted legs the equilibrium is unstable and modes say so.
  HamsasSpec spec = shippedScene();
  spec.flex_stiffness = 1.0;
  const HamsasModes h = analyseHamsas(spec);
  int unstable = 0;
  for (int i = 0; i < h.solution.omega2.size(); ++i) unstable += !h.solution.isStable(i);
  EXPECT_GE(unstable, 2);
}

}  // namespace
}  // namespace mmv

// Time runs through the nonlinear Simbody model (sim/hamsas/hamsas_simulation.hpp).
#include <unsupported/Eigen/MatrixFunctions>

#include "facility/table_programs.hpp"
#include "sim/hamsas/hamsas_simulation.hpp"
#include "support/record_column.hpp"

namespace mmv {
namespace {

HamsasScene timeRunScene(double amplitude, double duration, double rate_hz) {
  HamsasScene s = loadHamsasSceneFile(std::string(MMVLAB_SOURCE_DIR) + "/scenes/hamsas.yaml");
  s.ground_motion = TableMotion::sine(amplitude, 1.0);
  s.ground_motion->ramp = 0.5;
  s.ground_axis = 0;
  s.simulation.duration = duration;
  s.simulation.sample_rate_hz = rate_hz;
  s.simulation.integrator = "rk_merson";
  s.simulation.accuracy = 1e-10;
  return s;
}

using testing::column;

TEST(HamsasTimeRun, DesignIsTheEquilibriumOfTheNonlinearModel) {
  // The Simbody model's spring rest offsets come from the linearization's preloads: at
  // rest on still ground nothing may move.
  const SimulationResult r = simulate(timeRunScene(0.0, 0.2, 50));
  double worst = 0;
  for (const auto& row : r.record.rows)
    for (int c : {column(r.record, "optical_table_x_m"), column(r.record, "optical_table_z_m"),
                  column(r.record, "spring_box_x_m"), column(r.record, "spring_box_z_m"), column(r.record, "sensor_v1_m")})
      worst = std::max(worst, std::abs(row[c]));
  EXPECT_LT(worst, 1e-10);
}

TEST(HamsasTimeRun, NonlinearRunFollowsTheLinearModel) {
  // 1 mm of ground motion at 1 Hz with a 0.5 s ramp-in, 0.5 s: the nonlinear Simbody
  // run against the linear model integrated exactly for a piecewise-linear input
  // (matrix exponentials at the 1 ms sample interval: hold error ~ (2 pi f dt)^2 / 8).
  const double dt = 1e-3, T = 0.5;
  const HamsasScene scene = timeRunScene(1e-3, T, 1.0 / dt);
  const SimulationResult nl = simulate(scene);
  const HamsasModes h = analyseHamsas(scene.isolator);
  const SpatialLinearization& lin = h.lin;
  const int n = lin.num_free;
  const Eigen::MatrixXd Mi = lin.M.inverse();
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(2 * n, 2 * n);
  A.topRightCorner(n, n).setIdentity();
  A.bottomLeftCorner(n, n) = -Mi * lin.K;
  A.bottomRightCorner(n, n) = -Mi * lin.C;
  Eigen::VectorXd bd = Eigen::VectorXd::Zero(2 * n), bv = Eigen::VectorXd::Zero(2 * n);
  bd.tail(n) = -Mi * lin.Kb.col(0);
  bv.tail(n) = -Mi * lin.Cb.col(0);
  // exp of [[A, I, 0], [0, 0, I], [0, 0, 0]] dt gives Phi, Gamma0, Gamma1.
  Eigen::MatrixXd aug = Eigen::MatrixXd::Zero(6 * n, 6 * n);
  aug.block(0, 0, 2 * n, 2 * n) = A * dt;
  aug.block(0, 2 * n, 2 * n, 2 * n) = Eigen::MatrixXd::Identity(2 * n, 2 * n) * dt;
  aug.block(2 * n, 4 * n, 2 * n, 2 * n) = Eigen::MatrixXd::Identity(2 * n, 2 * n) * dt;
  const Eigen::MatrixXd E = aug.exp();
  // Phi = e^{A dt}, G1 = int_0^dt e^{As} ds, G2 = int_0^dt e^{As} (dt - s) ds.
  const Eigen::MatrixXd Phi = E.block(0, 0, 2 * n, 2 * n), G1 = E.block(0, 2 * n, 2 * n, 2 * n),
                        G2 = E.block(0, 4 * n, 2 * n, 2 * n);
  const auto program = facility::sineDwell(1e-3, 1.0, 1e9, 0.5);
  auto forcing = [&](double t) { Eigen::VectorXd f = bd * program->position(t) + bv * program->velocity(t); return f; };
  Eigen::VectorXd x = Eigen::VectorXd::Zero(2 * n);
  const int ot = SpatialLinearization::row(1), sb = SpatialLinearization::row(2);
  const int c_ot = column(nl.record, "optical_table_x_m"), c_sb = column(nl.record, "spring_box_x_m");
  double err_ot = 0, err_sb = 0, peak_ot = 0, peak_sb = 0;
  for (std::size_t k = 0; k < nl.record.rows.size(); ++k) {
    const double t = k * dt;
    if (k > 0) {
      const Eigen::VectorXd f0 = forcing(t - dt), f1 = forcing(t);
      // x(t + dt) = Phi x + int_0^dt e^{A(dt - s)} (f0 + (f1 - f0) s / dt) ds
      x = Phi * x + G1 * f0 + G2 * (f1 - f0) / dt;
    }
    err_ot = std::max(err_ot, std::abs(nl.record.rows[k][c_ot] - x[ot]));
    err_sb = std::max(err_sb, std::abs(nl.record.rows[k][c_sb] - x[sb]));
    peak_ot = std::max(peak_ot, std::abs(x[ot]));
    peak_sb = std::max(peak_sb, std::abs(x[sb]));
  }
  EXPECT_GT(peak_sb, 1e-5);
  // Measured 4e-5 and 5e-6 of the peaks (geometric nonlinearity of a 1 mm motion).
  EXPECT_LT(err_sb, 2e-4 * peak_sb) << "peak " << peak_sb;
  EXPECT_LT(err_ot, 1e-4 * peak_ot) << "peak " << peak_ot;
}

TEST(HamsasTimeRun, EnergyBalanceClosesWhenThePowerIsSampledFinely) {
  // The custom force element is conservative apart from its dampers: with the power
  // sampled at 5 kHz (the joints ring at 60 Hz-5 kHz) the balance
  // E(end) - E(0) = W_ground - D closes to round-off of a 1.3e5 J stored energy.
  const SimulationResult r = simulate(timeRunScene(1e-3, 0.3, 5000));
  ASSERT_GT(r.motion_work_j, 0.0);
  EXPECT_GT(r.dissipated_j, 0.0);
  EXPECT_LT(std::abs(r.energy_balance_error_j), 1e-5 * r.motion_work_j) << r.energy_balance_error_j;
  EXPECT_EQ(energyBalanceWarning(r), "");
}

TEST(HamsasTimeRun, NeedsGroundMotionAndStiffJoints) {
  HamsasScene s = timeRunScene(1e-3, 0.1, 50);
  s.ground_motion.reset();
  EXPECT_THROW(simulate(s), SceneError);
  s = timeRunScene(1e-3, 0.1, 50);
  s.isolator.ideal_joints = true;
  EXPECT_THROW(simulate(s), SceneError);
}

}  // namespace
}  // namespace mmv
