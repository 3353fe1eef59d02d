// place-sensors as a pre-test analysis: test-analysis models (--tam), the sensors' masses,
// the test geometry, the constraints. The TAMs on the chosen sensors of the article, their
// numbers against the modes computed another way, and the requests refused by name.
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "sim/core/text.hpp"
#include "support/cli.hpp"

namespace mmv::cli_testing {
namespace {

TEST_F(Cli, PlaceSensorsBuildsTheTamsAndTheirChecks) {
  const fs::path out = dir_ / "tam";
  const Result r = run("place-sensors --segments 8 --modes 1-6 --count 8 --tam all --json --out " + out.string());
  ASSERT_EQ(r.code, 0) << r.err;
  const auto doc = nlohmann::json::parse(r.out);
  const auto& tam = doc.at("tam");
  ASSERT_EQ(tam.at("models").size(), 3u);
  EXPECT_EQ(tam.at("channels").size(), 8u);
  // The target frequencies two ways: the TAM records', and `modes` on the same scene.
  const auto modes = nlohmann::json::parse(run("modes --segments 8 --modes 6 --no-error-estimate --json").out).at("modes");
  std::map<std::string, const nlohmann::json*> by_method;
  for (const auto& m : tam.at("models")) by_method[m.at("method")] = &m;
  for (std::size_t j = 0; j < 6; ++j) {
    const auto& serep = by_method.at("serep")->at("modes").at(j);
    EXPECT_NEAR(serep.at("frequency_hz").get<double>(), modes.at(j).at("frequency_hz").get<double>(), 1e-9);
    // SEREP holds the target modes exactly at any set that tells them apart.
    EXPECT_NEAR(serep.at("frequency_error").get<double>(), 0.0, 1e-8);
    EXPECT_NEAR(serep.at("cross_diagonal").get<double>(), 1.0, 1e-8);
    // IRS restores the omitted inertia: never further off than Guyan on these modes.
    const double guyan = std::abs(by_method.at("guyan")->at("modes").at(j).at("frequency_error").get<double>());
    const double irs = std::abs(by_method.at("irs")->at("modes").at(j).at("frequency_error").get<double>());
    EXPECT_LE(irs, guyan + 1e-12) << "mode " << j + 1;
    // A static reduction is a Ritz model: no TAM frequency below the mode it pairs with.
    EXPECT_GE(by_method.at("guyan")->at("modes").at(j).at("frequency_error").get<double>(), -1e-9) << "mode " << j + 1;
  }
  EXPECT_TRUE(by_method.at("serep")->at("pass").get<bool>());
  // tam.csv: a row per model and target mode, the records' values.
  const std::string csv = slurp(out / "tam.csv");
  EXPECT_EQ(csv.substr(0, csv.find('\n')),
            "method,mode,frequency_hz,tam_mode,tam_frequency_hz,frequency_error,self_diagonal,self_off_diagonal,"
            "cross_diagonal,cross_off_diagonal,pass,reason");
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 1 + 3 * 6);
}

TEST_F(Cli, PlaceSensorsRefusesATamItCannotBuildByName) {
  const Result unknown = run("place-sensors --segments 4 --tam craig");
  EXPECT_EQ(unknown.code, 64);
  EXPECT_NE(unknown.err.find("--tam: unknown test-analysis model 'craig' (known: guyan, irs, serep, all)"), std::string::npos)
      << unknown.err;
  // The isolator's TAMs are built (their identities: HamsasPlacement.Tams...); its
  // tam.csv has a row per model and target.
  const fs::path iso = dir_ / "isolator";
  const Result isolator = run("place-sensors " + (fs::path(MMVLAB_SOURCE_DIR) / "scenes" / "hamsas.yaml").string() +
                              " --below-hz 5 --count 9 --tam irs --out " + iso.string());
  ASSERT_EQ(isolator.code, 0) << isolator.err;
  const std::string iso_csv = slurp(iso / "tam.csv");
  EXPECT_EQ(std::count(iso_csv.begin(), iso_csv.end(), '\n'), 1 + 9);
  EXPECT_TRUE(fs::exists(iso / "tam.mat"));
  // Two sensors (ranked by kinetic energy: EfI refuses fewer than the modes itself) for
  // four target modes: SEREP needs one per mode; named, no output.
  const fs::path out = dir_ / "few";
  const Result few = run("place-sensors --segments 4 --modes 1-4 --count 2 --method mke --tam serep --out " + out.string());
  EXPECT_EQ(few.code, 64);
  EXPECT_NE(few.err.find("--tam serep: 2 sensor directions for 4 target modes"), std::string::npos) << few.err;
  EXPECT_FALSE(fs::exists(out));
}

}  // namespace
}  // namespace mmv::cli_testing

