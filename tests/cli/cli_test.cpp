// The mmvlab executable as a user runs it: exit codes, stdout/stderr discipline,
// nothing written on failure, and every shipped scene runs.

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "support/cli.hpp"

namespace {

using namespace mmv::cli_testing;


TEST_F(Cli, DefaultSceneModesTable) {
  const Result r = run("modes");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("Joints and the torque each torquer holds"), std::string::npos);
  EXPECT_NE(r.out.find("frequency_Hz"), std::string::npos);
  EXPECT_EQ(r.err, "");
}

TEST_F(Cli, DefaultSceneJsonHasSortedPositiveFrequencies) {
  const Result r = run("modes --json --modes 0");
  ASSERT_EQ(r.code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["command"], "modes");
  EXPECT_TRUE(j["equilibrium"]["converged"].get<bool>());
  const auto& modes = j["modes"];
  ASSERT_EQ(modes.size(), j["model"]["dofs"].get<std::size_t>());
  double prev = 0;
  for (const auto& m : modes) {
    ASSERT_TRUE(m["stable"].get<bool>());
    const double f = m["frequency_hz"].get<double>();
    EXPECT_GT(f, 0.0);
    EXPECT_GE(f, prev);
    prev = f;
    EXPECT_FALSE(m["shape"].empty());
  }
  EXPECT_EQ(j["equilibrium"]["joints"].size(), 3u);
}

TEST_F(Cli, SegmentsOverrideChangesTheModel) {
  const Result r = run("modes --json --segments 4");
  ASSERT_EQ(r.code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["model"]["dofs"], 16);
}

TEST_F(Cli, EmbeddedSceneIsTheShippedFile) {
  const Result r = run("scene");
  ASSERT_EQ(r.code, 0);
  EXPECT_EQ(r.out, slurp(fs::path(MMVLAB_SOURCE_DIR) / "scenes" / "mmv.yaml"));
}

// The worked example in docs/scene-format.md is the shipped scenes/two-link-demo.yaml,
// so the documented example is one that runs (next test).
TEST_F(Cli, DocumentedExampleIsTheShippedDemo) {
  const std::string doc = slurp(fs::path(MMVLAB_SOURCE_DIR) / "docs" / "scene-format.md");
  const auto begin = doc.find("```yaml\n", doc.find("## Worked example"));
  ASSERT_NE(begin, std::string::npos);
  const auto end = doc.find("```", begin + 8);
  EXPECT_EQ(doc.substr(begin + 8, end - begin - 8), slurp(fs::path(MMVLAB_SOURCE_DIR) / "scenes" / "two-link-demo.yaml"));
}

// Examples are tests: every shipped scene runs and gives a stable, converged result.
TEST_F(Cli, EveryShippedSceneRuns) {
  int count = 0;
  for (const auto& e : fs::directory_iterator(fs::path(MMVLAB_SOURCE_DIR) / "scenes")) {
    if (e.path().extension() != ".yaml") continue;
    ++count;
    const Result r = run("modes --json " + e.path().string());
    ASSERT_EQ(r.code, 0) << e.path() << ": " << r.err;
    const nlohmann::json j = nlohmann::json::parse(r.out);
    EXPECT_TRUE(j["equilibrium"]["converged"].get<bool>()) << e.path();
    for (const auto& m : j["modes"]) EXPECT_TRUE(m["stable"].get<bool>()) << e.path();
  }
  EXPECT_GE(count, 1);
}

TEST_F(Cli, HamsasModesTableAndJson) {
  const std::string scene = (fs::path(MMVLAB_SOURCE_DIR) / "scenes" / "hamsas.yaml").string();
  const Result r = run("modes " + scene);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.err, "");
  EXPECT_NE(r.out.find("Measured (LASTI, in vacuum) vs model"), std::string::npos);
  EXPECT_NE(r.out.find("effective spherical joints"), std::string::npos);
  const Result j = run("modes --json --modes 0 " + scene);
  ASSERT_EQ(j.code, 0) << j.err;
  const nlohmann::json doc = nlohmann::json::parse(j.out);
  EXPECT_EQ(doc["model"], "hamsas");
  EXPECT_EQ(doc["features"].size(), 9u);
  EXPECT_EQ(doc["modes"].size(), 60u);
  for (const auto& f : doc["features"]) EXPECT_NEAR(f["model_hz"].get<double>() / f["measured_hz"].get<double>(), 1.0, 0.05);
}

