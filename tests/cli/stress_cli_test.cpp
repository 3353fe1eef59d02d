// frf's and rom's stress outputs (`stress:STATION[:face]`, issue 64) from the command
// line: the static stress of a cantilever under a tip moment (c M / I, in and out of the
// plane), the unit, the UFF file's type, each malformed request refused by name, and a strain beside a
// stress judged against its own units (before, a strain's 1e-3 beside a stress's 1e8
// was taken for round-off: a "zero pair").
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <map>

#include "support/cli.hpp"

namespace mmv::cli_testing {
namespace {

using json = nlohmann::json;

TEST_F(Cli, StressOutputsMeetTheBeamAndAreRefusedByName) {
  // Link 1's tube (scenes/mmv.yaml): under a tip moment M the moment is M all along, and
  // the +y face carries -M c / I (a positive moment compresses it): magnitude c / I per N*m.
  const double b = 0.0762, h = 0.0254, t = 0.0034;
  const double I = (b * h * h * h - (b - 2 * t) * std::pow(h - 2 * t, 3)) / 12;
  const Result r = run("frf --no-gravity --segments 8 --input moment:link1.tip:rz --output stress:link1@1.0 --output "
                       "stress:link1@0.3:-y --output strain:link1@0.5m:link1@1.5m --from 0.001 --to 0.002 --points 2 --json");
  ASSERT_EQ(r.code, 0) << r.err;
  const json pairs = json::parse(r.out).at("pairs");
  for (int k : {0, 1}) {
    EXPECT_EQ(pairs.at(k).at("output_unit"), "Pa");
    EXPECT_NEAR(pairs.at(k).at("peak_db").get<double>(), 20 * std::log10(0.5 * h / I), 1e-4) << pairs.at(k);
  }
  EXPECT_FALSE(pairs.at(2).value("zero_pair", false)) << pairs.at(2);  // a strain beside a stress: its own units' floor
  for (const std::string& bad : {"stress:link1@0.5m:sideways", "stress:link1@0.5m:+z", "stress:link1@0.5m:+y:x", "stress",
                                 "stress:link9@0.5m", "stress:link1@9m"}) {
    const Result e = run("frf --segments 4 --output " + bad);
    EXPECT_EQ(e.code, 64) << bad << ": " << e.err;
    EXPECT_NE(e.err.find("--output " + bad + ": "), std::string::npos) << e.err;
  }
  const Result rigid = run("frf --segments 4 --set links.link2.segments=rigid --output stress:link2@0.1m");
  EXPECT_EQ(rigid.code, 64);
  EXPECT_NE(rigid.err.find("is rigid"), std::string::npos) << rigid.err;
  // Out of the plane (the spatial model): a tip moment about world y, the +z face's
  // stress c_out M / I_out with c_out half the width.
  const fs::path bar = dir_ / "bar.yaml";
  std::ofstream(bar) << "name: bar\nmodel: spatial\ngravity: [0, 0, 0]\nmaterials:\n  steel: {density: 7800, youngs_modulus: 2.0e11, poisson_ratio: 0.3}\n"
                        "sections:\n  flat: {shape: rectangle, b: 0.02, h: 0.01}\njoints:\n  - {name: j1, parent: base, hold: locked}\n"
                        "links:\n  - {name: beam, joint: j1, material: steel, section: flat, length: 1.0, segments: 8}\n";
  const Result out = run("frf " + bar.string() + " --input moment:beam.tip:ry --output stress:beam@0.4m:+z --from 0.001 --to 0.002 "
                         "--points 2 --json");
  ASSERT_EQ(out.code, 0) << out.err;
  const double I_out = 0.01 * 0.02 * 0.02 * 0.02 / 12;
  EXPECT_NEAR(json::parse(out.out).at("pairs").at(0).at("peak_db").get<double>(), 20 * std::log10(0.01 / I_out), 1e-4);
  // The UFF file writes it as a stress (ordinate type 2, Pa) at its station's node, a
  // scalar, which correlate names and leaves out.
  const fs::path uff = dir_ / "uff";
  ASSERT_EQ(run("frf --segments 8 --output stress:link3a@0.1m --out " + uff.string()).code, 0);
  const Result c = run("correlate --segments 8 --modes 8 --measured " + (uff / "frf.uff").string());
  EXPECT_NE(c.out.find("not modelled: a stress (ordinate type 2)"), std::string::npos) << c.out << c.err;
  // rom names it with its unit too.
  const Result rom = run("rom --segments 4 --output stress:link3a@0.1m --out " + (dir_ / "rom").string());
  ASSERT_EQ(rom.code, 0) << rom.err;
  const std::string doc = slurp(dir_ / "rom" / "rom.json");
  EXPECT_NE(doc.find("stress:link3a@0.1m"), std::string::npos) << doc.substr(0, 2000);
  EXPECT_NE(doc.find("\"Pa\""), std::string::npos) << doc.substr(0, 2000);
}

// place-sensors --max-deflection holds to its stated range: 1e-6 .. 100 m, at each bound
// and one past it (exit 64 naming the option), and shows in the table's levels.
TEST_F(Cli, MaxDeflectionIsHeldToItsRange) {
  const std::string scene = std::string(MMVLAB_SOURCE_DIR) + "/scenes/mmv-table.yaml --segments 4 --modes 1-2 --json";
  for (const char* ok : {"1e-6", "100"}) {
    const Result r = run("place-sensors " + scene + " --max-deflection " + ok);
    EXPECT_EQ(r.code, 0) << ok << ": " << r.err;
    EXPECT_NEAR(json::parse(r.out).at("table_levels").at("max_deflection_m").get<double>(), std::stod(ok), 1e-18) << ok;
  }
  for (const char* bad : {"9.9e-7", "100.1", "-1"}) {
    const Result r = run("place-sensors " + scene + " --max-deflection " + bad);
    EXPECT_EQ(r.code, 64) << bad;
    EXPECT_NE(r.err.find("--max-deflection"), std::string::npos) << r.err;
  }
  const json levels = json::parse(run("place-sensors " + scene + " --max-deflection 0.01").out).at("table_levels").at("modes");
  EXPECT_EQ(levels.at(0).at("limit"), "deflection");
  EXPECT_NEAR(levels.at(0).at("tip_amplitude_m").get<double>(), 0.01, 1e-12);
}

// check's sensor lines mean what they say (issue 64): they honour --margin (before, a
// fixed 2 %: enc_elbow passed at 11.1 % under --margin 20), one sensor's rigid and
// flexible estimates give one verdict (the larger judged, the other stated), and the
// gravity note agrees with the demand it qualifies (a high-pass removes the static reading).
TEST_F(Cli, CheckSensorLinesHonourTheMarginAndJudgeOnce) {
  const std::string scene = std::string(MMVLAB_SOURCE_DIR) + "/scenes/mmv-slew.yaml --segments 2 --json --report-only";
  const auto lines = [&](const std::string& margin) {
    const Result r = run("check " + scene + " --margin " + margin);
    EXPECT_EQ(r.code, 0) << r.err;
    std::map<std::string, json> out;
    const json j = json::parse(r.out);
    for (const auto& l : j["lines"]) out[l["id"].get<std::string>()] = l;
    return out;
  };
  const auto at30 = lines("30"), at40 = lines("40");
  const json enc2 = at30.at("sensor.enc2.run");  // 30 deg of its 45: a 33 % margin
  EXPECT_EQ(enc2["verdict"], "pass") << enc2;
  EXPECT_EQ(at40.at("sensor.enc2.run")["verdict"], "warn") << at40.at("sensor.enc2.run");
  EXPECT_NE(at40.at("sensor.enc2.run")["note"].get<std::string>().find("within 40 % of its range"), std::string::npos);
  // acc_link3a_tip: the rigid run and the flexible model both estimate it; the larger is judged.
  const json rigid = at30.at("sensor.acc_link3a_tip.run"), flexible = at30.at("sensor.acc_link3a_tip.table");
  ASSERT_GT(flexible["demand"].get<double>(), rigid["demand"].get<double>());
  EXPECT_EQ(rigid["verdict"], "info");
  EXPECT_NE(rigid["note"].get<std::string>().find("not judged"), std::string::npos) << rigid;
  EXPECT_NE(flexible["verdict"], "info");
  EXPECT_NE(flexible["note"].get<std::string>().find("not in it: its 0.1 Hz high-pass removes the static reading"), std::string::npos)
      << flexible;
}

}  // namespace
}  // namespace mmv::cli_testing