namespace mmv::cli_testing {
namespace {

// The test geometry place-sensors writes (test_geometry.uff, channels.csv) read back by
// correlate: every node pairs by its number to its own station (the position confirms
// it), and the predicted shapes pair with the model's modes at MAC 1 and no frequency
// error: the package closes on itself. A station keeps its node number in another run.
TEST_F(Cli, TheTestGeometryClosesOnCorrelate) {
  const fs::path a = dir_ / "a", b = dir_ / "b";
  ASSERT_EQ(run("place-sensors --segments 16 --count 12 --out " + a.string()).code, 0);
  ASSERT_EQ(run("place-sensors --segments 16 --count 8 --out " + b.string()).code, 0);
  const Result r = run("correlate --segments 16 --modes 10 --json --measured " + (a / "test_geometry.uff").string());
  ASSERT_EQ(r.code, 0) << r.err;
  const auto doc = nlohmann::json::parse(r.out);
  ASSERT_GE(doc.at("nodes").size(), 6u);
  for (const auto& n : doc.at("nodes")) {
    EXPECT_TRUE(n.at("by_number").get<bool>()) << n.dump();
    EXPECT_LT(n.at("distance_m").get<double>(), 1e-4) << n.dump();  // the UFF keeps 6 digits of each coordinate
  }
  ASSERT_EQ(doc.at("pairs").size(), doc.at("test_modes").size());
  for (const auto& p : doc.at("pairs")) {
    EXPECT_GT(p.at("mac").get<double>(), 0.9999) << p.dump();
    EXPECT_LT(std::abs(p.at("frequency_error").get<double>()), 1e-5) << p.dump();
  }
  // channels.csv: station -> node the same in both runs; unit measuring axes.
  std::map<std::string, std::string> node_of;
  for (const fs::path& dir : {a, b}) {
    std::istringstream csv(slurp(dir / "channels.csv"));
    std::string line;
    std::getline(csv, line);
    ASSERT_EQ(line.rfind("channel,node,station,link,axis,direction_x,direction_y,direction_z,", 0), 0u) << line;
    while (std::getline(csv, line)) {
      std::vector<std::string> c;
      std::stringstream cells(line);
      for (std::string cell; std::getline(cells, cell, ',');) c.push_back(cell);
      ASSERT_GE(c.size(), 8u) << line;
      const auto [it, fresh] = node_of.emplace(c[2], c[1]);
      EXPECT_EQ(it->second, c[1]) << c[2] << " changed its node between runs";
      const double x = std::stod(c[5]), y = std::stod(c[6]), z = std::stod(c[7]);
      EXPECT_NEAR(x * x + y * y + z * z, 1.0, 1e-5) << line;
    }
  }
}

}  // namespace
}  // namespace mmv::cli_testing

namespace mmv::cli_testing {
namespace {

// --sensor-mass: 0 .. 100 kg, at the bounds and one past; the loading in the JSON with
// each target's shift beside first order; on the isolator too.
TEST_F(Cli, SensorMassIsCheckedAndItsLoadingReported) {
  EXPECT_EQ(run("place-sensors --segments 4 --count 8 --sensor-mass 0").code, 0);
  EXPECT_EQ(run("place-sensors --segments 4 --count 8 --sensor-mass 100").code, 0);
  for (const char* bad : {"100.5", "-0.001", "nan"}) {
    const Result r = run(std::string("place-sensors --segments 4 --count 8 --sensor-mass ") + bad);
    EXPECT_EQ(r.code, 64) << bad;
    EXPECT_NE(r.err.find("--sensor-mass"), std::string::npos) << r.err;
  }
  // The isolator's: its springs carry the sensors' weight (HamsasPlacement.SensorMasses* checks the numbers).
  const Result isolator = run("place-sensors " + (fs::path(MMVLAB_SOURCE_DIR) / "scenes" / "hamsas.yaml").string() +
                              " --below-hz 5 --count 9 --sensor-mass 0.01 --json");
  ASSERT_EQ(isolator.code, 0) << isolator.err;
  const auto on_isolator = nlohmann::json::parse(isolator.out).at("mass_loading");
  EXPECT_EQ(on_isolator.at("sensors").get<int>(), 9);
  EXPECT_TRUE(on_isolator.at("weight_in_stiffness").get<bool>());
  EXPECT_EQ(on_isolator.at("modes").size(), 9u);
  // Without gravity the sensors' weight changes no geometric stiffness: the shift is
  // their inertia alone, first-order theory's (within 1 %: the mass rides its piece, the
  // shape is read between the hinges, which agree to 0.5 % at 16 segments).
  const Result r = run("place-sensors --segments 16 --count 8 --sensor-mass 1e-6 --no-gravity --json");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto loading = nlohmann::json::parse(r.out).at("mass_loading");
  EXPECT_EQ(loading.at("sensors").get<int>(), 8);
  EXPECT_NEAR(loading.at("added_kg").get<double>(), 8e-6, 1e-15);
  for (const auto& m : loading.at("modes")) {
    EXPECT_NEAR(m.at("shift").get<double>(), m.at("first_order_shift").get<double>(),
                0.01 * std::abs(m.at("first_order_shift").get<double>()) + 1e-12);
    // the loaded frequency two ways: its own, and the unloaded one times (1 + shift)
    EXPECT_NEAR(m.at("loaded_hz").get<double>(), m.at("frequency_hz").get<double>() * (1 + m.at("shift").get<double>()), 1e-9);
  }
}

}  // namespace
}  // namespace mmv::cli_testing