TEST_F(Cli, HamsasFrfAndRomWriteTheirFiles) {
  const std::string scene = (fs::path(MMVLAB_SOURCE_DIR) / "scenes" / "hamsas.yaml").string();
  const Result f = run("frf " + scene + " --points 80 --out " + (dir_ / "frf").string() + " --vary counterweight_mass=0,3.5");
  ASSERT_EQ(f.code, 0) << f.err;
  for (const char* name : {"transmissibility.csv", "transmissibility_horizontal.png", "transmissibility_vertical.png",
                           "transmissibility_angular.png", "transmissibility_10hz.png", "transmissibility_vary.png"})
    EXPECT_TRUE(fs::exists(dir_ / "frf" / name)) << name;
  EXPECT_NE(f.out.find("x <- ground x"), std::string::npos);
  EXPECT_NE(f.out.find("Varying counterweight_mass"), std::string::npos);
  const std::string csv = slurp(dir_ / "frf" / "transmissibility.csv");
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 81);
  const Result r = run("rom " + scene + " --band 0:80 --out " + (dir_ / "rom").string());
  ASSERT_EQ(r.code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(slurp(dir_ / "rom" / "rom.json"));
  EXPECT_EQ(j["inputs"].size(), 8u);
  EXPECT_EQ(j["outputs"].size(), 8u);
  EXPECT_LT(j["reduced_states"].get<int>(), j["full_states"].get<int>());
  EXPECT_LT(j["max_relative_frf_error"].get<double>(), 0.01);
  EXPECT_TRUE(fs::exists(dir_ / "rom" / "rom.mat"));
}

