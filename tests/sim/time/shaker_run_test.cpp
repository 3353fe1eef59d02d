// The extra shaker in time runs (`shaker.program`): its armature on a slider along the
// force, held to the driving point by the stinger (sim/model/attachments.hpp).
//
// Known answer: a rigid arm on a servo joint (spring k) in zero gravity, the shaker at
// its tip pushing across it, is one degree of freedom with the armature's mass m at the
// lever L: (I + m L^2) theta'' + k theta = F L sin(w t) from rest, whose solution
// theta = F L / (k - I_eff w^2) (sin w t - (w / w_n) sin w_n t) is written here. The
// force stays along world y while the arm turns (theta < 1e-4 rad): the run departs from
// the linear solution by about theta^2 / 2 ~ 4e-9 of it.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "sim/core/errors.hpp"
#include "sim/model/article_builder.hpp"
#include "sim/model/stations.hpp"
#include "sim/modes/system_modes.hpp"
#include "sim/core/text.hpp"
#include "sim/plan/check.hpp"
#include "sim/statics/linearize.hpp"
#include "sim/statics/statics.hpp"
#include "sim/time/simulation.hpp"
#include "sim/time/trade.hpp"
#include "support/record_column.hpp"

namespace mmv {
namespace {

const char* kShakenArm = R"(name: shaken arm
gravity: [0, 0, 0]
materials:
  al: {density: 2700, youngs_modulus: 7.0e10}
sections:
  bar: {shape: rectangle, b: 0.02, h: 0.02}
joints:
  - {name: j1, parent: base, angle_deg: 0, hold: servo, servo_stiffness: 200}
links:
  - {name: arm, joint: j1, material: al, section: bar, length: 1.0, segments: rigid}
shaker:
  at: arm@1.0m
  direction: [0, 1, 0]
  armature_mass_kg: 0.5
  force_limit_n: 100
  program: {type: sine, amplitude: 0.01, frequency_hz: 1.0}
simulation: {duration: 3, sample_rate_hz: 1000, start: rest, integrator: rk_merson, accuracy: 1.0e-12}
)";

TEST(ShakerRun, TheArmaturesMassAndTheForceMoveTheArmAsTheClosedForm) {
  const ArticleScene s = std::get<ArticleScene>(parseScene(kShakenArm, "arm.yaml"));
  const SimulationResult r = simulate(s);
  const double L = 1.0, m_link = 2700 * 0.02 * 0.02 * L, I = m_link * L * L / 3, m = 0.5, k = 200, F = 0.01;
  const double w = 2 * M_PI * 1.0, I_eff = I + m * L * L, wn = std::sqrt(k / I_eff);
  using testing::column;
  const int angle = column(r.record, "j1_angle_deg"), force = column(r.record, "shaker_force_n"),
            stroke = column(r.record, "shaker_stroke_m"), stinger = column(r.record, "shaker_stinger_force_n");
  ASSERT_GT(r.record.rows.size(), 500u);
  double peak = 0, worst = 0, worst_stroke = 0, worst_stinger = 0;
  for (const auto& row : r.record.rows) {
    const double t = row[0];
    const double theta = F * L / (k - I_eff * w * w) * (std::sin(w * t) - w / wn * std::sin(wn * t));
    const double theta_dd = F * L / (k - I_eff * w * w) * (-w * w * std::sin(w * t) + w * wn * std::sin(wn * t));
    const double run = row[angle] * M_PI / 180;
    peak = std::max(peak, std::abs(theta));
    worst = std::max(worst, std::abs(run - theta));
    EXPECT_NEAR(row[force], F * std::sin(w * t), 1e-12);
    // The armature follows the tip along y: L sin(theta) from the start.
    worst_stroke = std::max(worst_stroke, std::abs(row[stroke] - L * std::sin(run)));
    // The stinger passes the force less the armature's inertia.
    worst_stinger = std::max(worst_stinger, std::abs(row[stinger] - (F * std::sin(w * t) - m * L * theta_dd)));
  }
  std::printf("[shaker] peak %.6g rad, largest error %.3g rad (%.2g of the peak); stroke %.3g m; stinger %.3g N\n", peak,
              worst, worst / peak, worst_stroke, worst_stinger);
  EXPECT_LT(worst, 1e-5 * peak);          // theta^2 / 2 and the integrator
  EXPECT_LT(worst_stroke, 1e-11);         // the stinger's closure
  EXPECT_LT(worst_stinger, 1e-3 * F);     // F - m L theta''
  ASSERT_TRUE(r.shaker.has_value());
  EXPECT_NEAR(r.shaker->peak_force_n, F, 1e-6);
  EXPECT_NEAR(r.shaker->peak_stroke_m, L * peak, 1e-4 * L * peak);
  EXPECT_FALSE(r.shaker->stroke_exceeded);
  // The program's work balances the arm's and the armature's energy (the balance's
  // trapezoidal rule at 1 kHz: (h w_n)^2 / 12 ~ 2e-5).
  EXPECT_LT(std::abs(r.max_energy_balance_error_j), 1e-4 * energyScale(r));
  EXPECT_GT(r.motion_work_j + 1e-12, 0.0);
}

TEST(ShakerRun, ADeadLoadsWorkIsInTheEnergyBalance) {
  // The armature's weight is cancelled by a dead load; a scene's `loads:` are dead loads
  // too. Started at rest away from the loaded equilibrium, the arm swings: its energy
  // changes by the load's work, which the balance must count (it did not while the load
  // had no potential energy: the balance was off by F dy, about 0.1 J here).
  std::string text = kShakenArm;
  text.erase(text.find("shaker:"), text.find("simulation:") - text.find("shaker:"));
  text += "loads:\n  - {point: arm.tip, force: [0, 10, 0]}\n";
  const SimulationResult r = simulate(std::get<ArticleScene>(parseScene(text, "arm.yaml")));
  std::printf("[dead load] peak kinetic %.4g J, largest balance error %.3g J\n", r.peak_kinetic_energy_j,
              r.max_energy_balance_error_j);
  EXPECT_GT(r.peak_kinetic_energy_j, 0.1);  // it swings: 10 N over 5 cm and back
  EXPECT_LT(std::abs(r.max_energy_balance_error_j), 1e-4 * r.peak_kinetic_energy_j);
}

// The run's armature (a body on a slider, held to the article by the stinger's closure)
// against the linear models' (the article's mass matrix plus m b b^T, b the station's
// Jacobian along the force, sim/linear/exciter.hpp): at a mesh node the driving point is
// the same material point, so the loaded modes agree to round-off; between nodes the run
// takes the piece's point (on the chord between two hinges) and the linear models the
// Hermite station, O(h^2) apart.
double loadedModesGap(const std::string& at, int modes, const std::string& segments = "8") {
  std::string text = kShakenArm;
  text.replace(text.find("hold: servo, servo_stiffness: 200"), 33, "hold: locked");
  text.replace(text.find("segments: rigid"), 15, "segments: " + segments);
  text.replace(text.find("at: arm@1.0m"), 12, "at: " + at);
  text.replace(text.find("direction: [0, 1, 0]"), 20, "direction: [0.6, 0.8, 0]");
  text.replace(text.find("gravity: [0, 0, 0]"), 18, "gravity: [0, -9.81, 0]");
  const ArticleScene s = std::get<ArticleScene>(parseScene(text, "arm.yaml"));
  const auto run = buildArticleModel(s, ModelUse::TimeRun);
  const EquilibriumResult eq = solveEquilibrium(*run);
  EXPECT_TRUE(eq.converged) << eq.failure;
  const ModalSolution with_closure = solveModes(linearize(*run, eq.state, eq.closure_multipliers), modes);

  const auto article = buildArticleModel(s);
  const EquilibriumResult eq2 = solveEquilibrium(*article);
  LinearizedModel lin = linearize(*article, eq2.state, eq2.closure_multipliers);
  std::string error;
  const StationPoint station(*article, *parseStation(at, s.article, error));
  SimTK::State at_rest = eq2.state;
  article->getSystem().realize(at_rest, SimTK::Stage::Position);
  const Eigen::MatrixXd J = station.translationJacobian(at_rest, lin.dofs);
  const Eigen::RowVectorXd b = 0.6 * J.row(0) + 0.8 * J.row(1);
  lin.M += 0.5 * b.transpose() * b;
  const ModalSolution added_mass = solveModes(lin, modes);
  double gap = 0;
  for (int i = 0; i < modes; ++i) {
    const double f1 = with_closure.frequencyHz(i), f2 = added_mass.frequencyHz(i);
    EXPECT_GT(f1, 0.1);
    gap = std::max(gap, std::abs(f1 / f2 - 1));
  }
  return gap;
}

TEST(ShakerRun, TheRunsArmatureIsTheLinearModelsAddedMass) {
  const double at_node = loadedModesGap("arm@1.0m", 4);
  const double coarse = loadedModesGap("arm@0.5m", 4, "8"), fine = loadedModesGap("arm@0.5m", 4, "16");
  std::printf("[shaker] loaded modes, run's model against M + m b b^T: %.3g at the tip node; mid-piece %.3g at 8 "
              "segments, %.3g at 16\n", at_node, coarse, fine);
  EXPECT_LT(at_node, 1e-9);
  // Mid-piece the run's stinger holds the Hermite station the linear models drive (a
  // weighted closure): before, it held the chord's point of the piece, and mode 4 differed
  // by 4.8 % at 8 segments and 1.6 % at 16.
  EXPECT_LT(coarse, 1e-9);
  EXPECT_LT(fine, 1e-9);
}

// The trade and the accuracy contract offer no modal links on a scene whose shaker
// drives it: the stinger closes the tree (their runs failed as non-finite states).
TEST(ShakerRun, TheTradeOffersNoModalLinksWhenTheStingerClosesTheTree) {
  std::string text = kShakenArm;
  text.replace(text.find("segments: rigid"), 15, "segments: 8");
  EXPECT_FALSE(articleTradeProblem(std::get<ArticleScene>(parseScene(text, "arm.yaml"))).has_modes);
  text.erase(text.find("  program:"), text.find("simulation:") - text.find("  program:"));
  EXPECT_TRUE(articleTradeProblem(std::get<ArticleScene>(parseScene(text, "arm.yaml"))).has_modes);
}

TEST(ShakerRun, AStrokeTooShortForTheMotionIsFlagged) {
  std::string text = kShakenArm;
  text.replace(text.find("armature_mass_kg: 0.5"), 21, "armature_mass_kg: 0.5\n  stroke_m: 0.00005");
  const SimulationResult r = simulate(std::get<ArticleScene>(parseScene(text, "arm.yaml")));
  ASSERT_TRUE(r.shaker.has_value());
  EXPECT_TRUE(r.shaker->stroke_exceeded);  // the tip swings about 0.085 mm
  EXPECT_GT(r.shaker->peak_stroke_m, 0.00005);
}

TEST(ShakerRun, OnlyARunBuildsTheArmature) {
  // The analyses see the article as the scene states it (the armature's shift is theirs to report).
  const ArticleScene s = std::get<ArticleScene>(parseScene(kShakenArm, "arm.yaml"));
  const auto analysis = buildArticleModel(s);
  const auto run = buildArticleModel(s, ModelUse::TimeRun);
  EXPECT_EQ(run->getNumCoordinates(), analysis->getNumCoordinates() + 1);
  EXPECT_TRUE(analysis->getClosures().empty());
  ASSERT_EQ(run->getClosures().size(), 1u);
  std::string idle = kShakenArm;
  idle.erase(idle.find("  program:"), idle.find("simulation:") - idle.find("  program:"));
  const auto no_program = buildArticleModel(std::get<ArticleScene>(parseScene(idle, "arm.yaml")), ModelUse::TimeRun);
  EXPECT_EQ(no_program->getNumCoordinates(), analysis->getNumCoordinates());
}

TEST(ShakerRun, ProgramsBeyondTheShakerOrItsAttachmentAreRefusedAtTheKey) {
  const std::string base = kShakenArm;
  const std::string program = "program: {type: sine, amplitude: 0.01, frequency_hz: 1.0}";
  auto with = [&](const std::string& replace_program, const std::string& extra = "") {
    std::string text = base;
    text.replace(text.find(program), program.size(), replace_program);
    const std::string armature = "  armature_mass_kg: 0.5";
    if (!extra.empty()) text.replace(text.find(armature), armature.size(), extra);
    return text;
  };
  auto refused = [&](const std::string& text, const std::string& message) {
    try {
      parseScene(text, "arm.yaml");
      ADD_FAILURE() << text << ": accepted";
    } catch (const SceneError& e) {
      EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("arm.yaml:"), std::string::npos) << e.what();
    }
  };
  // The force limit (force_limit_n: 100), at the bound and one past it.
  EXPECT_NO_THROW(parseScene(with("program: {type: sine, amplitude: 100, frequency_hz: 1.0}"), "arm.yaml"));
  refused(with("program: {type: sine, amplitude: 100.0001, frequency_hz: 1.0}"), "above the shaker's force limit");
  refused(with("program: {type: sweep, amplitude: -140, from_hz: 1, to_hz: 5, duration: 2}"), "above the shaker's force limit");
  // A random program: RMS x crest factor (3) against the limit.
  EXPECT_NO_THROW(parseScene(with("program: {type: random, rms: 33.3333, from_hz: 1, to_hz: 5, duration: 2}"), "arm.yaml"));
  refused(with("program: {type: random, rms: 33.334, from_hz: 1, to_hz: 5, duration: 2}"), "lower rms to 33.3333");
  // A CSV force program: its peak, sampled, against the limit.
  const std::string csv = (std::filesystem::temp_directory_path() / "mmv_shaker_force_test.csv").string();
  std::ofstream(csv) << "time_s,force_n\n0,0\n1,120\n2,0\n";
  refused(with("program: {type: csv, file: " + csv + "}"), "its peak force of 120 N is above");
  std::ofstream(csv) << "time_s,force_n\n0,0\n1,90\n2,0\n";
  EXPECT_NO_THROW(parseScene(with("program: {type: csv, file: " + csv + "}"), "arm.yaml"));
  std::filesystem::remove(csv);
  refused(with(program, "  armature_mass_kg: 0.0"), "shaker.armature_mass_kg > 0");
  std::string automatic = base;
  automatic.replace(automatic.find("at: arm@1.0m"), 12, "at: auto");
  automatic.replace(automatic.find("direction: [0, 1, 0]"), 20, "direction: auto");
  refused(automatic, "give shaker.at a station");
  refused(with("program: {type: sine, amplitude: 1.0}"), "shaker.program");
  std::string modal = base;
  modal.replace(modal.find("segments: rigid"), 15, "segments: 8, modes: 2");
  modal.replace(modal.find("integrator: rk_merson"), 21, "integrator: cvode_bdf");
  refused(modal, "remove links.arm.modes");
}