namespace mmv::cli_testing {
namespace {

// The constraints as a user gives them: each refused by its option's name with the fix,
// nothing written; a budget in channels sets the count (a triaxial block takes three).
TEST_F(Cli, PlacementConstraintsAreCheckedByName) {
  const fs::path out = dir_ / "c";
  const std::vector<std::pair<std::string, std::string>> bad{
      {"--keep-out link9:0:1", "--keep-out link9:0:1: no link 'link9'"},
      {"--keep-out link1:0:2.44", "covers the whole link"},
      {"--keep-out link1:1:0.5", "expected 0 <= FROM < TO <= 2.44 m"},
      {"--keep-out link1:x", "expected LINK:FROM_M:TO_M"},
      {"--min-separation 100.01", "--min-separation: must be a finite number"},
      {"--min-separation 3", "--min-separation 3 m: the candidates it leaves cannot tell every target mode apart"},
      {"--channels 2 --triaxial", "--channels 2: a triaxial block takes 3 channels"},
  };
  for (const auto& [args, message] : bad) {
    const Result r = run("place-sensors --segments 4 " + args + " --out " + out.string());
    EXPECT_EQ(r.code, 64) << args;
    EXPECT_NE(r.err.find(message), std::string::npos) << args << ": " << r.err;
    EXPECT_FALSE(fs::exists(out)) << args;
  }
  EXPECT_EQ(run("place-sensors --segments 4 --min-separation 100").code, 64);  // the bound: accepted, then too far for 8 modes
  const auto doc = [&](const std::string& args) { return nlohmann::json::parse(run("place-sensors --segments 8 --json " + args).out); };
  EXPECT_EQ(doc("--channels 12 --triaxial").at("chosen").size(), 4u);
  EXPECT_EQ(doc("--channels 12").at("chosen").size(), 12u);
  const auto kept = doc("--channels 12 --keep-out link1:2:2.44");  // a named document: a range-for over a temporary's member dangles
  for (const auto& c : kept.at("chosen"))
    EXPECT_FALSE(c.at("link") == "link1" && c.at("x_along_link_m").get<double>() >= 2.0) << c.dump();
}

}  // namespace
}  // namespace mmv::cli_testing