TEST_F(Cli, HamsasSceneErrorsAndCommandsThatDoNotApply) {
  const std::string scene = (fs::path(MMVLAB_SOURCE_DIR) / "scenes" / "hamsas.yaml").string();
  for (const std::string cmd : {"compare ", "converge ", "sweep-config "}) {
    const Result r = run(cmd + scene + (cmd == "sweep-config " ? " --grid joint2:0:10:10" : ""));
    EXPECT_EQ(r.code, 64) << cmd << r.err;
    EXPECT_NE(r.err.find("HAM-SAS isolator scene"), std::string::npos) << cmd << r.err;
  }
  EXPECT_EQ(run("frf " + scene + " --vary no_such_key=1").code, 64);
  // Time runs of the isolator: the scene's ground motion through the nonlinear model.
  const Result sim = run("simulate " + scene + " --duration 0.05 --json");
  ASSERT_EQ(sim.code, 0) << sim.err;
  const nlohmann::json sj = nlohmann::json::parse(sim.out);
  EXPECT_EQ(sj["command"], "simulate");
  EXPECT_NEAR(sj["duration_s"].get<double>(), 0.05, 1e-12);
  // The isolator scores its optical table and spring box; under the ground's motion
  // both move, and no torquer is involved.
  EXPECT_GT(sj["peak_displacement_m"]["optical_table"].get<double>(), 0.0) << sim.out;
  EXPECT_GT(sj["peak_displacement_m"]["spring_box"].get<double>(), 0.0) << sim.out;
  EXPECT_TRUE(sj["torques"].empty());
  EXPECT_EQ(run("frf " + scene + " --input table_x").code, 64);
  EXPECT_EQ(run("modes --segments 4 " + scene).code, 64);
  std::string text = slurp(scene);
  const std::string from = "  sb_mass: 741.4";
  const auto at = text.find(from);
  ASSERT_NE(at, std::string::npos);
  std::string bad = text;
  bad.replace(at, from.size(), "  sb_mass: -741.4");
  Result r = run("modes " + write("bad.yaml", bad).string());
  EXPECT_EQ(r.code, 65);
  EXPECT_EQ(r.out, "");
  EXPECT_NE(r.err.find("bad.yaml:"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("hamsas.sb_mass must be > 0 kg (got -741.4)"), std::string::npos) << r.err;
  bad = text;
  bad.replace(at, from.size(), "  sb_mas: 741.4");
  r = run("modes " + write("typo.yaml", bad).string());
  EXPECT_EQ(r.code, 65);
  EXPECT_NE(r.err.find("unknown key 'hamsas.sb_mas'"), std::string::npos) << r.err;
  bad = text;
  const std::string joints = "spherical_joints: stiff";
  bad.replace(bad.find(joints), joints.size(), "spherical_joints: rigid");
  r = run("modes " + write("joints.yaml", bad).string());
  EXPECT_EQ(r.code, 65);
  EXPECT_NE(r.err.find("must be stiff or ideal (got rigid)"), std::string::npos) << r.err;
}

TEST_F(Cli, BadSceneExits65WithOneLineAndNoOutput) {
  std::string text = run("scene").out;
  const std::string from = "    length: 1.52";
  const auto at = text.find(from);
  ASSERT_NE(at, std::string::npos);
  text.replace(at, from.size(), "    length: -1.52");
  const fs::path p = write("bad.yaml", text);
  const Result r = run("modes --json " + p.string());
  EXPECT_EQ(r.code, 65);
  EXPECT_EQ(r.out, "");
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_EQ(r.err.rfind(p.string() + ":", 0), 0u) << r.err;
  EXPECT_NE(r.err.find("links[1].length must be > 0 m (got -1.52)"), std::string::npos) << r.err;
}

TEST_F(Cli, MalformedYamlExits65) {
  const fs::path p = write("broken.yaml", "links: [\n  - a\n");
  const Result r = run("modes " + p.string());
  EXPECT_EQ(r.code, 65);
  EXPECT_EQ(r.out, "");
  EXPECT_NE(r.err.find("malformed YAML"), std::string::npos) << r.err;
}

TEST_F(Cli, MissingSceneExits66) {
  const Result r = run("modes " + (dir_ / "nope.yaml").string());
  EXPECT_EQ(r.code, 66);
  EXPECT_EQ(r.out, "");
  EXPECT_NE(r.err.find("cannot open scene file"), std::string::npos) << r.err;
}

TEST_F(Cli, DirectoryAsSceneExits66) {
  const Result r = run("modes " + dir_.string());
  EXPECT_EQ(r.code, 66);
  EXPECT_EQ(r.out, "");
  EXPECT_NE(r.err.find("is a directory"), std::string::npos) << r.err;
}

TEST_F(Cli, UsageErrorExits64) {
  EXPECT_EQ(run("modes --segments 0").code, 64);
  EXPECT_EQ(run("frobnicate").code, 64);
  EXPECT_EQ(run("").code, 64);
}

TEST_F(Cli, NumericalFailureExits1AndNamesIt) {
  // A free pendulum released exactly horizontal: singular tangent stiffness.
  const fs::path p = write("singular.yaml", singularPendulumScene("rigid"));
  const Result r = run("modes --json " + p.string());
  EXPECT_EQ(r.code, 1);
  EXPECT_EQ(r.out, "");
  EXPECT_NE(r.err.find("numerical failure: static equilibrium failed: tangent stiffness is singular"),
            std::string::npos)
      << r.err;
}

TEST_F(Cli, ConvergeTable) {
  const Result r = run("converge --max-segments 8 --modes 3");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("richardson"), std::string::npos);
  const Result j = run("converge --json --max-segments 8 --modes 3");
  ASSERT_EQ(j.code, 0) << j.err;
  const nlohmann::json doc = nlohmann::json::parse(j.out);
  EXPECT_EQ(doc["runs"].size(), 4u);
  EXPECT_EQ(doc["modes"].size(), 3u);
}


TEST_F(Cli, CompareReportsTable2Table3AndSynthesis) {
  const Result r = run("compare --json --modes 6");
  ASSERT_EQ(r.code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["command"], "compare");
  ASSERT_EQ(j["component_modes"].size(), 4u);
  // Link 1 with the torquer tip mass at 16 segments: the report's 1.656 Hz within 0.1 %.
  EXPECT_NEAR(j["component_modes"][0]["modes"][0]["frequency_hz"].get<double>() / 1.656, 1.0, 1e-3);
  EXPECT_EQ(j["system_modes"].size(), 6u);
  EXPECT_EQ(j["synthesis"]["assumed_modes"]["modes"].size(), 6u);
  EXPECT_EQ(j["tip_mass_rules"].size(), 3u);
  // An explicit tip mass is used as given.
  const Result e = run("compare --json --modes 2 --tip-mass 4.67,0.01");
  ASSERT_EQ(e.code, 0) << e.err;
  const nlohmann::json ej = nlohmann::json::parse(e.out);
  EXPECT_EQ(ej["component_tip_mass_rule"], "explicit");
  EXPECT_DOUBLE_EQ(ej["component_modes"][0]["tip_mass_kg"].get<double>(), 4.67);
  EXPECT_DOUBLE_EQ(ej["component_modes"][0]["tip_rotary_inertia_kg_m2"].get<double>(), 0.01);
  const Result t = run("compare --modes 4");
  ASSERT_EQ(t.code, 0) << t.err;
  EXPECT_NE(t.out.find("Table 2: component modes"), std::string::npos);
  EXPECT_NE(t.out.find("Table 3: system modes"), std::string::npos);
}

