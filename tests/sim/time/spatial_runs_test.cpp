// Time runs of the spatial article (docs/spatial.md). Sensors: every axis of a
// triaxial accelerometer and of a rate gyro, read in a run that leaves the plane, against
// an independent rigid-body estimate passed through the same instrument model (its band
// filters, resolution and range), and the planar model's readings where the spatial
// model is held in the plane. Trade: the error and the motion scored include z. The
// table's y axis: a stage across the plane.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "facility/sensors.hpp"
#include "facility/slews.hpp"
#include "sim/time/simulation.hpp"
#include "sim/time/trade.hpp"
#include "support/record_column.hpp"
#include "support/spatial_scenes.hpp"

namespace mmv {
namespace {

using testing::column;

SensorSceneSpec sensor(const std::string& name, const std::string& type, const std::string& point, int axis) {
  SensorSceneSpec s;
  s.name = name;
  s.type = type;
  s.target = point;
  s.axis = axis;
  s.where = "<test>";
  return s;
}

// A stiff link hanging from the gimbal, rolled 0 to 20 deg (cycloidal, 1 s): it swings
// out of the plane as a rigid pendulum on the roll axis, which is the link's transverse
// axis. At the tip, the gyro about that axis reads the roll rate theta'; the accelerometer
// along the section's normal reads the specific force across the swing,
// -(L theta'' + g sin theta), within the ringing of the link's 123 Hz out-of-plane mode
// that the slew's jerk sets off; the gyros about the link and about the normal, and the
// accelerometer across the link in its plane, read nothing (the link is symmetric).
TEST(SpatialSensors, EveryAxisReadsARollSlewAsTheRigidBodyEstimate) {
  const double m = 3.0, L = 1.0, g = 9.81, fs = 1000;
  ArticleScene s = testing::spatialCantilever(testing::explicitSection(1e-4, 2e-8, 2e-8, 4e-8), m / (1e-4 * L), 7e12,
                                              2.7e12, L, 4);
  s.gravity = {0, -g, 0};
  s.article.base.direction = -M_PI / 2;  // hanging
  s.article.base.gimbal = GimbalSpec{};
  SlewSpec slew;
  slew.to = 20 * M_PI / 180;
  s.article.base.gimbal->roll.slew = slew;
  s.simulation.duration = 1.0;
  s.simulation.sample_rate_hz = fs;
  s.simulation.integrator = "cvode_bdf";
  s.simulation.accuracy = 1e-7;
  s.sensors = {sensor("rate_y", "rate_gyro", "link1.tip", 1), sensor("rate_x", "rate_gyro", "link1.tip", 0),
               sensor("rate_z", "rate_gyro", "link1.tip", 2), sensor("acc_z", "accelerometer", "link1.tip", 2),
               sensor("acc_y", "accelerometer", "link1.tip", 1)};
  const SimulationResult r = simulate(s);
  const facility::Slew motion = facility::makeSlew(facility::SlewShape::Cycloidal, 0, slew.to, 0,
                                                   {90 * M_PI / 180, slew.max_rate, slew.max_acceleration});
  facility::Sensor gyro(facility::rateGyroSpec(), fs), accel(facility::accelerometerSpec(), fs);
  const int rate_y = column(r.record, "rate_y_rad_per_s"), acc_z = column(r.record, "acc_z_m_per_s2");
  double peak_rate = 0, peak_acc = 0, err_rate[2] = {0, 0}, err_acc[2] = {0, 0}, others = 0, acc_y = 0;
  for (const auto& row : r.record.rows) {
    const facility::SlewState st = motion.at(row[0]);
    const double rate = gyro.sample(st.rate), acc = accel.sample(L * st.acceleration + g * std::sin(st.angle));
    peak_rate = std::max(peak_rate, std::abs(rate));
    peak_acc = std::max(peak_acc, std::abs(acc));
    for (int sign : {0, 1}) {  // the estimate up to the axes' sense
      err_rate[sign] = std::max(err_rate[sign], std::abs(row[rate_y] - (sign ? -rate : rate)));
      err_acc[sign] = std::max(err_acc[sign], std::abs(row[acc_z] - (sign ? -acc : acc)));
    }
    for (const char* c : {"rate_x_rad_per_s", "rate_z_rad_per_s"}) others = std::max(others, std::abs(row[column(r.record, c)]));
    acc_y = std::max(acc_y, std::abs(row[column(r.record, "acc_y_m_per_s2")]));
  }
  EXPECT_GT(peak_rate, 0.6);  // 2 x 20 deg / 1 s at the middle of the slew
  EXPECT_LT(std::min(err_rate[0], err_rate[1]), 2e-3 * peak_rate);  // 5e-4
  EXPECT_LT(std::min(err_acc[0], err_acc[1]), 1.5e-2 * peak_acc);  // 5.7e-3
  EXPECT_LT(others, 1e-9 * peak_rate);  // the symmetric link neither twists nor bends in its plane
  EXPECT_LT(acc_y, 1e-9 * peak_acc);
}

// Held in its plane, the spatial model's instruments read what the planar model's do:
// the default slew of joint 1 with gyros about the normal and accelerometers along and
// across each link, to 1e-9 of each column's peak (they agree bit for bit).
TEST(SpatialSensors, HeldInThePlaneTheyReadThePlanarModel) {
  ArticleScene planar = loadDefaultScene();
  for (auto& l : planar.article.links) l.segments = 2;
  SlewSpec slew;
  slew.to = planar.article.joints[0].angle + 10 * M_PI / 180;
  planar.article.joints[0].slew = slew;
  planar.simulation.duration = 0.3;
  planar.simulation.sample_rate_hz = 400;
  planar.simulation.integrator = "cvode_bdf";
  planar.simulation.accuracy = 1e-9;
  // The segment model in both (the spatial one has no modal links): the accelerometers'
  // 1 mg quantization turns a round-off difference into a step.
  planar.simulation.fidelity = SimulationSpec::Fidelity::Segments;
  planar.sensors = {sensor("g1", "rate_gyro", "link2.tip", 2), sensor("ax", "accelerometer", "link3a.tip", 0),
                    sensor("ay", "accelerometer", "link3a.tip", 1), sensor("as", "accelerometer", "link2@0.5", 1)};
  ArticleScene held = planar;
  held.article.model = ArticleModel::Spatial;
  held.article.lock_out_of_plane = true;
  const SimulationResult a = simulate(planar), b = simulate(held);
  ASSERT_EQ(a.record.rows.size(), b.record.rows.size());
  for (const char* c : {"g1_rad_per_s", "ax_m_per_s2", "ay_m_per_s2", "as_m_per_s2"}) {
    const int ca = column(a.record, c), cb = column(b.record, c);
    double peak = 0, diff = 0;
    for (std::size_t i = 0; i < a.record.rows.size(); ++i) {
      peak = std::max(peak, std::abs(a.record.rows[i][ca]));
      diff = std::max(diff, std::abs(a.record.rows[i][ca] - b.record.rows[i][cb]));
    }
    EXPECT_GT(peak, 0) << c;
    EXPECT_LE(diff, 1e-9 * peak) << c;
  }
}

}  // namespace
}  // namespace mmv

