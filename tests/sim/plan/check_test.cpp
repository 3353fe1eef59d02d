// mmvlab check (sim/plan/check.hpp): each kind of line against a hand-computed case.
#include "sim/plan/check.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "facility/sensors.hpp"
#include "facility/slews.hpp"
#include "sim/core/text.hpp"
#include "sim/scene/scene.hpp"
#include "tests/support/scenes.hpp"

namespace mmv {
namespace {

const CheckLine* find(const CheckReport& r, const std::string& starts) {
  for (const auto& l : r.lines)
    if (l.requirement.rfind(starts, 0) == 0) return &l;
  return nullptr;
}

constexpr double kG = 9.80665;

testing::Beam rigidBeam() {
  testing::Beam b;
  b.length = 1.2;
  b.area = 2e-4;  // 7800 * 2e-4 * 1.2 = 1.872 kg
  return b;
}

TEST(Check, RigidLinkHoldingTorqueIsWorstWhereTheLinkIsLevelInsideTheRange) {
  // Base direction 20 deg: the link is level at joint angle -20 deg, between grid points.
  const auto b = rigidBeam();
  ArticleScene s = testing::cantileverScene(b, 1, kG, 20.0, 0.5, /*rigid=*/true);
  const double m = b.massPerLength() * b.length, tau = (m * b.length / 2 + 0.5 * b.length) * kG;
  s.article.joints[0].torque_capacity = 2 * tau;
  const CheckReport r = runCheck(s);
  const CheckLine* l = find(r, "joint1 holding torque, worst over +-45 deg");
  ASSERT_NE(l, nullptr);
  EXPECT_NEAR(l->demand, tau, 1e-6 * tau);
  EXPECT_NEAR(l->margin_pct, 50.0, 1e-4);
  EXPECT_EQ(l->verdict, Verdict::Pass);
  EXPECT_NE(l->note.find("joint1 -20.0 deg"), std::string::npos) << l->note;
  // A smaller capacity fails; one within the required margin warns.
  s.article.joints[0].torque_capacity = 0.9 * tau;
  EXPECT_EQ(find(runCheck(s), "joint1 holding")->verdict, Verdict::Fail);
  s.article.joints[0].torque_capacity = 1.1 * tau;
  EXPECT_EQ(find(runCheck(s), "joint1 holding")->verdict, Verdict::Warn);
}

TEST(Check, FlexibleLinkHoldsLessThanRigidWhereItSags) {
  // A soft horizontal cantilever sags, pulling its mass towards the joint: the
  // flexible holding torque is below m g L / 2 and the rigid one is given in the note.
  testing::Beam b = rigidBeam();
  b.second_moment = 2e-10;
  ArticleScene s = testing::cantileverScene(b, 16, kG, 0.0);
  s.article.joints[0].torquer = LumpedMass{2.0, 0};  // on the ground: no torque of its own
  const double tau = b.massPerLength() * b.length * b.length / 2 * kG;
  const CheckReport r = runCheck(s);
  const CheckLine* l = find(r, "joint1 holding");
  ASSERT_NE(l, nullptr);
  EXPECT_LT(l->demand, tau);
  EXPECT_GT(l->demand, 0.9 * tau);
  EXPECT_EQ(l->verdict, Verdict::NotChecked);  // no capacity in the scene
  EXPECT_NE(l->note.find(strf("needs %.3g N*m per kg of its 2 kg torquer", l->demand / 2)), std::string::npos) << l->note;
  EXPECT_NE(l->note.find(strf("rigid links: %.4g N*m", tau)), std::string::npos) << l->note;
}

ArticleScene tableScene(double amplitude, double f_hz) {
  testing::Beam b = rigidBeam();
  b.second_moment = 1e-6;  // first mode far above the 2 Hz sine: quasi-static
  ArticleScene s = testing::cantileverScene(b, 4, kG, -90.0);
  s.article.joints[0].torquer = LumpedMass{3.0, 0};
  s.article.base.type = BaseType::Table;
  s.article.base.motion = TableMotion::sine(amplitude, f_hz);
  s.article.base.gimbal = GimbalSpec{};
  s.simulation.duration = 2;
  s.sensors.push_back({"acc", "accelerometer", "link1.tip", 1, 0, 1, "<test>"});
  return s;
}

TEST(Check, TablePayloadStrokeAndAccelerometerPeakUnderASine) {
  const ArticleScene s = tableScene(0.01, 2.0);
  const CheckReport r = runCheck(s);
  const double m_link = rigidBeam().massPerLength() * rigidBeam().length;
  const CheckLine* payload = find(r, "payload weight");
  ASSERT_NE(payload, nullptr);
  EXPECT_NEAR(payload->demand, (m_link + 3.0 + 3 * 10.0) * kG, 1e-9 * payload->demand);  // link, torquer, three gimbal rings
  EXPECT_EQ(payload->capacity, 2300);
  const CheckLine* stroke = find(r, "stroke of the program");
  ASSERT_NE(stroke, nullptr);
  EXPECT_DOUBLE_EQ(stroke->demand, 0.01);
  EXPECT_NEAR(stroke->margin_pct, (0.15 - 0.01) / 0.15 * 100, 1e-9);
  EXPECT_NE(stroke->note.find("peak acceleration 1.58 m/s^2"), std::string::npos) << stroke->note;  // 0.01 (4 pi)^2
  // The hanging link's transverse axis is world x: the accelerometer reads the table's
  // acceleration (2 pi f)^2 A through its band limits: in steady state (the note), and
  // over the scene's 2 s run from rest (the demand) at least that (a 200 Hz sample
  // misses the crest by at most 1 - cos(pi f / fs) = 0.1 %) plus the 0.1 Hz high-pass's
  // response to the sine starting at t = 0 (5.6 % here).
  const CheckLine* acc = find(r, "acc (accelerometer at link1.tip) under the table's program");
  ASSERT_NE(acc, nullptr);
  const facility::Sensor sensor(facility::accelerometerSpec(), s.simulation.sample_rate_hz);
  const double expected = std::pow(2 * M_PI * 2.0, 2) * 0.01 * sensor.bandGain(2.0);
  EXPECT_NE(acc->note.find("steady state of the 2 Hz sine would read 1.58 m/s^2"), std::string::npos) << acc->note;
  EXPECT_GE(acc->demand, 0.999 * expected);
  EXPECT_LE(acc->demand, 1.1 * expected);
  EXPECT_EQ(acc->verdict, Verdict::Pass);
  // The same accelerometer in the rigid-link run, as recorded: the link is rigid, so the
  // time run of the nonlinear model and the linear model's response are one motion.
  const CheckLine* run = find(r, "acc (accelerometer at link1.tip) during the scene's run");
  ASSERT_NE(run, nullptr);
  EXPECT_NEAR(run->demand, acc->demand, 1e-3 * acc->demand);
}

TEST(Check, ASineBeyondTheAccelerometersRangeFails) {
  const CheckReport r = runCheck(tableScene(0.14, 3.0));  // (6 pi)^2 0.14 = 49.7 m/s^2 > 5 g
  const CheckLine* acc = find(r, "acc (accelerometer at link1.tip) under the table's program");
  ASSERT_NE(acc, nullptr);
  EXPECT_EQ(acc->verdict, Verdict::Fail);
  EXPECT_EQ(r.overall, Verdict::Fail);
}

TEST(Check, LengthInMillimetresIsNamed) {
  testing::Beam b = rigidBeam();
  b.length = 2440;
  const CheckReport r = runCheck(testing::cantileverScene(b, 2, kG, -90.0, 0, true));
  bool named = false;
  for (const auto& l : r.lines) named = named || (l.group == "plausibility" && l.requirement.find("given in mm") != std::string::npos);
  EXPECT_TRUE(named);
  EXPECT_EQ(r.overall, Verdict::Warn);
}

TEST(Check, HangingArticleDepthAgainstTheLab) {
  ArticleScene s = testing::cantileverScene(rigidBeam(), 1, kG, -90.0, 0, true);
  s.lab = facility::LabSpec{};
  const CheckReport r = runCheck(s);
  const CheckLine* depth = find(r, "depth below the platform's top");
  ASSERT_NE(depth, nullptr);
  EXPECT_NEAR(depth->demand, s.lab->base_below_platform + rigidBeam().length, 1e-9);
  EXPECT_DOUBLE_EQ(depth->capacity, s.lab->platform_height);
  // Longer than the platform is high: it would hit the floor.
  testing::Beam tall = rigidBeam();
  tall.length = 14;
  s = testing::cantileverScene(tall, 1, kG, -90.0, 0, true);
  s.lab = facility::LabSpec{};
  EXPECT_EQ(find(runCheck(s), "depth below the platform's top")->verdict, Verdict::Fail);
}

// The platform's hole is square in x and z: on the spatial model a link that rises into
// it tilted out of the plane is judged by its offset along z too. A rigid 1.2 m link
// pointing up, tilted 60 deg toward +z, puts its tip 1.2 sin 60 = 1.04 m off the hole's
// centre along z (beyond the 0.76 m half-side: fail); tilted 20 deg, 0.41 m (pass).
TEST(Check, TheLabsHoleSeesOffsetsOutOfThePlane) {
  for (const double tilt_deg : {60.0, 20.0}) {
    ArticleScene s = testing::cantileverScene(rigidBeam(), 1, kG, 90.0, 0, true);
    s.lab = facility::LabSpec{};
    s.article.model = ArticleModel::Spatial;
    s.article.links[0].tilt = tilt_deg * M_PI / 180;
    const CheckReport report = runCheck(s);  // the line points into it
    const CheckLine* hole = find(report, "points above the platform's underside within the hole");
    ASSERT_NE(hole, nullptr);
    EXPECT_NEAR(hole->demand, rigidBeam().length * std::sin(tilt_deg * M_PI / 180), 1e-9) << tilt_deg;
    EXPECT_EQ(hole->verdict, tilt_deg > 40 ? Verdict::Fail : Verdict::Pass) << tilt_deg;
  }
}

TEST(Check, ClosedTreeIsCheckedAtItsConfigurationAndSaysSo) {
  const ArticleScene s = loadArticleSceneFile(MMVLAB_SOURCE_DIR "/scenes/mmv-closed.yaml");
  const CheckReport r = runCheck(s);
  const CheckLine* l = find(r, "joint1 holding torque at the scene's angles");
  ASSERT_NE(l, nullptr);
  EXPECT_NE(l->note.find("closed tree"), std::string::npos);
}

TEST(Check, JudgeMargins) {
  CheckLine l;
  l.demand = 80;
  l.capacity = 100;
  judge(l, 20);
  EXPECT_DOUBLE_EQ(l.margin_pct, 20);
  EXPECT_EQ(l.verdict, Verdict::Pass);
  l.demand = 81;
  judge(l, 20);
  EXPECT_EQ(l.verdict, Verdict::Warn);
  l.demand = 101;
  judge(l, 20);
  EXPECT_EQ(l.verdict, Verdict::Fail);
  l.capacity = 0;
  judge(l, 20);
  EXPECT_EQ(l.verdict, Verdict::NotChecked);
}

}  // namespace
}  // namespace mmv