TEST_F(Cli, CompareWritesItsFilesOnceAndRefusesToOverwrite) {
  const fs::path out = dir_ / "cmp";
  const Result r = run("compare --modes 4 --out " + out.string());
  ASSERT_EQ(r.code, 0) << r.err;
  for (const char* f : {"compare.md", "compare.json", "component_modes.csv", "system_modes.csv", "synthesis.csv",
                        "mac_assumed_modes.csv", "mac_craig_bampton.csv"})
    EXPECT_TRUE(fs::exists(out / f)) << f;
  EXPECT_TRUE(isPng(out / "mac_assumed_modes.png"));
  EXPECT_TRUE(isPng(out / "mac_craig_bampton.png"));
  EXPECT_EQ(slurp(out / "system_modes.csv").rfind("mode,frequency_hz,", 0), 0u);
  // A user's file of the same name is not replaced without --force, and nothing else is written.
  std::ofstream(out / "compare.md") << "my notes";
  fs::remove(out / "synthesis.csv");
  const Result again = run("compare --modes 4 --out " + out.string());
  EXPECT_EQ(again.code, 73);
  EXPECT_EQ(again.out, "");
  EXPECT_EQ(slurp(out / "compare.md"), "my notes");
  EXPECT_FALSE(fs::exists(out / "synthesis.csv"));
  for (const auto& e : fs::directory_iterator(dir_))
    EXPECT_EQ(e.path().filename().string().find(".mmvlab-staging"), std::string::npos) << "staging left behind";
  EXPECT_EQ(run("compare --modes 4 --force --out " + out.string()).code, 0);
  EXPECT_NE(slurp(out / "compare.md"), "my notes");
}

TEST_F(Cli, CompareBadArguments) {
  const Result closed = run("compare --topology open,closed");  // the default scene has no closures
  EXPECT_EQ(closed.code, 64);  // the command line asked for a closed tree
  EXPECT_NE(closed.err.find("has no closures"), std::string::npos) << closed.err;
  EXPECT_EQ(run("compare --bc clamped-clamped").code, 64);
  EXPECT_EQ(run("compare --tip-mass everything").code, 64);
  EXPECT_EQ(run("compare --tip-mass -1").code, 64);
  EXPECT_EQ(run("compare --tip-mass 2,x").code, 64);
  EXPECT_EQ(run("compare --topology sideways").code, 64);
}

TEST_F(Cli, CompareOpenAgainstClosed) {
  const Result r = run("compare " + (fs::path(MMVLAB_SOURCE_DIR) / "scenes" / "mmv-closed.yaml").string() +
                       " --modes 4 --topology open,closed --json");
  ASSERT_EQ(r.code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["topologies"].size(), 2u);
  // Pinning a branch tip stiffens the article: the closed tree's first mode is higher.
  EXPECT_GT(j["topologies"][1]["system_modes"][0]["frequency_hz"].get<double>(),
            j["topologies"][0]["system_modes"][0]["frequency_hz"].get<double>());
}

TEST_F(Cli, SweepConfigWritesCsvAndPlots) {
  const fs::path out = dir_ / "sweep";
  const Result r = run("sweep-config --grid joint2:-20:20:10 --modes 4 --out " + out.string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("Per track"), std::string::npos);
  const std::string csv = slurp(out / "sweep.csv");
  EXPECT_EQ(csv.rfind("joint2_deg,point_kind,track,sorted_mode,frequency_hz", 0), 0u);
  EXPECT_EQ(csv.find(",refined,"), std::string::npos);  // the open tree is followed at the grid's step
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 1 + 5 * 4);  // header + 5 angles x 4 tracks
  EXPECT_TRUE(isPng(out / "frequencies.png"));
  EXPECT_TRUE(isPng(out / "synthesis_error.png"));
  const Result two = run("sweep-config --grid joint2:-10:10:10 --grid joint1:20:40:20 --modes 3 --json");
  ASSERT_EQ(two.code, 0) << two.err;
  EXPECT_EQ(nlohmann::json::parse(two.out)["points"].size(), 6u);
}

