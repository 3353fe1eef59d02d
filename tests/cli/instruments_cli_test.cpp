// The sensor catalogue at work: place-sensors --instrument (its mass loads the model as
// --sensor-mass does, its resolution sets the shaker's signal-to-noise, a triaxial one
// places blocks), --iterate-loaded, a scene sensor's instrument range in check, and the
// requests refused by name with nothing written.
#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>

#include "support/cli.hpp"

namespace mmv::cli_testing {
namespace {

// The instrument's mass is --sensor-mass's: the same loading, number for number.
TEST_F(Cli, AnInstrumentsMassLoadsTheModelAsSensorMassDoes) {
  const auto a = nlohmann::json::parse(
      run("place-sensors --segments 8 --count 8 --set instruments.accelerometer.mass_kg=0.005 --json").out);
  const auto b = nlohmann::json::parse(run("place-sensors --segments 8 --count 8 --sensor-mass 0.005 --json").out);
  ASSERT_TRUE(a.contains("mass_loading"));
  EXPECT_EQ(a.at("mass_loading"), b.at("mass_loading"));
  EXPECT_EQ(a.at("instrument").at("mass_kg").get<double>(), 0.005);
  EXPECT_EQ(b.at("instrument").at("mass_kg").get<double>(), 0.0);  // the scene's instrument, its mass overridden
  // A triaxial instrument places blocks, each one housing.
  const Result tri = run("place-sensors --segments 8 --count 4 --set instruments.tri.type=accelerometer --set instruments.tri.axes=3 "
                         "--set instruments.tri.mass_kg=0.012 --instrument tri --json");
  ASSERT_EQ(tri.code, 0) << tri.err;
  const auto t = nlohmann::json::parse(tri.out);
  EXPECT_EQ(t.at("sensor"), "triaxial");
  EXPECT_EQ(t.at("mass_loading").at("sensor_mass_kg").get<double>(), 0.012);
  EXPECT_EQ(t.at("mass_loading").at("sensors").get<int>(), 4);
}

// The exciter's signal-to-noise is over the placed instrument's resolution: ten times
// finer, every mode's sine SNR 20 dB higher, the forces unchanged (the range is the same).
TEST_F(Cli, TheShakersSignalToNoiseIsTheInstruments) {
  const std::string table = (fs::path(MMVLAB_SOURCE_DIR) / "scenes" / "mmv-table.yaml").string();
  const std::string base = "place-sensors " + table + " --segments 8 --count 12 --json";
  const auto coarse = nlohmann::json::parse(run(base).out).at("exciter");
  const Result r = run(base + " --set instruments.fine.type=accelerometer --set instruments.fine.resolution=0.0009806650 --instrument fine");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto fine = nlohmann::json::parse(r.out).at("exciter");
  EXPECT_NEAR(fine.at("sensor").at("resolution_m_per_s2").get<double>(), 0.1 * coarse.at("sensor").at("resolution_m_per_s2").get<double>(), 1e-15);
  ASSERT_EQ(fine.at("modes").size(), coarse.at("modes").size());
  for (std::size_t j = 0; j < fine.at("modes").size(); ++j) {
    const auto &f = fine.at("modes").at(j), &c = coarse.at("modes").at(j);
    EXPECT_NEAR(f.at("sine_snr_db").get<double>() - c.at("sine_snr_db").get<double>(), 20.0, 1e-9) << "mode " << j + 1;
    EXPECT_EQ(f.at("sine_force_n").get<double>(), c.at("sine_force_n").get<double>());
  }
}

// --iterate-loaded reports its passes; a milligram settles at once.
TEST_F(Cli, IteratedPlacementReportsItsPasses) {
  const Result r = run("place-sensors --segments 8 --count 8 --modes 1-4 --sensor-mass 0.002 --iterate-loaded --json");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto l = nlohmann::json::parse(r.out).at("mass_loading");
  ASSERT_GE(l.at("iterations").size(), 1u);
  EXPECT_LE(l.at("iterations").size(), 8u);
  const std::string outcome = l.at("iteration_outcome");
  EXPECT_EQ(outcome == "settled", l.at("iterations").back().at("settled").get<bool>());
  const Result text = run("place-sensors --segments 8 --count 8 --modes 1-4 --sensor-mass 1e-9 --iterate-loaded");
  ASSERT_EQ(text.code, 0) << text.err;
  EXPECT_NE(text.out.find("placed again on the model carrying them: pass 1, 0 changed; the set carries itself"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("Target modes of the model carrying them (Hz):"), std::string::npos);
}

// The review renders of an iterated placement draw the model its target modes are of
// (the one carrying the settled set), not the bare one: the mode panels' titles, read
// from the figure layout log, carry the target frequencies placement.json lists.
TEST_F(Cli, AnIteratedPlacementsModePanelsAreTheCarryingModels) {
  const fs::path out = dir_ / "iterated", log = dir_ / "layout.jsonl";
  const Result r = run("place-sensors " + (fs::path(MMVLAB_SOURCE_DIR) / "scenes" / "hamsas.yaml").string() +
                           " --below-hz 5 --count 12 --sensor-mass 0.1 --iterate-loaded --out " + out.string(),
                       "MMVLAB_FIGURE_LAYOUT=" + log.string() + " ");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(std::ifstream(out / "placement.json"));
  std::ifstream in(log);
  std::string panels;
  for (std::string line; std::getline(in, line);)
    if (line.find("review_modes.png") != std::string::npos) panels = line;
  ASSERT_FALSE(panels.empty());
  const auto f = j["target_frequencies_hz"];
  ASSERT_EQ(f.size(), 9u);
  for (std::size_t k = 0; k < f.size(); ++k) {
    char title[64];
    std::snprintf(title, sizeof title, "mode %zu: %.4g Hz", k + 1, f[k].get<double>());
    EXPECT_NE(panels.find(title), std::string::npos) << title;
  }
  EXPECT_EQ(panels.find("mode 1: 0.05083 Hz"), std::string::npos);  // the bare isolator's mode 1
}

TEST_F(Cli, InstrumentRequestsAreRefusedByName) {
  const std::string hamsas = (fs::path(MMVLAB_SOURCE_DIR) / "scenes" / "hamsas.yaml").string();
  struct Refusal {
    std::string args, message;
  };
  for (const Refusal& b : {
           Refusal{"--segments 4 --instrument accelerometr", "--instrument: unknown instrument 'accelerometr' (did you mean 'accelerometer'?)"},
           Refusal{"--segments 4 --instrument rate_gyro", "--instrument rate_gyro: a rate gyro; sensors are placed as accelerometers"},
           Refusal{"--segments 4 --instrument accelerometer --sensor-mass 0.001", "--sensor-mass and --instrument both give the sensors' mass"},
           Refusal{"--segments 4 --iterate-loaded", "--iterate-loaded: the accelerometer is massless"},
           Refusal{hamsas + " --instrument accelerometer", "--instrument applies to the article's scenes"},
           Refusal{hamsas + " --iterate-loaded", "--iterate-loaded: the sensors are massless: nothing loads the isolator (give --sensor-mass)"},
           Refusal{"--segments 4 --set instruments.accelerometer.mass_kg=11", "--set instruments.accelerometer.mass_kg=11: instruments.accelerometer.mass_kg must be between 0 and 10 kg"},
       }) {
    const fs::path none = dir_ / "refused";
    const Result e = run("place-sensors --count 4 " + b.args + " --out " + none.string());
    EXPECT_EQ(e.code, 64 + (b.args.find("--set") != std::string::npos)) << b.args << ": " << e.err;  // a scene value: 65
    EXPECT_NE(e.err.find(b.message), std::string::npos) << e.err;
    EXPECT_FALSE(fs::exists(none));
  }
}

// A scene sensor's range is its instrument's: a +-0.5 m/s^2 accelerometer on the slew
// saturates in simulate and check fails it, where the report's +-5 g one did not.
TEST_F(Cli, ASceneSensorsRangeIsItsInstruments) {
  const std::string slew = (fs::path(MMVLAB_SOURCE_DIR) / "scenes" / "mmv-slew.yaml").string();
  const std::string small = " --set instruments.accelerometer.range=0.5";
  const auto before = nlohmann::json::parse(run("check " + slew + " --json").out);
  const auto after = nlohmann::json::parse(run("check " + slew + small + " --json").out);
  auto line = [](const nlohmann::json& doc, const std::string& id) {
    for (const auto& l : doc.at("lines"))
      if (l.at("id") == id) return l;
    return nlohmann::json();
  };
  // The sensor's one verdict: the line of its two estimates (rigid run, flexible model) not left as info.
  const auto judged = [&](const nlohmann::json& doc) {
    const auto run = line(doc, "sensor.acc_link3a_tip.run");
    return run.at("verdict") == "info" ? line(doc, "sensor.acc_link3a_tip.table") : run;
  };
  const auto b = judged(before), a = judged(after);
  ASSERT_FALSE(b.is_null());
  ASSERT_FALSE(a.is_null());
  EXPECT_NEAR(b.at("capacity").get<double>(), 5 * 9.80665, 1e-9);
  EXPECT_NEAR(a.at("capacity").get<double>(), 0.5, 1e-12);
  EXPECT_NE(b.at("verdict"), "FAIL");
  EXPECT_EQ(a.at("verdict"), "FAIL") << a;
}

// check plans the scene's shaker on the scene's own accelerometers: its lines are
// place-sensors' exciter with those sensors kept (the same numbers, computed by the other
// command); without accelerometers, or undamped, the lines say why they are not checked.
TEST_F(Cli, CheckPlansTheShakerOnTheScenesAccelerometers) {
  // The default article with a shaker set, as place-sensors' own tests set it.
  const std::string shaker = " --set shaker.at=link2@1.2m --set 'shaker.direction=[0, 1, 0]'";
  std::string text = slurp(fs::path(MMVLAB_SOURCE_DIR) / "scenes" / "mmv.yaml");
  const std::string table = (dir_ / "bare.yaml").string() + shaker;
  text += "\nsensors:\n  - {name: a3, type: accelerometer, point: link3a.tip, axis: transverse}\n"
          "  - {name: a2, type: accelerometer, point: link2@1.0m, axis: transverse}\n";
  std::ofstream(dir_ / "bare.yaml") << slurp(fs::path(MMVLAB_SOURCE_DIR) / "scenes" / "mmv.yaml");
  std::ofstream(dir_ / "sensed.yaml") << text;
  const std::string sensed = (dir_ / "sensed.yaml").string() + shaker;
  const Result c = run("check " + sensed + " --segments 8 --json");
  ASSERT_LE(c.code, 1) << c.err;  // 1: a verdict below pass somewhere
  const auto doc = nlohmann::json::parse(c.out);
  const Result p = run("place-sensors " + sensed + " --segments 8 --below-hz 50 --count 2 --method dpr --keep-scene-sensors --json");
  ASSERT_EQ(p.code, 0) << p.err;
  const auto e = nlohmann::json::parse(p.out).at("exciter");
  int modes = 0;
  bool shift = false;
  for (const auto& l : doc.at("lines")) {
    if (l.at("group") != "shaker") continue;
    const std::string id = l.at("id");
    if (id == "shaker.armature_shift") {
      shift = true;
      EXPECT_EQ(l.at("capacity").get<double>(), 2.0);
      continue;
    }
    const auto& m = e.at("modes").at(static_cast<std::size_t>(modes++));
    EXPECT_EQ(id, "shaker.mode" + std::to_string(m.at("mode").get<int>()));
    EXPECT_NEAR(l.at("capacity").get<double>(), m.at("sine_snr_db").get<double>(), 1e-9);
    EXPECT_EQ(l.at("verdict"), m.at("seen").get<bool>() ? "pass" : "warn");
  }
  EXPECT_TRUE(shift);
  EXPECT_EQ(static_cast<std::size_t>(modes), e.at("modes").size());
  EXPECT_GT(modes, 3);
  struct Case {
    std::string args, message;
  };
  for (const Case& k : {Case{table, "the scene has no accelerometer to see the modes"},
                        Case{sensed + " --set damping.modal_ratio=0", "the shaker's levels need damping"}}) {
    const Result r = run("check " + k.args + " --segments 8 --json");
    ASSERT_LE(r.code, 1) << r.err;
    bool found = false;
    const auto lines = nlohmann::json::parse(r.out).at("lines");  // a copy: the parsed document is a temporary
    for (const auto& l : lines)
      if (l.at("id") == "shaker.levels") {
        found = true;
        EXPECT_EQ(l.at("verdict"), "n/a");
        EXPECT_NE(l.at("note").get<std::string>().find(k.message), std::string::npos) << l.at("note");
      }
    EXPECT_TRUE(found) << k.args;
  }
}

// modes --strain: each mode's strain over a span, checked against frf's strain output two
// ways: the static strain under a unit force at link 2, sum over every mode of
// strain_r u_r / omega_r^2 from modes' own numbers, is frf's response at 1e-4 Hz.
TEST_F(Cli, ModalStrainsSumToTheStaticStrainFrfGives) {
  const std::string span = "link3a@0.1m:link3a@0.5m", at = "link2@1.0m";
  const Result m = run("modes --segments 4 --modes 0 --no-error-estimate --json --points " + at + " --strain " + span);
  ASSERT_EQ(m.code, 0) << m.err;
  const auto modes = nlohmann::json::parse(m.out).at("modes");
  double sum = 0;
  for (const auto& mode : modes) {
    const double w = 2 * M_PI * mode.at("frequency_hz").get<double>();
    ASSERT_EQ(mode.at("strains").at(0).at("span"), span);
    sum += mode.at("strains").at(0).at("strain_per_modal_unit").get<double>() * mode.at("at_points").at(0).at("uy_per_modal_unit").get<double>() / (w * w);
  }
  // At 1e-4 Hz: the modal sum cancels to a small static strain that the dynamic terms move by 1e-3 at 0.01 Hz.
  const Result f = run("frf --segments 4 --input force:" + at + ":y --output strain:" + span + " --from 0.0001 --to 0.0002 --points 2 --json");
  ASSERT_EQ(f.code, 0) << f.err;
  const double frf_db = nlohmann::json::parse(f.out).at("pairs").at(0).at("peak_db").get<double>();
  EXPECT_NEAR(20 * std::log10(std::abs(sum)), frf_db, 1e-5) << "modal sum " << sum;
  const Result text = run("modes --segments 4 --modes 2 --no-error-estimate --strain " + span);
  EXPECT_NE(text.out.find("Modal strain over the spans asked for"), std::string::npos) << text.out;
  for (const std::string& bad : {"link3a@0.1m", "link3a@0.1m:link3b@0.5m", "link3a@0.1m:link3a@0.1m", "link3a@0.1m:link3a@0.9m"}) {
    const Result e = run("modes --segments 4 --strain " + bad);
    EXPECT_EQ(e.code, 64) << bad;
    EXPECT_NE(e.err.find("--strain " + bad + ": "), std::string::npos) << e.err;
  }
}

}  // namespace
}  // namespace mmv::cli_testing