namespace mmv::cli_testing {
namespace {

// The scene's shaker (`shaker:`, here by --set on the default scene): its analysis in
// placement.json, exciter.csv and exciter_ranking.csv from the field lists; none of it
// without a shaker.
TEST_F(Cli, TheScenesShakerIsPlannedOnTheChosenSensors) {
  const std::string shaker = " --set shaker.at=link2@1.2m --set 'shaker.direction=[0, 1, 0]'";
  const fs::path out = dir_ / "shaker";
  const Result r = run("place-sensors --segments 8 --count 12" + shaker + " --json --out " + out.string());
  ASSERT_EQ(r.code, 0) << r.err;
  const auto doc = nlohmann::json::parse(r.out);
  const auto& e = doc.at("exciter");
  EXPECT_EQ(e.at("at"), "link2@1.2m");
  EXPECT_FALSE(e.at("chosen_by_ranking").get<bool>());
  const auto& targets = doc.at("target_frequencies_hz");
  ASSERT_EQ(e.at("modes").size(), targets.size());
  for (std::size_t j = 0; j < targets.size(); ++j) {
    const auto& m = e.at("modes").at(j);
    EXPECT_NEAR(m.at("frequency_hz").get<double>(), targets.at(j).get<double>(), 1e-9 * targets.at(j).get<double>());
    EXPECT_LE(m.at("loaded_hz").get<double>(), m.at("frequency_hz").get<double>() * (1 + 1e-9));  // the armature adds mass
    EXPECT_LE(m.at("sine_force_n").get<double>(), 30 * 4.4482216152605 * (1 + 1e-12));
    EXPECT_LE(m.at("sine_stroke_m").get<double>(), 0.075 * (1 + 1e-12));
    EXPECT_LE(m.at("sine_acc").get<double>(), 5 * 9.80665 * (1 + 1e-12));
    EXPECT_EQ(m.at("seen").get<bool>(), m.at("sine_snr_db").get<double>() >= 20);
  }
  std::string csv = slurp(out / "exciter.csv");
  EXPECT_EQ(csv.substr(0, csv.find('\n')),
            "mode,frequency_hz,loaded_mode,loaded_hz,shift,mac,zeta,sine_force_n,sine_limit,stress_link,static_stress_pa,stress_amplitude_pa,"
            "stress_limit_pa,tip,tip_amplitude_m,sine_acc,best_channel,sine_snr_db,"
            "channels_seen,sine_stroke_m,random_snr_db,seen");
  EXPECT_EQ(static_cast<std::size_t>(std::count(csv.begin(), csv.end(), '\n')), 1 + targets.size());
  csv = slurp(out / "exciter_ranking.csv");
  EXPECT_EQ(static_cast<long>(std::count(csv.begin(), csv.end(), '\n')), 1 + e.at("candidates").get<long>());
  // The text report says where and what it found.
  const Result text = run("place-sensors --segments 8 --count 12" + shaker);
  EXPECT_NE(text.out.find("Shaker (133.4 N, +-0.075 m stroke, 0.5 kg armature) at link2@1.2m"), std::string::npos) << text.out;
  // Without a shaker: no analysis, no files.
  const fs::path bare = dir_ / "bare";
  const Result none = run("place-sensors --segments 8 --count 12 --json --out " + bare.string());
  ASSERT_EQ(none.code, 0) << none.err;
  EXPECT_FALSE(nlohmann::json::parse(none.out).contains("exciter"));
  EXPECT_FALSE(fs::exists(bare / "exciter.csv"));
}

// The shaker's limits as the docs state them, at each bound and one past it; an
// attachment off the article; the fix named, exit 65 and nothing written.
TEST_F(Cli, TheShakersValuesAreCheckedAtTheirBounds) {
  const std::string at = " --set shaker.at=link1@1m --set 'shaker.direction=[0, 1, 0]'";
  struct Bound {
    std::string key, ok, past;
  };
  for (const Bound& b : {Bound{"force_limit_n", "1e-3", "0.99e-3"}, Bound{"force_limit_n", "1e6", "1.01e6"},
                         Bound{"stroke_m", "1e-6", "0.99e-6"}, Bound{"stroke_m", "10", "10.1"},
                         Bound{"armature_mass_kg", "0", "-1e-9"}, Bound{"armature_mass_kg", "1000", "1000.1"},
                         Bound{"crest_factor", "1", "0.99"}, Bound{"crest_factor", "10", "10.1"}}) {
    const Result ok = run("place-sensors --segments 4 --count 8" + at + " --set shaker." + b.key + "=" + b.ok);
    EXPECT_EQ(ok.code, 0) << b.key << "=" << b.ok << ": " << ok.err;
    const fs::path out = dir_ / ("past-" + b.key);
    const Result past = run("place-sensors --segments 4 --count 8" + at + " --set shaker." + b.key + "=" + b.past + " --out " + out.string());
    EXPECT_EQ(past.code, 65) << b.key << "=" << b.past;
    EXPECT_NE(past.err.find("shaker." + b.key + " must be between"), std::string::npos) << past.err;
    EXPECT_FALSE(fs::exists(out));
  }
  const Result off = run("place-sensors --segments 4 --set shaker.at=link2@2m --set 'shaker.direction=[0, 1, 0]'");
  EXPECT_EQ(off.code, 65);
  EXPECT_NE(off.err.find("shaker.at: the shaker must be attached to the article at a station"), std::string::npos) << off.err;
  EXPECT_NE(off.err.find("outside link2 (0 to 1.52 m)"), std::string::npos) << off.err;
  const Result flat = run("place-sensors --segments 4 --set shaker.at=link2@1m --set 'shaker.direction=[0, 0, 1]'");
  EXPECT_EQ(flat.code, 65);
  EXPECT_NE(flat.err.find("shaker.direction leaves the plane of motion (z = 1): it needs model: spatial"), std::string::npos) << flat.err;
  const Result half = run("place-sensors --segments 4 --set shaker.at=auto --set 'shaker.direction=[0, 1, 0]'");
  EXPECT_EQ(half.code, 65);
  EXPECT_NE(half.err.find("give both as 'auto', or neither"), std::string::npos) << half.err;
  // Undamped, a resonance has no bound: refused, not round-off printed as levels.
  const fs::path undamped = dir_ / "undamped";
  const Result none = run("place-sensors --segments 4 --count 8" + at + " --set damping.modal_ratio=0 --out " + undamped.string());
  EXPECT_EQ(none.code, 65);
  EXPECT_NE(none.err.find("the shaker's levels need damping: mode 1 of the article with the armature"), std::string::npos) << none.err;
  EXPECT_FALSE(fs::exists(undamped));
}

// --keep-scene-sensors: the slew scene's two accelerometers (link 2's tip, transverse;
// link 3a's tip, transverse) kept and counted; the refusals named, nothing written.
TEST_F(Cli, TheScenesOwnSensorsAreKeptAndCounted) {
  const std::string slew = (fs::path(MMVLAB_SOURCE_DIR) / "scenes" / "mmv-slew.yaml").string();
  const fs::path out = dir_ / "kept";
  const Result r = run("place-sensors " + slew + " --segments 8 --count 8 --method dpr --keep-scene-sensors --json --out " + out.string());
  ASSERT_EQ(r.code, 0) << r.err;
  const auto doc = nlohmann::json::parse(r.out);
  ASSERT_EQ(doc.at("chosen").size(), 8u);
  std::set<std::string> fixed;
  for (const auto& c : doc.at("chosen"))
    if (c.at("fixed").get<int>() == 1) fixed.insert(c.at("station").get<std::string>() + " " + c.at("axis").get<std::string>());
  EXPECT_EQ(fixed, (std::set<std::string>{"link2@1.52m transverse", "link3a@0.762m transverse"}));
  const std::string csv = slurp(out / "candidates.csv");
  EXPECT_EQ(csv.substr(0, csv.find('\n')), "station,link,x_along_link_m,axis,world_x_m,world_y_m,world_z_m,chosen,score,fixed");
  struct Refusal {
    std::string args, message;
    int code;
  };
  EXPECT_EQ(run("place-sensors " + slew + " --segments 4 --modes 1-2 --count 2 --keep-scene-sensors").code, 0);  // the bound: only the scene's
  // Triaxial: a block at each of the two stations, kept and counted (it failed before:
  // --triaxial was refused with --keep-scene-sensors).
  const Result tri = run("place-sensors " + slew + " --segments 8 --count 4 --triaxial --keep-scene-sensors --json");
  ASSERT_EQ(tri.code, 0) << tri.err;
  std::set<std::string> blocks;
  const auto tri_doc = nlohmann::json::parse(tri.out);  // kept alive over the loop
  for (const auto& c : tri_doc.at("chosen"))
    if (c.at("fixed").get<int>() == 1) blocks.insert(c.at("station").get<std::string>() + " " + c.at("axis").get<std::string>());
  EXPECT_EQ(blocks, (std::set<std::string>{"link2@1.52m triaxial", "link3a@0.762m triaxial"}));
  for (const Refusal& b : {Refusal{slew + " --segments 4 --count 1", "--count 1: below the 2 accelerometers of the scene", 64},
                           Refusal{"--segments 4", "--keep-scene-sensors: the scene has no accelerometer to keep", 64},
                           Refusal{slew + " --segments 4 --triaxial --count 1", "--count 1: below the 2 accelerometers of the scene", 64},
                           Refusal{(fs::path(MMVLAB_SOURCE_DIR) / "scenes" / "hamsas.yaml").string(), "applies to the article's scenes", 64}}) {
    const fs::path none = dir_ / "refused";
    const Result e = run("place-sensors " + b.args + " --keep-scene-sensors --out " + none.string());
    EXPECT_EQ(e.code, b.code) << b.args;
    EXPECT_NE(e.err.find(b.message), std::string::npos) << e.err;
    EXPECT_FALSE(fs::exists(none));
  }
  // A sensor at a point of the mesh moves with the segments: refused, with its position.
  std::string text = slurp(slew);
  text.replace(text.find("point: link2.tip"), 16, "point: link2.h3");
  const fs::path scene = dir_ / "mesh-point.yaml";
  std::ofstream(scene) << text;
  const Result mesh = run("place-sensors " + scene.string() + " --segments 4 --keep-scene-sensors");
  EXPECT_EQ(mesh.code, 64);
  const std::string entry_line =  // the sensor's entry, wherever the shipped scene has it
      std::to_string(1 + std::count(text.begin(), text.begin() + static_cast<long>(text.find("name: acc_link2_tip")), '\n'));
  EXPECT_NE(mesh.err.find("sensor acc_link2_tip (" + scene.string() + ":" + entry_line + ":5): 'link2.h3' is a point of the mesh"),
            std::string::npos)
      << mesh.err;
}

// A strain output (a gauge or the report's piezo film): the static strain of link 1 under
// a tip moment is -c M / (E I), computed here from the section's dimensions; the film
// on link 3a is written with its unit and as a strain (UFF ordinate type 3) that
// correlate names and leaves out; malformed spans refused by name.
TEST_F(Cli, StrainOutputsMeetTheBeamAndAreRefusedByName) {
  const Result r = run("frf --no-gravity --segments 8 --input moment:link1.tip:rz --output strain:link1@0.5m:link1@1.5m "
                       "--from 0.001 --to 0.002 --points 2 --json");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto pair = nlohmann::json::parse(r.out).at("pairs").at(0);
  EXPECT_EQ(pair.at("output_unit"), "m/m");
  const double b = 0.0762, h = 0.0254, t = 0.0034;  // link 1's tube (scenes/mmv.yaml)
  const double I = (b * h * h * h - (b - 2 * t) * std::pow(h - 2 * t, 3)) / 12, EI = 41.4e9 * I;
  EXPECT_NEAR(pair.at("peak_db").get<double>(), 20 * std::log10(0.5 * h / EI), 1e-4);
  const fs::path out = dir_ / "film";
  const Result film = run("frf --segments 8 --output strain:link3a@0.1m:link3a@0.5m --out " + out.string());
  ASSERT_EQ(film.code, 0) << film.err;
  const std::string csv = slurp(out / "frf_strain_link3a_0.1m_link3a_0.5m__table_x.csv");
  EXPECT_EQ(csv.substr(0, csv.find('\n')), "frequency_hz,magnitude_db,phase_deg,magnitude_m_m_per_m_s2,rom_magnitude_db,rom_phase_deg");
  const Result c = run("correlate --segments 8 --modes 8 --measured " + (out / "frf.uff").string());
  EXPECT_NE(c.out.find("not modelled: a strain (ordinate type 3)"), std::string::npos) << c.out;
  for (const std::string& bad : {"strain:link3a@0.1m:link3b@0.5m", "strain:link3a@0.1m:link3a@0.1m", "strain:link3a.tip:link3a@0.1m",
                                 "strain:link3a@0.1m", "strain:link3a@0.1m:link3a@0.9m"}) {
    const Result e = run("frf --segments 4 --output " + bad);
    EXPECT_EQ(e.code, 64) << bad;
    EXPECT_NE(e.err.find("--output " + bad + ": "), std::string::npos) << e.err;
  }
  EXPECT_NE(run("frf --segments 4 --set links.link2.segments=rigid --output strain:link2@0.1m:link2@0.5m").err.find("it does not bend"),
            std::string::npos);
  // Out of the plane (the spatial model): a tip moment about world y bends a cantilever
  // along x about its width, and the +z face's strain is c M / (E I_out) everywhere.
  const fs::path bar = dir_ / "bar.yaml";
  std::ofstream(bar) << "name: bar\nmodel: spatial\ngravity: [0, 0, 0]\nmaterials:\n  steel: {density: 7800, youngs_modulus: 2.0e11, poisson_ratio: 0.3}\n"
                        "sections:\n  flat: {shape: rectangle, b: 0.02, h: 0.01}\njoints:\n  - {name: j1, parent: base, hold: locked}\n"
                        "links:\n  - {name: beam, joint: j1, material: steel, section: flat, length: 1.0, segments: 8}\n";
  const Result out_of_plane = run("frf " + bar.string() + " --input moment:beam.tip:ry --output strain:beam@0.2m:beam@0.6m:out "
                                  "--from 0.001 --to 0.002 --points 2 --json");
  ASSERT_EQ(out_of_plane.code, 0) << out_of_plane.err;
  const double I_out = 0.01 * 0.02 * 0.02 * 0.02 / 12;
  EXPECT_NEAR(nlohmann::json::parse(out_of_plane.out).at("pairs").at(0).at("peak_db").get<double>(), 20 * std::log10(0.01 / (2.0e11 * I_out)), 1e-4);
  EXPECT_NE(run("frf --segments 4 --output strain:link2@0.1m:link2@0.5m:out").err.find("does not bend out of its plane"), std::string::npos);
  const Result sideways = run("frf --segments 4 --set model=spatial --output strain:link2@0.1m:link2@0.5m:sideways");
  EXPECT_EQ(sideways.code, 64);
  EXPECT_NE(sideways.err.find("[:in|out]"), std::string::npos) << sideways.err;
  const Result modes = run("modes --segments 4 --set model=spatial --strain link2@0.1m:link2@0.5m:out --json");
  EXPECT_EQ(modes.code, 0) << modes.err;
  // A link kept planar in a spatial article does not bend out of the plane: refused there,
  // and placement offers its in-plane face only.
  const Result kept = run("frf --segments 4 --set model=spatial --set links.link2.model=planar --output strain:link2@0.1m:link2@0.5m:out");
  EXPECT_EQ(kept.code, 64);
  EXPECT_NE(kept.err.find("link2 is planar in this spatial article"), std::string::npos) << kept.err;
  const fs::path mixed = dir_ / "mixed";
  const Result placed = run("place-sensors --segments 4 --set model=spatial --set links.link2.model=planar --strain-span 0.3 "
                            "--modes 1-4 --count 6 --out " + mixed.string());
  ASSERT_EQ(placed.code, 0) << placed.err;
  int out_faces = 0, link2_in = 0, link2_out = 0;
  std::istringstream rows(slurp(mixed / "candidates.csv"));
  for (std::string row; std::getline(rows, row);) {
    const std::string station = row.substr(0, row.find(','));
    const bool out = station.find(":out") != std::string::npos, on2 = station.rfind("link2@", 0) == 0;
    out_faces += out ? 1 : 0;
    link2_in += on2 && !out ? 1 : 0;
    link2_out += on2 && out ? 1 : 0;
  }
  EXPECT_GT(out_faces, 0);
  EXPECT_GT(link2_in, 0);
  EXPECT_EQ(link2_out, 0);
}

// The TAM exported (tam.mat) and used by correlate: the predicted modes of the placement's
// own test geometry are the target modes at the channels, so their test orthogonality
// under SEREP is the identity, and under Guyan it is the TAM's self-orthogonality that
// place-sensors reported (two ways: from the model, and from the file through correlate).
TEST_F(Cli, TheTamIsExportedAndGivesCorrelateTestOrthogonality) {
  const fs::path p = dir_ / "pretest";
  const Result placed = run("place-sensors --segments 8 --modes 1-6 --count 8 --tam all --json --out " + p.string());
  ASSERT_EQ(placed.code, 0) << placed.err;
  std::map<std::string, nlohmann::json> self;
  const auto placement = nlohmann::json::parse(placed.out);  // named: a range-for over a temporary's member dangles
  for (const auto& m : placement.at("tam").at("models")) self[m.at("method").get<std::string>()] = m;
  const std::string base = "correlate --segments 8 --modes 6 --json --measured " + (p / "test_geometry.uff").string() + " --tam " +
                           (p / "tam.mat").string();
  const Result serep = run(base + ":serep");
  ASSERT_EQ(serep.code, 0) << serep.err;
  const auto s = nlohmann::json::parse(serep.out).at("test_orthogonality");
  EXPECT_EQ(s.at("channels"), 8);
  EXPECT_TRUE(s.at("pass").get<bool>());
  ASSERT_EQ(s.at("matrix").size(), 6u);
  for (std::size_t i = 0; i < 6; ++i)
    for (std::size_t j = 0; j < 6; ++j)
      EXPECT_NEAR(s.at("matrix").at(i).at(j).get<double>(), i == j ? 1.0 : 0.0, 1e-5) << i << "," << j;  // the file's 6 digits
  const Result guyan = run(base + ":guyan");
  ASSERT_EQ(guyan.code, 0) << guyan.err;
  const auto g = nlohmann::json::parse(guyan.out).at("test_orthogonality");
  for (std::size_t i = 0; i < 6; ++i)
    EXPECT_NEAR(g.at("modes").at(i).at("max_off_diagonal").get<double>(),
                self.at("guyan").at("modes").at(i).at("self_off_diagonal").get<double>(), 1e-4)
        << "mode " << i + 1;
  // Refused by name: several TAMs and none named, one the file lacks, a file that is not a TAM's or not there.
  const Result several = run(base);
  EXPECT_EQ(several.code, 64);
  EXPECT_NE(several.err.find("the file holds 3 TAMs (guyan, irs, serep): name one"), std::string::npos) << several.err;
  const fs::path one = dir_ / "one";
  ASSERT_EQ(run("place-sensors --segments 8 --modes 1-6 --count 8 --tam guyan --out " + one.string()).code, 0);
  const Result lacks = run("correlate --segments 8 --measured " + (p / "test_geometry.uff").string() + " --tam " + (one / "tam.mat").string() + ":irs");
  EXPECT_EQ(lacks.code, 64);
  EXPECT_NE(lacks.err.find("the file holds no irs TAM (it holds guyan)"), std::string::npos) << lacks.err;
  const fs::path rom = dir_ / "rom";
  ASSERT_EQ(run("rom --segments 4 --out " + rom.string()).code, 0);
  const Result other = run("correlate --segments 8 --measured " + (p / "test_geometry.uff").string() + " --tam " + (rom / "full.mat").string());
  EXPECT_EQ(other.code, 65);
  EXPECT_NE(other.err.find("no Method: not a TAM file of place-sensors --tam --out"), std::string::npos) << other.err;
  const Result none = run("correlate --segments 8 --measured " + (p / "test_geometry.uff").string() + " --tam " + (dir_ / "nope.mat").string());
  EXPECT_EQ(none.code, 66);
  EXPECT_NE(none.err.find("no such file"), std::string::npos) << none.err;
}

// The scene's shaker drives frf too (--input shaker: its force along its direction, its
// armature on the article): the driving point's receptance at each target's dwell
// frequency is the exciter's amplitude over its force, computed the second way.
TEST_F(Cli, FrfsShakerInputIsTheExcitersModel) {
  const std::string scene = (fs::path(MMVLAB_SOURCE_DIR) / "scenes" / "mmv-table.yaml").string() +
                            " --segments 8 --set shaker.at=link2@1.2m --set 'shaker.direction=[0, 1, 0]'";
  const Result placed = run("place-sensors " + scene + " --count 12 --json");
  ASSERT_EQ(placed.code, 0) << placed.err;
  const auto doc = nlohmann::json::parse(placed.out);
  for (std::size_t j : {std::size_t{0}, std::size_t{4}}) {
    const auto& m = doc.at("exciter").at("modes").at(j);
    const double f = m.at("loaded_hz").get<double>();
    const fs::path out = dir_ / ("frf" + std::to_string(j));
    const Result r = run("frf " + scene + " --input shaker --output link2@1.2m:y:disp --points 2 --from " + strf("%.17g", f) +
                         " --to " + strf("%.17g", f * (1 + 1e-6)) + " --out " + out.string());
    ASSERT_EQ(r.code, 0) << r.err;
    std::istringstream csv(slurp(out / "frf_link2_1.2m_y_disp__shaker.csv"));
    std::string header, row;
    std::getline(csv, header);
    std::getline(csv, row);
    EXPECT_EQ(header.substr(0, 54), "frequency_hz,magnitude_db,phase_deg,magnitude_m_per_n,");
    std::vector<double> cells;
    std::istringstream line(row);
    for (std::string c; std::getline(line, c, ',');) cells.push_back(std::stod(c));
    ASSERT_GE(cells.size(), 4u);
    EXPECT_NEAR(cells[3] / (m.at("sine_stroke_m").get<double>() / m.at("sine_force_n").get<double>()), 1.0, 1e-6) << "mode " << j + 1;
  }
  const Result twice = run("frf " + scene + " --input shaker --input shaker");
  EXPECT_EQ(twice.code, 64);
  EXPECT_NE(twice.err.find("given twice"), std::string::npos) << twice.err;
  const Result none = run("frf --segments 4 --input shaker");
  EXPECT_EQ(none.code, 64);
  EXPECT_NE(none.err.find("the scene has no shaker"), std::string::npos) << none.err;
}

}  // namespace
}  // namespace mmv::cli_testing