// `check` predicts the shaker program's travel before any run (issue 34): the linear model
// with the armature, from rest over the scene's run. Two ways: on the shaken arm against
// the closed form above (undamped, as the run: the scene names no damping), and on the
// flexible article on the table against the time run's own record.
TEST(ShakerRun, CheckPredictsTheProgramsTravelBeforeTheRun) {
  auto travel = [](const CheckReport& r) -> const CheckLine* {
    for (const auto& l : r.lines)
      if (l.id == "shaker.program_stroke") return &l;
    return nullptr;
  };
  const ArticleScene arm = std::get<ArticleScene>(parseScene(kShakenArm, "arm.yaml"));
  const CheckReport r = runCheck(arm);
  const CheckLine* l = travel(r);
  ASSERT_NE(l, nullptr);
  const double L = 1.0, I = 2700 * 0.02 * 0.02 * L * L * L / 3, m = 0.5, k = 200, F = 0.01;
  const double w = 2 * M_PI * 1.0, I_eff = I + m * L * L, wn = std::sqrt(k / I_eff);
  double peak = 0;
  for (int i = 0; i <= 3000; ++i) {  // the scene's 1000 samples a second over its 3 s
    const double t = i * 1e-3;
    peak = std::max(peak, std::abs(L * F * L / (k - I_eff * w * w) * (std::sin(w * t) - w / wn * std::sin(wn * t))));
  }
  std::printf("[shaker check] arm: predicted travel %.9g m, closed form %.9g m\n", l->demand, peak);
  EXPECT_NEAR(l->demand, peak, 1e-5 * peak);  // the input's first-order hold: (w dt)^2 / 8 = 5e-6
  EXPECT_EQ(l->capacity, arm.shaker->hardware.stroke);
  EXPECT_EQ(l->verdict, Verdict::Pass);
  std::string short_stroke = kShakenArm;
  short_stroke.replace(short_stroke.find("armature_mass_kg: 0.5"), 21, strf("armature_mass_kg: 0.5\n  stroke_m: %.6g", 0.99 * peak));
  EXPECT_EQ(travel(runCheck(std::get<ArticleScene>(parseScene(short_stroke, "arm.yaml"))))->verdict, Verdict::Fail);
  // The samples are capped at 200000 (20 a period of the program's highest frequency
  // over the 3 s run): 3333.33 Hz needs 199999.98 of them, 3334 Hz 200040; the note says
  // when the cap binds.
  for (const auto& [hz, capped] : {std::pair{"3333.333", false}, std::pair{"3334", true}}) {
    std::string fast = kShakenArm;
    fast.replace(fast.find("frequency_hz: 1.0"), 17, std::string("frequency_hz: ") + hz);
    const CheckReport c = runCheck(std::get<ArticleScene>(parseScene(fast, "arm.yaml")));
    ASSERT_NE(travel(c), nullptr);
    EXPECT_EQ(travel(c)->note.find("capped") != std::string::npos, capped) << hz << ": " << travel(c)->note;
  }

  // The article on the table (its hinge dampers), shaken at link 1's 0.61 m (between the
  // nodes of 8 segments) by a 2 s, 10 N sine at 3 Hz near mode 2, the table still.
  const auto tableScene = [](const std::string& table_amplitude) {
    SceneFlags eight;
    eight.segments = 8;
    eight.segments_label = "segments=8";
    return std::get<ArticleScene>(loadSceneFile(
        std::string(MMVLAB_SOURCE_DIR) + "/scenes/mmv-table.yaml",
        {"base.motion.amplitude=" + table_amplitude, "shaker.at=link1@0.61m", "shaker.direction=[0.8745, 0.485, 0]",
         "shaker.program={type: sine, amplitude: 10, frequency_hz: 3}", "simulation.duration=2", "simulation.sample_rate_hz=400"},
        eight));
  };
  const ArticleScene shaken = tableScene("0");
  const CheckReport shaken_check = runCheck(shaken);
  const CheckLine* predicted = travel(shaken_check);
  ASSERT_NE(predicted, nullptr);
  const SimulationResult run = simulate(shaken);
  ASSERT_TRUE(run.shaker.has_value());
  std::printf("[shaker check] table scene: predicted travel %.6g m, the run's %.6g m\n", predicted->demand, run.shaker->peak_stroke_m);
  EXPECT_GT(run.shaker->peak_stroke_m, 1e-5);
  // Linear against nonlinear (gravity's preload and the closure held exactly), and the
  // run's samples against the check's finer ones.
  EXPECT_NEAR(predicted->demand, run.shaker->peak_stroke_m, 0.005 * run.shaker->peak_stroke_m);  // measured 0.04 %

  // With the table moving too (its 2 Hz sine, 0.5 mm). The run used to start the armature
  // at rest against a stinger the table already moved: the scene's cvode_bdf drifted off
  // the closure (11.2 mm of travel), Simbody's integrators projected the mismatch onto the
  // article (0.568 mm); started with the armature's speed fitted, every integrator gives
  // the linear prediction's 0.61 mm.
  const ArticleScene both = tableScene("0.0005");
  const CheckReport both_check = runCheck(both);
  const CheckLine* both_predicted = travel(both_check);
  ASSERT_NE(both_predicted, nullptr);
  EXPECT_EQ(both_predicted->verdict, Verdict::Pass);
  EXPECT_NE(both_predicted->note.find("the table's program included"), std::string::npos);
  for (const char* integrator : {"cvode_bdf", "rk_merson"}) {
    ArticleScene with = both;
    with.simulation.integrator = integrator;
    const SimulationResult moved = simulate(with);
    std::printf("[shaker check] table moving, %s: predicted travel %.6g m, the run's %.6g m, closure drift %.3g m\n", integrator,
                both_predicted->demand, moved.shaker->peak_stroke_m, moved.constraint_drift_m);
    EXPECT_NEAR(both_predicted->demand, moved.shaker->peak_stroke_m, 0.005 * moved.shaker->peak_stroke_m) << integrator;  // 0.1 %
    EXPECT_LT(moved.constraint_drift_m, 1e-7) << integrator;
  }
}

}  // namespace
}  // namespace mmv