TEST_F(Cli, SweepConfigBadGrid) {
  EXPECT_EQ(run("sweep-config --grid joint9:0:10:5").code, 64);
  EXPECT_EQ(run("sweep-config --grid joint2:0:10").code, 64);
  EXPECT_EQ(run("sweep-config --grid joint2:10:0:5").code, 64);
  EXPECT_EQ(run("sweep-config --grid joint2:0:10:0").code, 64);
  EXPECT_EQ(run("sweep-config").code, 64);
}

TEST_F(Cli, FrfWritesCsvBodeAndUff) {
  const fs::path out = dir_ / "frf";
  const Result r = run("frf --segments 4 --input table_x --output link3a.tip:x --points 50 --rom-modes 6 --out " + out.string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("statically residualized"), std::string::npos);
  const std::string csv = slurp(out / "frf_link3a.tip_x__table_x.csv");
  EXPECT_EQ(csv.rfind("frequency_hz,magnitude_db,phase_deg,", 0), 0u);
  // 50 log-spaced points and 18 more around each of the 6 kept modes' half-power bands
  // (fewer where a mode's band leaves the range or points coincide).
  const auto lines = std::count(csv.begin(), csv.end(), '\n');
  EXPECT_GT(lines, 51 + 5 * 17);
  EXPECT_LE(lines, 51 + 6 * 18);
  EXPECT_TRUE(isPng(out / "bode_link3a.tip_x__table_x.png"));
  // The UFF file holds the same transmissibility (type 5) as the CSV.
  const std::string uff = slurp(out / "frf.uff");
  EXPECT_NE(uff.find("    -1\n    58"), std::string::npos);
  EXPECT_NE(uff.find("    -1\n    55"), std::string::npos);
  const auto rec6 = uff.find("\n    5         1");
  EXPECT_NE(rec6, std::string::npos) << "58 record 6 with function type 5 (transmissibility)";
  // Low-frequency transmissibility is 1 (0 dB): the first CSV row.
  std::istringstream rows(csv);
  std::string header, first;
  std::getline(rows, header);
  std::getline(rows, first);
  EXPECT_NEAR(std::stod(first.substr(first.find(',') + 1)), 0.0, 0.01);
}

TEST_F(Cli, RomWritesMatAndJson) {
  const fs::path out = dir_ / "rom";
  const Result r = run("rom --segments 4 --rom-modes 4 --out " + out.string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(fs::file_size(out / "rom.mat") > 100);
  EXPECT_TRUE(fs::file_size(out / "full.mat") > 100);
  const nlohmann::json j = nlohmann::json::parse(slurp(out / "rom.json"));
  EXPECT_EQ(j["reduced_states"], 8);
  EXPECT_EQ(j["full_states"], 32);
  EXPECT_TRUE(j["residualized"].get<bool>());
  EXPECT_EQ(run("rom --segments 4").code, 64);  // --out is required
}

TEST_F(Cli, LinearModelBadSpecs) {
  // Command-line names are checked against the scene before any model is built (64).
  const Result locked = run("frf --input torque:joint2");  // joint2 is locked: no DOF for a torque
  EXPECT_EQ(locked.code, 64);
  EXPECT_NE(locked.err.find("joint 'joint2' is locked"), std::string::npos) << locked.err;
  EXPECT_EQ(run("frf --input torque:joint9").code, 64);
  EXPECT_EQ(run("frf --input force:link9.tip:x").code, 64);
  EXPECT_EQ(run("frf --input shaker").code, 64);
  EXPECT_EQ(run("frf --output link1.tip:z").code, 64);
  const Result unknown = run("frf --output link9.tip:x");
  EXPECT_EQ(unknown.code, 64);
  EXPECT_NE(unknown.err.find("--output link9.tip:x: unknown point 'link9.tip'"), std::string::npos) << unknown.err;
  EXPECT_EQ(run("frf --from 10 --to 1").code, 64);
  EXPECT_EQ(run("frf --band 5:1").code, 64);
}

TEST_F(Cli, SimulateSlewScene) {
  const fs::path out = dir_ / "slew";
  const Result r = run("simulate " + (fs::path(MMVLAB_SOURCE_DIR) / "scenes" / "mmv-slew.yaml").string() +
                       " --duration 2 --out " + out.string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("Torques the torquers must give"), std::string::npos);
  const std::string csv = slurp(out / "history.csv");
  EXPECT_EQ(csv.rfind("time_s,table_x_m,table_force_n,gimbal_yaw_angle_deg,gimbal_yaw_torque_n_m,gimbal_pitch_angle_deg,", 0), 0u);
  EXPECT_NE(csv.find(",joint1_angle_deg,joint1_torque_n_m,"), std::string::npos);
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 1 + 1001);  // header + 2 s at 500 Hz + t = 0
  EXPECT_EQ(csv.find("nan"), std::string::npos);
  const nlohmann::json j = nlohmann::json::parse(slurp(out / "summary.json"));
  EXPECT_EQ(j["integrator"], "cvode_bdf");  // the cheapest within 1e-4 m (docs/accuracy.md)
  EXPECT_NEAR(j["table"]["carried_weight_n"].get<double>(), 956.4, 0.1);  // article + 3 x 10 kg rings
  EXPECT_GT(j["table"]["peak_force_n"].get<double>(), 0.0);
  ASSERT_EQ(j["torques"].size(), 6u);  // gimbal yaw, pitch, roll; joints 1 to 3
  EXPECT_EQ(j["torques"][1]["joint"], "gimbal.pitch");
  EXPECT_EQ(j["torques"][3]["joint"], "joint1");
  EXPECT_GT(j["torques"][3]["peak_torque_n_m"].get<double>(), 90.0);  // at least the static holding torque
  // The pitch axis and joint 1 share the point and the axis: the same moment.
  EXPECT_NEAR(j["torques"][1]["peak_torque_n_m"].get<double>(), j["torques"][3]["peak_torque_n_m"].get<double>(), 1e-6);
  EXPECT_GT(j["realizations"].get<int>(), 0);
}

