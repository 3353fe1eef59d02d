// The gimbal (AGS) between the base and the article: held angles re-orient the article
// exactly, driven axes need the torques rigid-body dynamics says, and commands beyond
// an axis's range are refused.
#include <gtest/gtest.h>

#include <cmath>

#include "facility/slews.hpp"
#include "sim/modes/system_modes.hpp"
#include "sim/time/simulation.hpp"
#include "support/record_column.hpp"
#include "support/scenes.hpp"

namespace mmv {
namespace {

constexpr double kDeg = M_PI / 180;

using testing::column;

// A rigid uniform link (1 m, 3 kg) held horizontal along the plate's x on a gimbal.
ArticleScene rigidLinkOnGimbal(double yaw, double pitch, double roll) {
  testing::Beam b;
  b.density = 3.0 / b.area;  // 3 kg/m
  ArticleScene s = testing::cantileverScene(b, 1, 9.81, 0.0, 0.0, /*rigid=*/true);
  GimbalSpec g;
  g.yaw.angle = yaw;
  g.pitch.angle = pitch;
  g.roll.angle = roll;
  s.article.base.gimbal = g;
  s.simulation.from_equilibrium = false;
  s.simulation.duration = 0.01;
  s.simulation.sample_rate_hz = 1000;
  return s;
}

// Held at rest, the motors carry gravity's moments about their axes. Link along the
// plate's x, centre of mass a = L/2 from the axes' common point:
//   roll r: joint 1 carries m g a cos r (gravity's in-plane part), pitch m g a (world z
//   is still the pitch axis), roll and yaw nothing (the link lies on the roll axis;
//   gravity is parallel to yaw's).
//   pitch p: joint 1 and pitch both m g a cos p.
//   yaw y: turning the plane about the vertical changes nothing in it.
TEST(Gimbal, HeldTorquesAreGravityMoments) {
  const double mga = 3.0 * 9.81 * 0.5;
  struct Case {
    double yaw, pitch, roll, j1, tp, tr;
  } cases[] = {{0, 0, 60 * kDeg, mga * 0.5, mga, 0},
               {0, 30 * kDeg, 0, mga * std::cos(30 * kDeg), mga * std::cos(30 * kDeg), 0},
               {40 * kDeg, 0, 0, mga, mga, 0},
               {0, 0, 90 * kDeg, 0, mga, 0}};
  for (const auto& c : cases) {
    const SimulationResult r = simulate(rigidLinkOnGimbal(c.yaw, c.pitch, c.roll));
    const auto& row = r.record.rows.front();
    EXPECT_NEAR(std::abs(row[column(r.record, "joint1_torque_n_m")]), c.j1, 1e-9 * mga);
    EXPECT_NEAR(std::abs(row[column(r.record, "gimbal.pitch_torque_n_m")]), c.tp, 1e-9 * mga);
    EXPECT_NEAR(std::abs(row[column(r.record, "gimbal.roll_torque_n_m")]), c.tr, 1e-9 * mga);
    EXPECT_NEAR(row[column(r.record, "gimbal.yaw_torque_n_m")], 0.0, 1e-9 * mga);
  }
}

// The pitch axis following `pitch` on the rigid link (ring inertia 0.7 kg*m^2) for
// 1.5 s: its angle is `model`'s at every sample and its motor needs
//   tau = (m L^2 / 3 + 2 J_ring) theta'' + m g a cos theta
// (the pitch ring and the roll ring inside it turn with it), to 1e-9 of the peak:
// nothing is integrated, every DOF is prescribed. Returns the run.
SimulationResult expectPitchInverseDynamics(const SlewSpec& pitch, const facility::Slew& model) {
  ArticleScene s = rigidLinkOnGimbal(0, 0, 0);
  s.article.base.gimbal->pitch.slew = pitch;
  s.article.base.gimbal->ring_inertia = 0.7;
  s.simulation.duration = 1.5;
  s.simulation.sample_rate_hz = 200;
  const SimulationResult r = simulate(s);
  const int a = column(r.record, "gimbal.pitch_angle_deg"), t = column(r.record, "gimbal.pitch_torque_n_m");
  const double m = 3.0, L = 1.0, g = 9.81, I = m * L * L / 3 + 2 * 0.7;
  double peak = 0;
  for (const auto& row : r.record.rows) peak = std::max(peak, std::abs(row[t]));
  for (const auto& row : r.record.rows) {
    const facility::SlewState st = model.at(row[0]);
    EXPECT_NEAR(row[a], st.angle / kDeg, 1e-9) << "t = " << row[0];
    const double expected = I * st.acceleration + m * g * (L / 2) * std::cos(st.angle);
    EXPECT_NEAR(std::abs(row[t]), std::abs(expected), 1e-9 * peak) << "t = " << row[0];
  }
  return r;
}

// A cycloidal slew of the pitch axis, 0 -> 40 deg, as above.
TEST(Gimbal, PitchSlewTorqueIsTheInverseDynamics) {
  SlewSpec slew;
  slew.to = 40 * kDeg;
  const SimulationResult r = expectPitchInverseDynamics(
      slew, facility::makeSlew(facility::SlewShape::Cycloidal, 0, 40 * kDeg, 0, {45 * kDeg, slew.max_rate, slew.max_acceleration}));
  EXPECT_NEAR(r.record.rows.back()[column(r.record, "gimbal.pitch_angle_deg")], 40.0, 1e-9);
  ASSERT_EQ(r.torques.size(), 4u);
  for (const auto& ts : r.torques)
    if (ts.joint == "gimbal.pitch") EXPECT_DOUBLE_EQ(ts.capacity_nm, 200.0);
}

// Everything held rigid on the table (a rigid link on a held gimbal) moves with it, so
// the table's actuator must give (table mass + carried mass) x the table's
// acceleration at every sample (1e-9 of the peak), and the carried weight is the
// link's and the three rings' (m + 3 m_ring) g.
TEST(Gimbal, TableForceIsTheWholeMassTimesItsAcceleration) {
  ArticleScene s = rigidLinkOnGimbal(0, 20 * kDeg, 0);
  s.article.base.type = BaseType::Table;
  s.article.base.table_mass = 100;
  const double amp = 0.002, f = 3.0, w = 2 * M_PI * f;
  s.article.base.motion = TableMotion::sine(amp, f);
  s.simulation.duration = 0.5;
  const SimulationResult r = simulate(s);
  const double carried = 3.0 + 3 * 10.0;
  EXPECT_NEAR(r.carried_weight_n, carried * 9.81, 1e-9);
  const int force = column(r.record, "table_force_n");
  double peak = 0;
  for (const auto& row : r.record.rows) {
    const double expected = (100 + carried) * (-amp * w * w * std::sin(w * row[0]));
    EXPECT_NEAR(row[force], expected, 1e-9 * (100 + carried) * amp * w * w) << "t = " << row[0];
    peak = std::max(peak, std::abs(row[force]));
  }
  EXPECT_DOUBLE_EQ(r.peak_table_force_n, peak);
}

// Held gimbal angles in the modal analysis of the MMV article: pitch p gives exactly
// the modes of the article with its base turned by p in the plane; roll r leaves
// gravity's in-plane part g cos r, so the modes are those of the article under g cos r
// (the links are rigid out of their plane). No gimbal: the scene builds none and its
// modes are the default scene's.
TEST(Gimbal, HeldAnglesReorientTheModes) {
  const ArticleScene plain = loadDefaultScene();
  ArticleScene pitched = plain, turned = plain, rolled = plain, weaker = plain;
  pitched.article.base.gimbal = GimbalSpec{};
  pitched.article.base.gimbal->pitch.angle = 30 * kDeg;
  turned.article.base.direction += 30 * kDeg;
  rolled.article.base.gimbal = GimbalSpec{};
  rolled.article.base.gimbal->roll.angle = 60 * kDeg;
  weaker.gravity[1] *= std::cos(60 * kDeg);
  const auto fp = solveSceneModes(pitched).frequencies_hz, ft = solveSceneModes(turned).frequencies_hz;
  const auto fr = solveSceneModes(rolled).frequencies_hz, fw = solveSceneModes(weaker).frequencies_hz;
  const auto f0 = solveSceneModes(plain).frequencies_hz;
  ASSERT_EQ(fp.size(), ft.size());
  ASSERT_EQ(fr.size(), fw.size());
  ASSERT_EQ(fp.size(), f0.size());
  for (int i = 0; i < 6; ++i) {
    EXPECT_NEAR(fp(i) / ft(i), 1.0, 1e-8) << "mode " << i + 1;
    EXPECT_NEAR(fr(i) / fw(i), 1.0, 1e-8) << "mode " << i + 1;
  }
  EXPECT_GT(std::abs(fr(0) / f0(0) - 1), 1e-4);  // and gravity matters to mode 1
}

// A spin-up of the yaw axis (Kane, Ryan and Banerjee's profile, 90 deg/s over 1 s, on a
// slip ring) turns the article past a half turn: the recorded angle is the profile's at
// every sample (225 deg after 3 s), and the motor gives (m (L^2 / 3 + r^2) + 3 J_ring)
// theta'' (r^2 = I/A the section's gyration, which the link's inertia about the plane's
// in-plane normal carries (sim/model/article_builder.cpp, pieceBody); the three rings turn
// with yaw; gravity has no moment about the vertical), to 1e-9 of the peak, nothing once
// the rate is constant.
TEST(Gimbal, YawSpinUpTurnsPastAHalfTurnWithTheInverseDynamicsTorque) {
  ArticleScene s = rigidLinkOnGimbal(0, 0, 0);
  SlewSpec spin;
  spin.spin_rate = 90 * kDeg;
  spin.spin_ramp = 1.0;
  s.article.base.gimbal->yaw.continuous = true;
  s.article.base.gimbal->yaw.slew = spin;
  s.article.base.gimbal->ring_inertia = 0.7;
  s.simulation.duration = 3.0;
  s.simulation.sample_rate_hz = 100;
  const SimulationResult r = simulate(s);
  const int a = column(r.record, "gimbal.yaw_angle_deg"), t = column(r.record, "gimbal.yaw_torque_n_m");
  const testing::Beam b;  // rigidLinkOnGimbal's section
  const double I = 3.0 * (1.0 / 3 + b.second_moment / b.area) + 3 * 0.7, peak = I * 2 * (90 * kDeg) / 1.0;
  EXPECT_NEAR(r.record.rows.back()[a], 90 * (3.0 - 0.5), 1e-9);
  const facility::Slew model = facility::makeSpinUp(0, 90 * kDeg, 1.0);
  double largest = 0;
  for (const auto& row : r.record.rows) {
    const facility::SlewState st = model.at(row[0]);
    EXPECT_NEAR(row[a], st.angle / kDeg, 1e-9) << "t = " << row[0];
    EXPECT_NEAR(std::abs(row[t]), I * st.acceleration, 1e-9 * peak) << "t = " << row[0];
    largest = std::max(largest, std::abs(row[t]));
  }
  EXPECT_NEAR(largest, peak, 1e-9 * peak);  // at half the ramp
}

// An angle program on the pitch axis (a CSV in degrees, 0 -> 30 -> 10 deg): the angle
// follows it and the motor's torque is the inverse dynamics, as for a slew.
TEST(Gimbal, PitchAngleProgramTorqueIsTheInverseDynamics) {
  SlewSpec program;
  program.program_csv = "time_s,angle_deg\n0,0\n0.5,30\n1.2,10\n";
  program.program_source = "pitch.csv";
  const SimulationResult r = expectPitchInverseDynamics(
      program, facility::makeAngleProgram(0, facility::csvProfile(program.program_csv, "pitch.csv"), kDeg, 45 * kDeg));
  EXPECT_NEAR(r.record.rows.back()[column(r.record, "gimbal.pitch_angle_deg")], 10.0, 1e-9);
}

}  // namespace
}  // namespace mmv
