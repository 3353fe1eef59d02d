// `mmvlab correlate` end to end: a "measured" set written by our own UFF writer from a
// model whose link 2 is 5 % stiffer (the known answer: each mode's frequency shift,
// computed here from the two models' own mode tables), the same set against its own
// model (exact), modes the test did not see, nodes off the article, named pairs, and
// the input errors.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <regex>

#include "support/cli.hpp"

namespace mmv::cli_testing {
namespace {

using json = nlohmann::json;

class Correlate : public Cli {
 protected:
  /// scenes/mmv-table.yaml with link 2 of a material 5 % stiffer (same density).
  fs::path stiffScene() {
    std::string s = slurp(fs::path(MMVLAB_SOURCE_DIR) / "scenes/mmv-table.yaml");
    s = std::regex_replace(s, std::regex("\nmaterials:\n"), "\nmaterials:\n  cc_stiff: {density: 1650, youngs_modulus: 43.47e9}\n");
    const auto l2 = s.find("name: link2");
    const auto m = s.find("material:", l2);
    s.replace(m, s.find('\n', m) - m, "material: cc_stiff");
    return write("stiff.yaml", s);
  }
  fs::path measured(const std::string& scene, const std::string& name) {
    const Result r = run("frf " + scene + " --out " + (dir_ / name).string());
    EXPECT_EQ(r.code, 0) << r.err;
    return dir_ / name / "frf.uff";
  }
  json runJson(const std::string& args) {
    const Result r = run(args + " --json");
    EXPECT_EQ(r.code, 0) << r.err;
    return json::parse(r.out);
  }
  std::string table() const { return (fs::path(MMVLAB_SOURCE_DIR) / "scenes/mmv-table.yaml").string(); }
};

TEST_F(Correlate, AStifferLinkTwoShowsAsItsModesFrequencyShifts) {
  const fs::path stiff = stiffScene();
  const fs::path uff = measured(stiff.string(), "stiff");
  const json c = runJson("correlate " + table() + " --measured " + uff.string() + " --modes 12");
  const json nominal = runJson("modes " + table() + " --no-error-estimate");
  const json stiffer = runJson("modes " + stiff.string() + " --no-error-estimate");
  ASSERT_EQ(c["pairs"].size(), 12u) << c.dump(1);
  double largest = 0;
  std::string largest_link;
  for (std::size_t k = 0; k < 12; ++k) {
    const json& p = c["pairs"][k];
    EXPECT_EQ(p["test"], "T" + std::to_string(k + 1));
    EXPECT_EQ(p["model"], "M" + std::to_string(k + 1));  // every mode with its own
    EXPECT_GT(p["mac"].get<double>(), 0.99) << k;
    // The known answer: f_model / f_test - 1 from the two models' own tables (the file
    // holds 6 significant digits).
    const double expect = nominal["modes"][k]["frequency_hz"].get<double>() / stiffer["modes"][k]["frequency_hz"].get<double>() - 1;
    EXPECT_NEAR(p["frequency_error"].get<double>(), expect, 2e-5) << k;
    if (std::abs(expect) > std::abs(largest)) largest = expect, largest_link = nominal["modes"][k]["dominant_link_strain"];
  }
  EXPECT_LT(largest, -0.01);  // the model is softer than the test by over 1 % ...
  EXPECT_EQ(largest_link, "link2");  // ... in a mode link 2's strain carries
  EXPECT_TRUE(c["model_modes_not_seen"].empty());
  EXPECT_TRUE(c["test_modes_not_predicted"].empty());
  ASSERT_EQ(c["frfs"].size(), 16u);  // frf's defaults: 8 tip accelerations x 2 table axes
  for (const json& f : c["frfs"]) {
    ASSERT_TRUE(f.contains("frac")) << f.dump();
    EXPECT_GT(f["frac"].get<double>(), 0.9) << f.dump();
    EXPECT_LT(f["frac"].get<double>(), 0.99999) << f.dump();  // the stiffer link shows in every response
  }
}

TEST_F(Correlate, TheModelAgainstItsOwnResponsesIsExact) {
  const fs::path uff = measured(table(), "self");
  const fs::path out = dir_ / "out";
  const Result r = run("correlate " + table() + " --measured " + uff.string() + " --modes 12 --out " + out.string());
  ASSERT_EQ(r.code, 0) << r.err;
  const json c = json::parse(slurp(out / "correlation.json"));
  ASSERT_EQ(c["pairs"].size(), 12u);
  for (const json& p : c["pairs"]) {
    EXPECT_GT(p["mac"].get<double>(), 0.9999) << p.dump();
    EXPECT_LT(std::abs(p["frequency_error"].get<double>()), 1e-5) << p.dump();
  }
  for (const json& f : c["frfs"]) EXPECT_GT(f["frac"].get<double>(), 0.999999) << f.dump();
  for (const json& n : c["nodes"]) EXPECT_LT(n["distance_m"].get<double>(), 2e-5) << n.dump();  // E13.5 coordinates: 6 digits
  EXPECT_TRUE(isPng(out / "mac.png"));
  int bodes = 0;
  for (const auto& e : fs::directory_iterator(out)) bodes += e.path().filename().string().rfind("frf_", 0) == 0 && isPng(e.path());
  EXPECT_EQ(bodes, 16);
  const std::string csv = slurp(out / "mac.csv");
  EXPECT_EQ(csv.substr(0, csv.find('\n')), "test_mode,test_frequency_hz,model_mode,model_frequency_hz,mac");
  EXPECT_NE(r.out.find("T1 "), std::string::npos);
}

// Pairing with judgement: a mode pairs only within the frequency window, a candidate
// left out is named; a node without geometry and nodes that share a station are noted;
// each FRAC has its verdict. Before, a 167 Hz test mode paired with a 62.7 kHz model
// mode, nodes without geometry vanished ("MAC over 0 translations") and 18 nodes on one
// station went unremarked.
TEST_F(Correlate, PairsInsideTheWindowAndNotesWhatItLeavesOut) {
  const fs::path uff = measured(stiffScene().string(), "stiff");
  const json tight = runJson("correlate " + table() + " --measured " + uff.string() + " --modes 12 --max-frequency-error 1e-6");
  for (const json& p : tight["pairs"]) EXPECT_LE(std::abs(p["frequency_error"].get<double>()), 1e-6) << p.dump();
  const std::size_t left_out = tight["test_modes_not_predicted"].size();
  EXPECT_EQ(left_out + tight["pairs"].size(), 12u);
  EXPECT_GE(left_out, 6u);  // the modes link 2's stiffness moves
  std::size_t window_notes = 0;
  for (const json& n : tight["notes"])
    window_notes += n.get<std::string>().find("outside the +-0.0001 % frequency window: not paired") != std::string::npos;
  EXPECT_EQ(window_notes, left_out) << tight["notes"].dump(1);
  const json wide = runJson("correlate " + table() + " --measured " + uff.string() + " --modes 12");
  EXPECT_EQ(wide["pairs"].size(), 12u);
  for (const json& f : wide["frfs"]) {
    EXPECT_EQ(f["frac_threshold"].get<double>(), 0.9);
    EXPECT_EQ(f["frac_verdict"], f["frac"].get<double>() >= 0.9 ? "consistent" : "differs") << f.dump();
  }

  std::string text = slurp(uff);
  // Node 1 loses its geometry (its dataset-15 line), and node 998 is put where node 2 is.
  const auto nodes = text.find("    -1\n    15    ");
  ASSERT_NE(nodes, std::string::npos);
  const auto first = text.find('\n', nodes + 7) + 1;  // past the "15" line
  const std::string line1 = text.substr(first, text.find('\n', first) + 1 - first);
  ASSERT_EQ(line1.substr(0, 10), "         1") << line1;
  text.erase(first, line1.size());
  const std::string line2 = text.substr(first, text.find('\n', first) + 1 - first);
  ASSERT_EQ(line2.substr(0, 10), "         2") << line2;
  text.insert(first, "       998" + line2.substr(10));
  const json c = runJson("correlate " + table() + " --measured " + write("edited.uff", text).string() + " --modes 12");
  const std::string notes = c["notes"].dump();
  EXPECT_NE(notes.find("node 1 has a mode shape but no geometry"), std::string::npos) << notes;
  EXPECT_NE(notes.find("3 nodes (998, 2, 76) pair with one station, link1@0m"), std::string::npos) << notes;  // 76: the root once more
  EXPECT_EQ(c["pairs"].size(), 12u);  // the rest still pair
}

TEST_F(Correlate, UnseenModesUnpairedNodesAndNamedPairs) {
  std::string text = slurp(measured(table(), "self"));
  // The test missed mode 3: its dataset 55 is gone.
  const auto m3 = text.find("mode 3 ");
  ASSERT_NE(m3, std::string::npos);
  const auto start = text.rfind("    -1\n    55", m3), end = text.find("    -1\n", m3) + 7;
  text.erase(start, end - start);
  // A node 2 m from the article (a reference accelerometer on the floor, say).
  const auto nodes = text.find("    -1\n    15    ");  // the header is padded to 80 columns
  ASSERT_NE(nodes, std::string::npos);
  const auto close = text.find("    -1\n", nodes + 14);
  text.insert(close, "       999         0         0         8  5.00000E+00  1.00000E+00  0.00000E+00\n");
  const fs::path uff = write("edited.uff", text);
  const json c = runJson("correlate " + table() + " --measured " + uff.string() + " --modes 12 --pair 3=link1@0.5");
  ASSERT_EQ(c["model_modes_not_seen"].size(), 1u) << c.dump(1);
  EXPECT_EQ(c["model_modes_not_seen"][0], "M3");
  EXPECT_EQ(c["pairs"].size(), 11u);
  bool far_found = false, named_found = false;
  for (const json& n : c["nodes"]) {
    if (n["node"] == 999) far_found = n["station"].is_null() && n["distance_m"].get<double>() > 1.0;
    if (n["node"] == 3) named_found = n["station"] == "link1@0.5" && n["by_name"] == true;
  }
  EXPECT_TRUE(far_found);
  EXPECT_TRUE(named_found);
  ASSERT_FALSE(c["warnings"].empty());
  EXPECT_NE(c["warnings"].dump().find("node 999"), std::string::npos);
}

TEST_F(Correlate, BadInputIsNamed) {
  Result r = run("correlate --measured " + (dir_ / "missing.uff").string());
  EXPECT_EQ(r.code, 66) << r.err;
  const fs::path bad = write("bad.uff", "    -1\n    58\nx\nx\nx\nx\nx\n    4         1    0         0 NONE               1   1 NONE               1   1\n         3         2         0\n    -1\n");
  r = run("correlate --measured " + bad.string());
  EXPECT_EQ(r.code, 65) << r.err;
  EXPECT_NE(r.err.find("bad.uff:9:1: dataset 58: ordinate data type must be"), std::string::npos) << r.err;
  const fs::path empty = write("empty.uff", "    -1\n   151\nname\ndesc\nprog\n    -1\n");
  r = run("correlate --measured " + empty.string());
  EXPECT_EQ(r.code, 65) << r.err;
  EXPECT_NE(r.err.find("no mode shapes (dataset 55) and no functions (58)"), std::string::npos) << r.err;
  r = run("correlate " + (fs::path(MMVLAB_SOURCE_DIR) / "scenes/hamsas.yaml").string() + " --measured " + bad.string());
  EXPECT_EQ(r.code, 64) << r.err;
  r = run("correlate --measured " + bad.string() + " --pair x=link1@0.5");
  EXPECT_EQ(r.code, 64) << r.err;
  EXPECT_TRUE(r.out.empty());
  r = run("correlate --measured " + bad.string() + " --pair-distance 0");
  EXPECT_EQ(r.code, 64) << r.err;
}

// The limits docs/outputs.md states: a file over 256 MB is refused before it is read
// (a sparse file: nothing is written to disk), and over 2000 nodes after it is parsed.
TEST_F(Correlate, MeasuredFileLimitsAreEnforced) {
  const fs::path huge = dir_ / "huge.uff";
  { std::ofstream(huge) << "    -1\n"; }
  fs::resize_file(huge, (256L << 20) + 1);
  Result r = run("correlate --measured " + huge.string());
  EXPECT_EQ(r.code, 66) << r.err;
  EXPECT_NE(r.err.find("above the limit"), std::string::npos) << r.err;
  std::string nodes = "    -1\n    15\n";
  char line[100];
  for (int k = 1; k <= 2001; ++k) {
    std::snprintf(line, sizeof line, "%10d%10d%10d%10d%13.5E%13.5E%13.5E\n", k, 0, 0, 8, 0.001 * k, 0.0, 0.0);
    nodes += line;
  }
  r = run("correlate --measured " + write("many.uff", nodes + "    -1\n").string());
  EXPECT_EQ(r.code, 65) << r.err;
  EXPECT_NE(r.err.find("2001 nodes, more than the 2000"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace mmv::cli_testing