namespace mmv {
namespace {

const CheckLine* findId(const CheckReport& r, const std::string& id) {
  for (const auto& l : r.lines)
    if (l.id == id) return &l;
  return nullptr;
}

ArticleScene spatialOnTheTable(bool branches_out) {
  ArticleScene s = std::get<ArticleScene>(loadSceneFile(std::string(MMVLAB_SOURCE_DIR) + "/scenes/mmv-table.yaml"));
  s.article.model = ArticleModel::Spatial;
  if (branches_out)
    for (auto& l : s.article.links)
      if (l.name == "link3a" || l.name == "link3b") l.tilt = (l.name == "link3a" ? 1 : -1) * 15 * M_PI / 180;
  return s;
}

// The planarity lines (spatial model only): every out-of-plane mode in the band against
// its nearest in-plane mode's half-power bandwidth, and the table program's out-of-plane
// response at the tips against the limit, as the modes report computes it. The symmetric
// article is decoupled; spreading link 3's branches out of the plane couples it, and a
// limit below its ratio warns.
TEST(Check, PlanarityLinesJudgeTheSpatialArticle) {
  EXPECT_EQ(findId(runCheck(std::get<ArticleScene>(loadSceneFile(std::string(MMVLAB_SOURCE_DIR) + "/scenes/mmv-table.yaml"))),
                   "planarity.modes"),
            nullptr);
  const CheckReport sym = runCheck(spatialOnTheTable(false));
  const CheckLine* count = findId(sym, "planarity.modes");
  ASSERT_NE(count, nullptr);
  EXPECT_EQ(count->demand, 6);
  const CheckLine* base = findId(sym, "planarity.base x");
  ASSERT_NE(base, nullptr);
  EXPECT_EQ(base->demand, 0.0);
  EXPECT_EQ(base->verdict, Verdict::Pass);
  int separations = 0;
  for (const auto& l : sym.lines)
    if (l.id.rfind("planarity.mode", 0) == 0 && l.id != "planarity.modes") {
      ++separations;
      EXPECT_EQ(l.verdict, l.capacity > l.demand ? Verdict::Pass : Verdict::Advisory) << l.requirement;
    }
  EXPECT_EQ(separations, 6);

  const ArticleScene tilted = spatialOnTheTable(true);
  ModesOptions mo;
  mo.with_shapes = false;
  const ModesReport modes = runModes(tilted, mo);
  ASSERT_TRUE(modes.planarity.has_value());
  double worst = 0;
  for (const auto& r : modes.planarity->responses)
    if (r.excitation == "base x") worst = std::max(worst, r.ratio);
  EXPECT_GT(worst, 1e-3);
  CheckOptions tight;
  tight.max_out_of_plane_ratio = 0.5 * worst;
  const CheckReport r = runCheck(tilted, tight, &modes);
  const CheckLine* coupled = findId(r, "planarity.base x");
  ASSERT_NE(coupled, nullptr);
  EXPECT_DOUBLE_EQ(coupled->demand, worst);
  EXPECT_EQ(coupled->verdict, Verdict::Advisory);  // beyond the limit: advice, labelled as such
  EXPECT_NE(r.overall, Verdict::Pass);  // and it raises the overall verdict
  EXPECT_EQ(findId(runCheck(tilted, CheckOptions{}, &modes), "planarity.base x")->verdict, Verdict::Pass);
}

// The gimbal's range lines follow what each axis commands: an angle program's largest
// angle (between its samples too: the cubic through 0, 30, 10 deg passes 30), not the
// move's end it does not have (0); a slip ring has no range to check (n/a, said so);
// the held roll axis its held angle.
TEST(Check, GimbalRangeLinesFollowSpinUpsAndAnglePrograms) {
  ArticleScene s = testing::cantileverScene(rigidBeam(), 1, kG, 0.0, 0.0, /*rigid=*/true);
  s.article.base.gimbal = GimbalSpec{};
  SlewSpec program;
  program.program_csv = "time_s,angle_deg\n0,0\n0.5,30\n1.2,10\n";
  program.program_source = "pitch.csv";
  s.article.base.gimbal->pitch.slew = program;
  SlewSpec spin;
  spin.spin_rate = 1.0;
  spin.spin_ramp = 0.5;
  s.article.base.gimbal->yaw.slew = spin;
  s.article.base.gimbal->yaw.continuous = true;
  s.article.base.gimbal->yaw.range = M_PI;
  s.simulation.duration = 1.5;
  const CheckReport r = runCheck(s);
  const facility::Slew p = facility::makeAngleProgram(0, facility::csvProfile(program.program_csv, "pitch.csv"), M_PI / 180, M_PI);
  double top = 0;  // sampled 10x finer than the reader does
  for (int k = 0; k <= 20000; ++k) top = std::max(top, std::abs(p.at(p.duration() * k / 20000).angle) * 180 / M_PI);
  const CheckLine* pitch = find(r, "gimbal pitch angle");
  ASSERT_NE(pitch, nullptr);
  EXPECT_NEAR(pitch->demand, top, 1e-4);
  EXPECT_GT(pitch->demand, 30.0);
  EXPECT_NE(pitch->note.find("angle program"), std::string::npos) << pitch->note;
  const CheckLine* yaw = find(r, "gimbal yaw angle");
  ASSERT_NE(yaw, nullptr);
  EXPECT_EQ(yaw->verdict, Verdict::NotChecked);
  EXPECT_NE(yaw->note.find("slip ring"), std::string::npos) << yaw->note;
  EXPECT_EQ(find(r, "gimbal roll angle")->demand, 0.0);
}

}  // namespace
}  // namespace mmv
