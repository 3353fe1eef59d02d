// The spatial article end to end (docs/spatial.md): `modes --set model=spatial` lists the
// default article's mode families and its planarity report; commands that are still
// planar refuse the key, naming it.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <string>
#include <vector>

#include "sim/io/run_dir.hpp"
#include "sim/io/uff_read.hpp"
#include "support/cli.hpp"

namespace mmv::cli_testing {
namespace {

TEST_F(Cli, ModesOnTheSpatialArticleClassifiesModesAndReportsPlanarity) {
  const Result r = run("modes --set model=spatial --modes 14");
  ASSERT_EQ(r.code, 0) << r.err;
  for (const char* text : {"family", "out-of-plane", "in-plane", "Planarity: modes in 0.1-50 Hz", "nearest_in_plane",
                           "decoupled", "dz_mm"})
    EXPECT_NE(r.out.find(text), std::string::npos) << text << "\n" << r.out;
  const Result j = run("modes --set model=spatial --modes 14 --json --no-error-estimate");
  ASSERT_EQ(j.code, 0) << j.err;
  const nlohmann::json doc = nlohmann::json::parse(j.out);
  EXPECT_EQ(doc["model"]["kind"], "spatial");
  EXPECT_EQ(doc["modes"][1]["family"], "out-of-plane");  // link 1 out of the plane, below link 3's pair
  const auto& p = doc.at("planarity");
  EXPECT_TRUE(p["covers_band"].get<bool>());
  EXPECT_EQ(p["in_plane_modes_in_band"], 8);  // the planar model's eight modes below 50 Hz
  EXPECT_GE(p["other_modes_in_band"].size(), 4u);
  for (const auto& resp : p["responses"]) EXPECT_TRUE(resp["decoupled"].get<bool>()) << resp;
  EXPECT_TRUE(doc["modes"][1]["shape"][0].contains("uz"));
  // A model per link: link 3 spatial, links 1 and 2 planar, said in the text and the JSON.
  const Result mixed = run("modes --set links.link3.model=spatial --modes 4 --json --no-error-estimate");
  ASSERT_EQ(mixed.code, 0) << mixed.err;
  const nlohmann::json m = nlohmann::json::parse(mixed.out);
  EXPECT_EQ(m["model"]["kind"], "spatial");
  std::string models;
  for (const auto& l : m["model"]["links"]) models += l["model"].get<std::string>() + " ";
  EXPECT_EQ(models, "planar planar spatial spatial ");
  EXPECT_NE(run("modes --set links.link3.model=spatial --modes 4").out.find("link1 16 (planar) link2 16 (planar) link3a 16 "),
            std::string::npos);
  // The planar default reports no families and no planarity section.
  const nlohmann::json planar = nlohmann::json::parse(run("modes --json --no-error-estimate").out);
  EXPECT_EQ(planar["model"]["kind"], "planar");
  EXPECT_FALSE(planar.contains("planarity"));
  EXPECT_FALSE(planar["modes"][0].contains("family"));
}

// --target-error on the spatial article. simulate: the chosen run's link 3a tip (x, y, z)
// within the target of a tight reference run computed here. frf: the segments chosen
// hold every mode up to --to within the frequency error the FRF target asks of them
// (half the target times the damping ratio) of a 64-segment solution.
TEST_F(Cli, TargetErrorMeetsItsTargetOnTheSpatialArticle) {
  const std::string sets = " --segments 2 --set model=spatial --set 'base.gimbal.roll.slew={to_deg: 10}' --set simulation.duration=0.3";
  const Result chosen = run("simulate" + sets + " --target-error 1e-3 --points link3a.tip --time-budget 60 --out " + (dir_ / "t").string());
  ASSERT_EQ(chosen.code, 0) << chosen.err;
  const Result tight = run("simulate" + sets + " --set simulation.integrator=cvode_bdf --set simulation.accuracy=1e-10 --out " +
                           (dir_ / "ref").string());
  ASSERT_EQ(tight.code, 0) << tight.err;
  const CsvTable a = parseNumericCsv(slurp(dir_ / "t" / "history.csv"), "t"), b = parseNumericCsv(slurp(dir_ / "ref" / "history.csv"), "ref");
  ASSERT_EQ(a.rows.size(), b.rows.size());
  double worst = 0;
  for (std::size_t k = 0; k < a.rows.size(); ++k) {
    double d2 = 0;
    for (const char* c : {"link3a_tip_x_m", "link3a_tip_y_m", "link3a_tip_z_m"})
      d2 += std::pow(a.rows[k][a.column(c)] - b.rows[k][b.column(c)], 2);
    worst = std::max(worst, std::sqrt(d2));
  }
  EXPECT_LT(worst, 1e-3);

  // 10 % of each peak: every frequency below 10 Hz within 0.05 x 1 % damping = 5e-4.
  const Result frf = run("frf --set model=spatial --target-error 0.1 --input table_z --output link3a.tip:z --to 10 --json");
  ASSERT_EQ(frf.code, 0) << frf.err;
  const int segments = nlohmann::json::parse(frf.out)["target_error"]["segments"];
  EXPECT_LT(segments, 64);
  const auto modes = [&](int n) {
    return nlohmann::json::parse(run("modes --set model=spatial --modes 12 --no-error-estimate --json --segments " + std::to_string(n)).out)["modes"];
  };
  const auto got = modes(segments), fine = modes(64);
  for (std::size_t i = 0; i < fine.size(); ++i) {
    const double f = fine[i]["frequency_hz"];
    if (f > 10) break;
    EXPECT_NEAR(got[i]["frequency_hz"].get<double>(), f, 5e-4 * f) << "mode " << i + 1;
  }
}

// A time run of the spatial article: a gimbal roll slew swings it out of its plane; the
// tips get z columns; the instruments read every axis; the run is replayed in 3-D.
TEST_F(Cli, SimulateRunsTheSpatialArticle) {
  const std::string sets =
      " --segments 2 --set model=spatial --set 'damping={hinge_beta: 0.002}' --set 'base.gimbal.roll.slew={to_deg: 20}'"
      " --set simulation.duration=0.5 --set simulation.integrator=cvode_bdf";
  const Result r = run("simulate" + sets + " --json");
  ASSERT_EQ(r.code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_TRUE(j.dump().find("gimbal.roll") != std::string::npos);
  const Result out = run("simulate" + sets + " --out " + (dir_ / "run").string());
  ASSERT_EQ(out.code, 0) << out.err;
  const std::string csv = slurp(dir_ / "run" / "history.csv");
  EXPECT_NE(csv.find("link3b_tip_z_m"), std::string::npos) << csv.substr(0, 400);
  const std::string slew = (fs::path(MMVLAB_SOURCE_DIR) / "scenes" / "mmv-slew.yaml").string();
  // The slew scene's instruments, and a triaxial accelerometer and a gyro about the
  // link's axis, on the spatial model: every sensor gets its column.
  const std::string triaxial =
      " --set 'sensors=[{name: ax, type: accelerometer, point: link3a.tip}, {name: ay, type: accelerometer, point: "
      "link3a.tip, axis: transverse}, {name: az, type: accelerometer, point: link3a.tip, axis: normal}, {name: twist, "
      "type: rate_gyro, point: link1@0.5, axis: axial}]'";
  const Result sensors = run("simulate " + slew + " --set model=spatial --set simulation.duration=0.2" + triaxial +
                             " --out " + (dir_ / "tri").string());
  ASSERT_EQ(sensors.code, 0) << sensors.err;
  const std::string header = slurp(dir_ / "tri" / "history.csv").substr(0, 2000);
  for (const char* c : {"ax_m_per_s2", "ay_m_per_s2", "az_m_per_s2", "twist_rad_per_s"})
    EXPECT_NE(header.find(c), std::string::npos) << c;
  // The planar model refuses an axis out of its plane, naming the key.
  const Result planar = run("simulate " + slew + triaxial);
  EXPECT_EQ(planar.code, 65) << planar.err;
  EXPECT_NE(planar.err.find("sensors[2].axis: an accelerometer along the normal axis reads motion out of the plane: it "
                            "needs model: spatial"),
            std::string::npos)
      << planar.err;
  // A spatial run directory is replayed in three dimensions (iso by default).
  const fs::path still = dir_ / "still.png";
  const Result replay = run("render --history " + (dir_ / "run").string() + " --at 0.5 --out " + still.string());
  ASSERT_EQ(replay.code, 0) << replay.err;
  EXPECT_TRUE(isPng(still));
  ASSERT_EQ(run("render --history " + (dir_ / "run").string() + " --at 0.5 --view iso --out " + (dir_ / "iso.png").string()).code, 0);
  EXPECT_EQ(slurp(still), slurp(dir_ / "iso.png"));
}

// frf on the spatial article takes out-of-plane inputs and outputs (table_z, POINT:z).
// The symmetric article's in-plane pair is the planar model's; the in-plane to
// out-of-plane pairs are zero (round-off, counted as no error); the out-of-plane pair
// peaks at link 3's out-of-plane modes (3.0-3.5 Hz). The planar model refuses z.
TEST_F(Cli, FrfOnTheSpatialArticleHasOutOfPlaneInputsAndOutputs) {
  const std::string io = " --input table_x --input table_z --output link3a.tip:x --output link3a.tip:z --json";
  const Result r = run("frf --set model=spatial" + io);
  ASSERT_EQ(r.code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  const Result p = run("frf --input table_x --output link3a.tip:x --json");
  ASSERT_EQ(p.code, 0) << p.err;
  const double planar_db = nlohmann::json::parse(p.out)["pairs"][0]["peak_db"].get<double>();
  ASSERT_EQ(j["pairs"].size(), 4u);  // (x, x), (x, z), (z, x), (z, z): outputs by inputs
  EXPECT_NEAR(j["pairs"][0]["peak_db"].get<double>(), planar_db, 1e-6);
  EXPECT_TRUE(j["pairs"][1]["zero_pair"].get<bool>());
  EXPECT_TRUE(j["pairs"][2]["zero_pair"].get<bool>());
  EXPECT_FALSE(j["pairs"][3]["zero_pair"].get<bool>());
  EXPECT_GT(j["pairs"][3]["peak_hz"].get<double>(), 3.0);
  EXPECT_LT(j["pairs"][3]["peak_hz"].get<double>(), 3.5);
  // The modal UFF it writes carries the out-of-plane translations: mode 2 (link 1 out of
  // the plane) moves along z only, mode 1 in the plane only.
  ASSERT_EQ(run("frf --set model=spatial --input table_z --output link3a.tip:z --out " + (dir_ / "f").string()).code, 0);
  const uff::File file = uff::read(slurp(dir_ / "f" / "frf.uff"));
  ASSERT_GE(file.modes.size(), 2u);
  const auto largest = [&](int mode, int axis) {
    double m = 0;
    for (const auto& t : file.modes[mode].translations) m = std::max(m, std::abs(t[axis]));
    return m;
  };
  EXPECT_LT(largest(0, 2), 1e-9 * largest(0, 1));
  EXPECT_LT(std::max(largest(1, 0), largest(1, 1)), 1e-9 * largest(1, 2));
  const Result planar_z = run("frf --output link3a.tip:z");
  EXPECT_EQ(planar_z.code, 64);
  EXPECT_NE(planar_z.err.find("z is out of the plane"), std::string::npos) << planar_z.err;
}

// Rotations in and out of frf on the spatial article: a moment about x at link 3a's tip
// and its rotations; the UFF names them (directions 4-6, the moment as an excitation
// force of N*m, rotations without a length), carries 6 DOF per node in its mode shapes
// (mode 1 in the plane turns about z only, mode 2 out of the plane about x and y only),
// and correlate reads the file back to the same functions. The planar model refuses a
// rotation out of its plane and takes rz.
TEST_F(Cli, RotationalInputsAndOutputsOnTheSpatialArticle) {
  const std::string out = (dir_ / "r").string();
  const Result r = run("frf --set model=spatial --input moment:link3a.tip:rx --output link3a.tip:rx:disp --output "
                       "link3a.tip:ry --output link3a@0.5+0m+0.002m:z --out " + out);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("link3a.tip:rx:disp      rad      moment:link3a.tip:rx  N*m"), std::string::npos) << r.out;
  const uff::File file = uff::read(slurp(dir_ / "r" / "frf.uff"));
  ASSERT_EQ(file.functions.size(), 3u);
  EXPECT_EQ(file.functions[0].response_direction, 4);
  EXPECT_EQ(file.functions[0].reference_direction, 4);
  EXPECT_EQ(file.functions[0].denominator_type, 13);
  EXPECT_EQ(file.functions[0].ordinate_units, "rad");
  EXPECT_EQ(file.functions[1].response_direction, 5);
  EXPECT_EQ(file.functions[1].ordinate_units, "rad/s^2");
  ASSERT_GE(file.modes.size(), 2u);
  const auto largest = [&](int mode, int axis) {
    double m = 0;
    for (const auto& w : file.modes[mode].rotations) m = std::max(m, std::abs(w[axis]));
    return m;
  };
  ASSERT_FALSE(file.modes[0].rotations.empty());
  EXPECT_GT(largest(0, 2), 0.0);
  EXPECT_LT(std::max(largest(0, 0), largest(0, 1)), 1e-9 * largest(0, 2));
  EXPECT_LT(largest(1, 2), 1e-9 * std::max(largest(1, 0), largest(1, 1)));
  const Result c = run("correlate --set model=spatial --measured " + out + "/frf.uff --modes 8 --json");
  ASSERT_EQ(c.code, 0) << c.err;
  const nlohmann::json doc = nlohmann::json::parse(c.out);
  int matched = 0;
  for (const auto& f : doc["frfs"])
    if (f.contains("frac")) matched += f["frac"].get<double>() > 0.999999;
  EXPECT_EQ(matched, 3) << c.out;
  const Result planar = run("frf --output link3a.tip:ry");
  EXPECT_EQ(planar.code, 64);
  EXPECT_NE(planar.err.find("ry is out of the plane"), std::string::npos) << planar.err;
  EXPECT_EQ(run("frf --input moment:link1.tip:rz --output link1.tip:rz --out " + (dir_ / "p").string()).code, 0);
  const Result wrong = run("frf --input moment:link1.tip:z");
  EXPECT_EQ(wrong.code, 64);
  EXPECT_NE(wrong.err.find("axis must be rx, ry or rz (got z)"), std::string::npos) << wrong.err;
}

TEST_F(Cli, ConvergeRunsOnTheSpatialArticle) {
  const Result r = run("converge --set model=spatial --max-segments 8 --modes 6 --json");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out)["modes"].size(), 6u);
}

// The closed tree on the spatial model: the fixture's pin holds link 3a's tip out of the
// plane too, and reports the force it takes along z (none: the symmetric article loads
// the fixture in its plane).
TEST_F(Cli, TheClosedTreeRunsOnTheSpatialModel) {
  const std::string scene = (fs::path(MMVLAB_SOURCE_DIR) / "scenes" / "mmv-closed.yaml").string();
  const Result r = run("modes " + scene + " --set model=spatial --json --no-error-estimate");
  ASSERT_EQ(r.code, 0) << r.err;
  const nlohmann::json doc = nlohmann::json::parse(r.out);
  const auto& c = doc["equilibrium"]["closures"].at(0);
  EXPECT_EQ(c["name"], "fixture");
  EXPECT_NEAR(c["force_z_n"].get<double>(), 0.0, 1e-9);
  EXPECT_GT(std::abs(c["force_x_n"].get<double>()), 1.0);
  const Result text = run("modes " + scene + " --set model=spatial --no-error-estimate");
  EXPECT_NE(text.out.find("Fz_N"), std::string::npos) << text.out;
}

// compare on the spatial article: every component mode and system mode carries its
// family in text, JSON and CSV; the planar comparison has no family anywhere.
TEST_F(Cli, CompareRunsOnTheSpatialArticleWithFamilies) {
  const Result r = run("compare --set model=spatial --component-modes 8 --json");
  ASSERT_EQ(r.code, 0) << r.err;
  const nlohmann::json doc = nlohmann::json::parse(r.out);
  EXPECT_EQ(doc["model"], "spatial");
  std::vector<std::string> link1;
  for (const auto& m : doc["component_modes"][0]["modes"]) link1.push_back(m["family"]);
  EXPECT_NE(std::find(link1.begin(), link1.end(), "torsion"), link1.end());
  EXPECT_EQ(doc["system_modes"][1]["family"], "out-of-plane");
  EXPECT_EQ(doc["synthesis"]["craig_bampton"]["modes"][1]["family"], "out-of-plane");
  const Result text = run("compare --set model=spatial --out " + (dir_ / "cmp").string());
  ASSERT_EQ(text.code, 0) << text.err;
  EXPECT_NE(text.out.find("Spatial model: families in (in-plane), out (out-of-plane)"), std::string::npos) << text.out;
  const std::string csv = slurp(dir_ / "cmp" / "component_modes.csv");
  EXPECT_EQ(csv.substr(0, csv.find('\n')), "link,boundary_condition,tip_mass_rule,tip_mass_kg,mass_ratio,mode,frequency_hz,closed_form_hz,family");
  const nlohmann::json planar = nlohmann::json::parse(run("compare --json").out);
  EXPECT_EQ(planar["model"], "planar");
  EXPECT_FALSE(planar["system_modes"][0].contains("family"));
}

// check on the spatial article adds its planarity group (docs/planning.md).
TEST_F(Cli, CheckOnTheSpatialArticleJudgesPlanarity) {
  const std::string table = (fs::path(MMVLAB_SOURCE_DIR) / "scenes" / "mmv-table.yaml").string();
  const Result r = run("check " + table + " --set model=spatial --json");
  ASSERT_EQ(r.code, 0) << r.err;
  const nlohmann::json doc = nlohmann::json::parse(r.out);
  std::vector<std::string> ids;
  for (const auto& l : doc["lines"]) ids.push_back(l["id"]);
  for (const char* id : {"planarity.modes", "planarity.mode4.separation", "planarity.base x"})
    EXPECT_NE(std::find(ids.begin(), ids.end(), id), ids.end()) << id;
  const Result planar = run("check " + table + " --json");
  EXPECT_EQ(planar.out.find("planarity"), std::string::npos);
}

// render draws the spatial article and its modes (iso view by default: the front view
// looks along the plane's normal); a spatial run directory is still not replayed.
TEST_F(Cli, RenderDrawsTheSpatialArticleAndItsModes) {
  const fs::path png = dir_ / "mode2.png";
  const Result r = run("render --set model=spatial --mode 2 --out " + png.string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(isPng(png));
  const Result sheet = run("render --set model=spatial --mode 1-4 --out " + (dir_ / "sheet.png").string());
  EXPECT_EQ(sheet.code, 0) << sheet.err;
  ASSERT_EQ(run("render --set model=spatial --mode 2 --view iso --out " + (dir_ / "iso.png").string()).code, 0);
  ASSERT_EQ(run("render --set model=spatial --mode 2 --view front --out " + (dir_ / "front.png").string()).code, 0);
  EXPECT_EQ(slurp(png), slurp(dir_ / "iso.png"));
  EXPECT_NE(slurp(png), slurp(dir_ / "front.png"));
}

// Design and configuration sweeps on the spatial article: the modes are tracked by their
// three-dimensional shapes, and the check's planarity lines become sweep columns.
TEST_F(Cli, SweepsRunOnTheSpatialArticle) {
  const Result config = run("sweep-config --set model=spatial --grid joint1:-30:30:30 --modes 6 --json");
  ASSERT_EQ(config.code, 0) << config.err;
  const std::string spec = (dir_ / "spec.yaml").string();
  std::ofstream(spec) << "scene: " << (fs::path(MMVLAB_SOURCE_DIR) / "scenes" / "mmv.yaml").string()
                      << "\nsegments: 4\nset: [model=spatial]\nparameters:\n  - key: links.link3.length\n"
                         "    range: {from: 0.7, to: 0.8, samples: 2}\noutputs: [frequencies, check]\nmodes: 4\n";
  const Result sweep = run("sweep " + spec + " --out " + (dir_ / "sw").string());
  ASSERT_EQ(sweep.code, 0) << sweep.err;
  const std::string csv = slurp(dir_ / "sw" / "sweep.csv");
  EXPECT_NE(csv.find("planarity_modes_demand"), std::string::npos) << csv.substr(0, 600);
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 3);
}

// correlate against the spatial model: a measured set written from the spatial model
// itself (out-of-plane FRFs and mode shapes with z) pairs every mode and matches every
// out-of-plane function; the pairs the symmetric model decouples have no FRAC; the
// planar model skips the z functions, naming why.
TEST_F(Cli, CorrelateRunsOnTheSpatialArticle) {
  const std::string table = (fs::path(MMVLAB_SOURCE_DIR) / "scenes" / "mmv-table.yaml").string();
  ASSERT_EQ(run("frf " + table + " --set model=spatial --input table_x --input table_z --output link3a.tip:x --output "
                "link3a.tip:z --out " + (dir_ / "m").string()).code, 0);
  const std::string uff = (dir_ / "m" / "frf.uff").string();
  const Result r = run("correlate " + table + " --set model=spatial --measured " + uff + " --modes 12 --json");
  ASSERT_EQ(r.code, 0) << r.err;
  const nlohmann::json c = nlohmann::json::parse(r.out);
  ASSERT_EQ(c["pairs"].size(), 12u);
  for (const auto& p : c["pairs"]) EXPECT_GT(p["mac"].get<double>(), 0.9999) << p.dump();
  int matched = 0, decoupled = 0;
  for (const auto& f : c["frfs"]) {
    if (f.contains("frac")) matched += f["frac"].get<double>() > 0.999999;
    else decoupled += f["skipped"].get<std::string>().find("decoupled pair") != std::string::npos;
  }
  EXPECT_EQ(matched, 2);
  EXPECT_EQ(decoupled, 2);
  const Result planar = run("correlate " + table + " --measured " + uff + " --modes 12 --json");
  ASSERT_EQ(planar.code, 0) << planar.err;
  EXPECT_NE(planar.out.find("z and rotations out of the plane are outside the planar model"), std::string::npos);
}

}  // namespace
}  // namespace mmv::cli_testing