namespace mmv {
namespace {

// trade on the spatial model scores the tips' out-of-plane motion too: a stiff link
// hanging from the gimbal, rolled 20 deg, moves its tip 2 L sin 10 deg along the chord
// of its swing, almost all of it out of the plane (the in-plane part is L (1 - cos 20)).
TEST(SpatialTrade, TheScoredMotionIncludesTheSwingOutOfThePlane) {
  const double L = 1.0;
  ArticleScene s = testing::spatialCantilever(testing::explicitSection(1e-4, 2e-8, 2e-8, 4e-8), 3.0 / 1e-4, 7e11,
                                              2.7e11, L, 2);
  s.gravity = {0, -9.81, 0};
  s.article.base.direction = -M_PI / 2;
  s.article.base.gimbal = GimbalSpec{};
  SlewSpec slew;
  slew.to = 20 * M_PI / 180;
  s.article.base.gimbal->roll.slew = slew;
  s.simulation.duration = 1.0;
  s.simulation.sample_rate_hz = 50;
  TradeOptions o;
  o.integrators = {"cvode_bdf"};
  o.accuracies = {1e-4};
  o.segments = {};
  const TradeStudy t = runTrade(articleTradeProblem(s), o);
  EXPECT_NEAR(t.reference_amplitude_m, 2 * L * std::sin(10 * M_PI / 180), 1e-3);
  ASSERT_EQ(t.runs.size(), 1u);
  EXPECT_TRUE(t.runs[0].ok) << t.runs[0].failure;
}

}  // namespace
}  // namespace mmv

namespace mmv {
namespace {

// The table's y axis (base.motion_z, across the plane): a stage on the x table driven by
// its program. A rigid spatial article on it moves with it, and the stage's actuator
// force is the article's mass times the program's acceleration (the stage is massless).
TEST(SpatialTable, TheYAxisStageCarriesTheArticleAcrossThePlane) {
  const double m_link = 3.0, tip = 0.5, A = 0.004, f = 2.0;
  ArticleScene s = testing::spatialCantilever(testing::explicitSection(1e-4, 2e-8, 2e-8, 4e-8), m_link / 1e-4, 7e10,
                                              2.7e10, 1.0, 2, tip);
  s.article.links[0].rigid = true;
  s.gravity = {0, -9.81, 0};
  s.article.base.type = BaseType::Table;
  s.article.base.motion_z = TableMotion::sine(A, f);
  s.simulation.duration = 1.0;
  s.simulation.sample_rate_hz = 200;
  s.simulation.integrator = "rk_merson";
  s.simulation.accuracy = 1e-8;
  const SimulationResult r = simulate(s);
  const int z = column(r.record, "table_z_m"), fz = column(r.record, "table_z_force_n"),
            tip_z = column(r.record, "link1.tip_z_m"), tip_y = column(r.record, "link1.tip_y_m");
  const double w = 2 * M_PI * f, mass = m_link + tip, peak_force = mass * A * w * w;
  double worst_z = 0, worst_force = 0, worst_tip = 0;
  for (const auto& row : r.record.rows) {
    worst_z = std::max(worst_z, std::abs(row[z] - A * std::sin(w * row[0])));
    worst_force = std::max(worst_force, std::abs(row[fz] + mass * A * w * w * std::sin(w * row[0])));
    worst_tip = std::max({worst_tip, std::abs(row[tip_z] - row[z]), std::abs(row[tip_y] - r.record.rows[0][tip_y])});
  }
  EXPECT_LT(worst_z, 1e-12);
  EXPECT_LT(worst_force, 1e-6 * peak_force) << "peak " << peak_force << " N";
  EXPECT_LT(worst_tip, 1e-9);
  EXPECT_NEAR(r.peak_table_force_n, peak_force, 0.01 * peak_force);  // the x table, at rest, needs none
}

}  // namespace
}  // namespace mmv