TEST_F(Cli, SimulateBadInput) {
  // A sine beyond the table's +-15 cm stroke is refused before anything runs.
  std::string text = slurp(fs::path(MMVLAB_SOURCE_DIR) / "scenes" / "mmv-table.yaml");
  const std::string from = "motion: {type: sine, amplitude: 0.001, frequency_hz: 2.0}";
  ASSERT_NE(text.find(from), std::string::npos);
  text.replace(text.find(from), from.size(), "motion: {type: sine, amplitude: 0.2, frequency_hz: 2.0}");
  const fs::path p = write("stroke.yaml", text);
  const Result r = run("simulate --duration 0.1 " + p.string());
  EXPECT_EQ(r.code, 65);
  EXPECT_NE(r.err.find("exceeds the table's +-0.15 m stroke"), std::string::npos) << r.err;
  EXPECT_EQ(r.out, "");
  // Above the table's bandwidth: a warning, and the run goes on.
  text.replace(text.find("amplitude: 0.2, frequency_hz: 2.0"), 33, "amplitude: 0.001, frequency_hz: 20");
  const Result w = run("simulate --duration 0.05 --segments 2 " + write("fast.yaml", text).string());
  EXPECT_EQ(w.code, 0) << w.err;
  EXPECT_NE(w.err.find("above the table's 10 Hz bandwidth"), std::string::npos) << w.err;
  // An unknown integrator is a command-line mistake (64) named with the known ones,
  // or a scene mistake (65) at its line and column, found before any model is built.
  const Result li = run("simulate --integrator rk45 --duration 0.1");
  EXPECT_EQ(li.code, 64);
  EXPECT_NE(li.err.find("unknown integrator 'rk45'"), std::string::npos) << li.err;
  EXPECT_NE(li.err.find("cvode_bdf"), std::string::npos) << li.err;
  EXPECT_NE(li.err.find("ida"), std::string::npos) << li.err;
  std::string named = slurp(fs::path(MMVLAB_SOURCE_DIR) / "scenes" / "mmv-slew.yaml");
  const std::string integ = "integrator: cvode_bdf";
  ASSERT_NE(named.find(integ), std::string::npos);
  named.replace(named.find(integ), integ.size(), "integrator: cpode");
  const Result si = run("simulate --duration 0.1 " + write("integ.yaml", named).string());
  EXPECT_EQ(si.code, 65);
  EXPECT_NE(si.err.find("integ.yaml:"), std::string::npos) << si.err;
  EXPECT_NE(si.err.find("simulation.integrator: unknown integrator 'cpode' (did you mean 'cpodes'?)"), std::string::npos)
      << si.err;
  // Simbody aborts on an accuracy outside (0, 1); we refuse it first, on the command
  // line (usage) and in a scene (data, with its line).
  const Result a = run("simulate --accuracy 1 --duration 0.1");
  EXPECT_EQ(a.code, 64);
  EXPECT_NE(a.err.find("--accuracy: must be a finite number above 0 and below 1 (got 1)"), std::string::npos) << a.err;
  std::string loose = slurp(fs::path(MMVLAB_SOURCE_DIR) / "scenes" / "mmv-slew.yaml");
  const std::string acc = "accuracy: 1.0e-6";
  ASSERT_NE(loose.find(acc), std::string::npos);
  loose.replace(loose.find(acc), acc.size(), "accuracy: 2");
  const Result b = run("simulate --duration 0.1 " + write("loose.yaml", loose).string());
  EXPECT_EQ(b.code, 65);
  EXPECT_NE(b.err.find("simulation.accuracy must be below 1 (a relative accuracy; got 2)"), std::string::npos) << b.err;
  // An absolute tolerance for one of Simbody's integrators: refused by the reader, at the patch.
  const Result at =
      run("simulate --duration 0.1 --set simulation.integrator=cpodes --set simulation.absolute_tolerance=1e-9");
  EXPECT_EQ(at.code, 65) << at.err;
  EXPECT_NE(at.err.find("--set simulation.absolute_tolerance=1e-9: simulation.absolute_tolerance applies to the SUNDIALS"),
            std::string::npos) << at.err;
  // Gimbal rings of 200 kg put the table over its 2.3 kN payload: a warning.
  std::string heavy = slurp(fs::path(MMVLAB_SOURCE_DIR) / "scenes" / "mmv-slew.yaml");
  const std::string ring = "ring_mass: 10 ";
  ASSERT_NE(heavy.find(ring), std::string::npos);
  heavy.replace(heavy.find(ring), ring.size(), "ring_mass: 200 ");
  const Result h = run("simulate --duration 0.05 --segments 2 " + write("heavy.yaml", heavy).string());
  EXPECT_EQ(h.code, 0) << h.err;
  EXPECT_NE(h.out.find("warning: the table carries 6546 N, above its 2300 N payload"), std::string::npos) << h.out;
}

TEST_F(Cli, TradeWritesItsStudy) {
  const fs::path out = dir_ / "trade";
  const Result r = run("trade " + (fs::path(MMVLAB_SOURCE_DIR) / "scenes" / "mmv-slew.yaml").string() +
                       " --segments 2 --duration 0.4 --integrators rk_merson,cvode_bdf --accuracies 1e-3,1e-5 "
                       "--segment-ladder 1 --modes-ladder 1 --modes-accuracies 1e-5 --target-error 1e-3 --points link3a.tip --out " +
                       out.string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("Cheapest run within"), std::string::npos);
  EXPECT_NE(r.out.find("Error scored at: link3a.tip\n"), std::string::npos) << r.out;
  const std::string csv = slurp(out / "trade.csv");
  EXPECT_EQ(csv.rfind("integrator,accuracy,segments,modes,ok,status,tip_error_m,cpu_s,evaluations,pareto,energy_balance_ok,failure\n", 0), 0u);
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 1 + 6);  // 4 + the modal run + the segment ladder
  EXPECT_TRUE(isPng(out / "trade.png"));
  const nlohmann::json j = nlohmann::json::parse(slurp(out / "trade.json"));
  EXPECT_EQ(j["runs"].size(), 6u);
  EXPECT_EQ(j["runs"][4]["modes"], 1);
  EXPECT_NE(r.out.find("modes: per link, in modal coordinates"), std::string::npos) << r.out;
  EXPECT_EQ(j["points"], nlohmann::json::array({"link3a.tip"}));
  // Command-line mistakes (64), refused before anything runs or is written.
  const Result bad = run("trade --duration 0.1 --points tip9 --out " + (dir_ / "bad").string());
  EXPECT_EQ(bad.code, 64);
  EXPECT_NE(bad.err.find("--points: 'tip9' is not a link tip of the scene"), std::string::npos) << bad.err;
  EXPECT_FALSE(fs::exists(dir_ / "bad"));
  const Result bi = run("trade --duration 0.1 --integrators rk_merson,rk45");
  EXPECT_EQ(bi.code, 64);
  EXPECT_NE(bi.err.find("unknown integrator 'rk45'"), std::string::npos) << bi.err;
}

}  // namespace
