// Consistency through the command line, what each command prints two ways: its text
// against its JSON, row by row to the text's last digit (modes, check, simulate, frf,
// place-sensors, compare, correlate), and the shapes place-sensors places by against
// modes --points. Each disagreement fails with both values.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

#include "consistency/consistency_support.hpp"
#include "support/cli.hpp"

namespace mmv {
namespace {

using cli_testing::Result;
using cli_testing::slurp;
using consistency_testing::Consistency;
using consistency_testing::shippedScenes;
using consistency_testing::words;
using json = nlohmann::json;
namespace fs = std::filesystem;

// The text and the JSON of one run say the same: each mode's frequency in `modes`' table
// and each check line's demand, capacity, margin and verdict, to the text's digits, on
// every shipped article scene.
TEST_F(Consistency, TextAndJsonSayTheSame) {
  int lines = 0, modes = 0;
  for (const std::string& scene : shippedScenes()) {
    if (scene.find("hamsas") != std::string::npos) continue;
    SCOPED_TRACE(scene);
    const Result mt = run("modes " + scene + " --no-error-estimate"), mj = run("modes " + scene + " --no-error-estimate --json");
    ASSERT_EQ(mt.code, 0) << mt.err;
    const json mjs = json::parse(mj.out);
    for (const auto& m : mjs["modes"]) {
      if (!m["stable"].get<bool>()) continue;
      const std::string number = std::to_string(m["number"].get<int>());
      bool found = false;
      std::stringstream text(mt.out.substr(mt.out.find("System modes about the equilibrium")));
      for (std::string line; std::getline(text, line);) {
        const auto w = words(line);
        if (w.size() < 2 || w[0] != number) continue;
        EXPECT_NEAR(std::stod(w[1]), m["frequency_hz"].get<double>(), 5.01e-5) << line;
        found = true;
        ++modes;
        break;
      }
      EXPECT_TRUE(found) << "mode " << number;
    }
    const Result ct = run("check " + scene), cj = run("check " + scene + " --json");
    const json cjs = json::parse(cj.out);
    ASSERT_EQ(ct.code, cjs["overall"] == "FAIL" ? 3 : 0) << ct.err;  // a FAIL exits 3 (README)
    ASSERT_EQ(cj.code, ct.code);
    for (const auto& l : cjs["lines"]) {
      const std::string req = l["requirement"].get<std::string>();
      const auto at = ct.out.find("  " + req + "  ");
      if (at == std::string::npos || l["capacity"].is_null()) continue;  // a long requirement wraps; n/a lines
      const std::string line = ct.out.substr(at, ct.out.find('\n', at) - at);
      const auto w = words(line.substr(req.size() + 2));
      ASSERT_EQ(w.size(), 5u) << line;  // demand capacity unit margin verdict
      const double demand = l["demand"].get<double>(), capacity = l["capacity"].get<double>();
      EXPECT_NEAR(std::stod(w[0]), demand, 5e-4 * std::abs(demand) + 1e-12) << line;
      EXPECT_NEAR(std::stod(w[1]), capacity, 5e-4 * std::abs(capacity)) << line;
      EXPECT_EQ(w[2], l["unit"].get<std::string>()) << line;
      EXPECT_NEAR(std::stod(w[3]), l["margin_pct"].get<double>(), 0.051) << line;
      EXPECT_EQ(w[4], l["verdict"].get<std::string>()) << line;
      ++lines;
    }
  }
  EXPECT_GT(modes, 40);
  EXPECT_GT(lines, 20);
  std::printf("[consistency] text against JSON: %d mode frequencies, %d check lines, all equal to the text's digits\n", modes, lines);
}

// The shapes place-sensors places by, two ways: the AutoMAC it writes for its chosen
// triaxial blocks (automac.csv) and the AutoMAC of `modes --points` at the same
// stations, over every translation (a triaxial block's MAC does not depend on how
// the block is turned), on every shipped article scene and the spatial article.
TEST_F(Consistency, PlacementShapesAreModesShapesAtTheStations) {
  std::vector<std::string> cases;
  for (const std::string& scene : shippedScenes())
    if (scene.find("hamsas") == std::string::npos) cases.push_back(scene);
  cases.push_back("--set model=spatial");
  int compared = 0;
  for (const std::string& c : cases) {
    SCOPED_TRACE(c);
    const fs::path d = dir_ / ("place" + std::to_string(compared));
    // 4 segments a link: the two ways are compared on one model; the mesh is not in question.
    const Result p = run("place-sensors " + c + " --segments 4 --triaxial --count 6 --out " + d.string());
    ASSERT_EQ(p.code, 0) << p.err;
    const json placement = json::parse(slurp(d / "placement.json"));
    std::string points;
    for (const auto& ch : placement["chosen"]) points += (points.empty() ? "" : ",") + ch["station"].get<std::string>();
    const std::vector<int> target = placement["target_modes"].get<std::vector<int>>();
    const int last = *std::max_element(target.begin(), target.end());
    const Result m = run("modes " + c + " --segments 4 --no-error-estimate --json --modes " + std::to_string(last) + " --points " + points);
    ASSERT_EQ(m.code, 0) << m.err;
    const json modes = json::parse(m.out)["modes"];
    std::vector<std::vector<double>> phi;  // per target mode, every translation at every chosen station
    for (int t : target) {
      std::vector<double> v;
      for (const auto& at : modes[t - 1]["at_points"])
        for (const char* k : {"ux_per_modal_unit", "uy_per_modal_unit", "uz_per_modal_unit"})
          if (at.contains(k)) v.push_back(at[k].get<double>());
      ASSERT_EQ(modes[t - 1]["number"].get<int>(), t);
      phi.push_back(v);
    }
    std::stringstream csv(slurp(d / "automac.csv"));
    std::string line;
    std::getline(csv, line);  // header
    for (std::size_t i = 0; i < target.size(); ++i) {
      ASSERT_TRUE(static_cast<bool>(std::getline(csv, line)));
      std::stringstream cells(line);
      std::string cell;
      std::getline(cells, cell, ',');
      ASSERT_EQ(std::stoi(cell), target[i]) << line;
      for (std::size_t j = 0; j < target.size(); ++j) {
        ASSERT_TRUE(static_cast<bool>(std::getline(cells, cell, ','))) << line;
        double ij = 0, ii = 0, jj = 0;
        for (std::size_t k = 0; k < phi[i].size(); ++k) {
          ij += phi[i][k] * phi[j][k];
          ii += phi[i][k] * phi[i][k];
          jj += phi[j][k] * phi[j][k];
        }
        EXPECT_NEAR(std::stod(cell), ij * ij / (ii * jj), 2e-6) << "modes " << target[i] << ", " << target[j] << " at " << points;
      }
    }
    ++compared;
  }
  EXPECT_EQ(compared, static_cast<int>(cases.size()));
}

/// Whether `word`, a number as the text printed it, is `value` to the text's last digit.
::testing::AssertionResult printedAs(const std::string& word, double value) {
  const auto e = word.find_first_of("eE");
  const std::string mantissa = word.substr(0, e);
  const auto dot = mantissa.find('.');
  const int decimals = dot == std::string::npos ? 0 : static_cast<int>(mantissa.size() - dot - 1);
  const int exponent = e == std::string::npos ? 0 : std::stoi(word.substr(e + 1));
  const double ulp = std::pow(10.0, exponent - decimals);
  if (std::abs(std::stod(word) - value) <= 0.51 * ulp) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "text " << word << ", JSON " << value;
}

/// The line of `text` after `from` whose first words are `keys`, split into words.
std::vector<std::string> rowOf(const std::string& text, const std::string& from, const std::vector<std::string>& keys) {
  const auto at = text.find(from);
  if (at == std::string::npos) return {};
  std::stringstream ss(text.substr(at));
  for (std::string line; std::getline(ss, line);) {
    const auto w = words(line);
    if (w.size() >= keys.size() && std::equal(keys.begin(), keys.end(), w.begin())) return w;
  }
  return {};
}

// The text and the JSON of simulate, frf, place-sensors, compare and correlate say the
// same, row by row, to the text's last digit: simulate's torques and sensors, frf's
// pairs, the placement, compare's Tables 2 and 3 and its synthesis, correlate's pairs and
// FRACs.
TEST_F(Consistency, TextAndJsonOfTheOtherCommandsSayTheSame) {
  int values = 0;
  const std::string slew = std::string(MMVLAB_SOURCE_DIR) + "/scenes/mmv-slew.yaml --segments 4";
  const Result st = run("simulate " + slew), sj = run("simulate " + slew + " --json");
  ASSERT_EQ(st.code, 0) << st.err;
  const json sim = json::parse(sj.out);
  for (const auto& t : sim["torques"]) {
    const auto w = rowOf(st.out, "Torques the torquers must give", {t["joint"].get<std::string>()});
    ASSERT_EQ(w.size(), 4u) << t;
    EXPECT_TRUE(printedAs(w[1], t["peak_torque_n_m"].get<double>()));
    EXPECT_TRUE(printedAs(w[2], t["capacity_n_m"].get<double>()));
    EXPECT_EQ(w[3], t["exceeded"].get<bool>() ? "EXCEEDED" : "yes");
    values += 3;
  }
  for (const auto& x : sim["sensors"]) {
    const auto w = rowOf(st.out, "Sensors", {x["name"].get<std::string>()});
    ASSERT_EQ(w.size(), 6u) << x;
    EXPECT_EQ(w[1], x["type"].get<std::string>());
    EXPECT_EQ(w[2], x["unit"].get<std::string>());
    EXPECT_EQ(std::stoi(w[3]), x["saturated_samples"].get<int>());
    EXPECT_EQ(std::stoi(w[5]), x["samples"].get<int>());
    values += 4;
  }
  const Result ft = run("frf"), fj = run("frf --json");
  ASSERT_EQ(ft.code, 0) << ft.err;
  const json frf = json::parse(fj.out);
  for (const auto& p : frf["pairs"]) {
    const auto w = rowOf(ft.out, "peak_zeta_%", {p["output"].get<std::string>(), p["output_unit"].get<std::string>(),
                                                 p["input"].get<std::string>(), p["input_unit"].get<std::string>()});
    ASSERT_EQ(w.size(), 11u) << p;
    EXPECT_TRUE(printedAs(w[4], p["peak_hz"].get<double>())) << w[0] << "/" << w[2];
    EXPECT_TRUE(printedAs(w[5], p["peak_db"].get<double>())) << w[0] << "/" << w[2];
    if (w[6] != "-") EXPECT_TRUE(printedAs(w[6], 100 * p["peak_half_power_damping"].get<double>())) << w[0] << "/" << w[2];
    EXPECT_TRUE(printedAs(w[7], p["at_10_hz_db"].get<double>())) << w[0] << "/" << w[2];
    EXPECT_TRUE(printedAs(w[8], 100 * p["rom_relative_error"].get<double>())) << w[0] << "/" << w[2];
    EXPECT_TRUE(printedAs(w[9], 100 * p["rom_local_error"].get<double>())) << w[0] << "/" << w[2];
    EXPECT_TRUE(printedAs(w[10], p["rom_local_error_hz"].get<double>())) << w[0] << "/" << w[2];
    values += 7;
  }
  for (const char* method : {"efi", "mke"}) {
    const Result pt = run(std::string("place-sensors --method ") + method),
                 pj = run(std::string("place-sensors --json --method ") + method);
    ASSERT_EQ(pt.code, 0) << pt.err;
    const json place = json::parse(pj.out);
    ASSERT_FALSE(place["chosen"].empty());
    for (const auto& c : place["chosen"]) {
      const auto w = rowOf(pt.out, "station", {c["station"].get<std::string>(), c["axis"].get<std::string>()});
      ASSERT_EQ(w.size(), 6u) << c;
      EXPECT_TRUE(printedAs(w[2], c["world_x_m"].get<double>())) << w[0];
      EXPECT_TRUE(printedAs(w[3], c["world_y_m"].get<double>())) << w[0];
      EXPECT_TRUE(printedAs(w[4], c["world_z_m"].get<double>())) << w[0];
      EXPECT_NEAR(std::stod(w[5]), c["score"].get<double>(), 5e-4 * std::abs(c["score"].get<double>())) << w[0];
      values += 4;
    }
  }
  // compare: Table 2's component modes with their closed forms, Table 3's system modes,
  // and each synthesis row (assumed modes and Craig-Bampton).
  const Result ct = run("compare"), cj = run("compare --json");
  ASSERT_EQ(ct.code, 0) << ct.err;
  const json cmp = json::parse(cj.out);
  const auto unparen = [](std::string w) { return w.substr(w.front() == '(', w.size() - (w.front() == '(') - (w.back() == ')')); };
  for (const auto& c : cmp["component_modes"]) {
    const auto w = rowOf(ct.out, "Table 2", {c["link"].get<std::string>()});
    ASSERT_EQ(w.size(), 3 + 2 * c["modes"].size()) << c["link"];
    EXPECT_TRUE(printedAs(w[1], c["tip_mass_kg"].get<double>()));
    EXPECT_TRUE(printedAs(w[2], c["mass_ratio"].get<double>()));
    for (std::size_t k = 0; k < c["modes"].size(); ++k) {
      EXPECT_TRUE(printedAs(w[3 + 2 * k], c["modes"][k]["frequency_hz"].get<double>())) << c["link"] << " mode " << k + 1;
      EXPECT_TRUE(printedAs(unparen(w[4 + 2 * k]), c["modes"][k]["closed_form_hz"].get<double>())) << c["link"] << " mode " << k + 1;
      values += 2;
    }
  }
  for (const auto& m : cmp["system_modes"]) {
    const auto w = rowOf(ct.out, "Table 3", {std::to_string(m["mode"].get<int>())});
    ASSERT_GE(w.size(), 10u) << m;
    EXPECT_TRUE(printedAs(w[1], m["frequency_hz"].get<double>()));
    EXPECT_EQ(w[2], m["strain_link"].get<std::string>());
    EXPECT_TRUE(printedAs(w.back(), 100 * m["system_over_component_minus_1"].get<double>()));
    values += 3;
  }
  const json& am = cmp["synthesis"]["assumed_modes"]["modes"];
  const json& cb = cmp["synthesis"]["craig_bampton"]["modes"];
  ASSERT_EQ(am.size(), cb.size());
  for (std::size_t i = 0; i < am.size(); ++i) {
    const auto w = rowOf(ct.out, "Synthesis from component modes", {std::to_string(am[i]["mode"].get<int>())});
    ASSERT_EQ(w.size(), 11u) << am[i];
    EXPECT_TRUE(printedAs(w[1], am[i]["full_frequency_hz"].get<double>()));
    for (const auto& [row, at] : {std::pair<const json*, int>{&am[i], 3}, {&cb[i], 7}}) {
      EXPECT_TRUE(printedAs(w[at], (*row)["synthesized_frequency_hz"].get<double>())) << w[0];
      EXPECT_TRUE(printedAs(w[at + 1], 100 * (*row)["relative_error"].get<double>())) << w[0];
      EXPECT_TRUE(printedAs(w[at + 2], (*row)["mac"].get<double>())) << w[0];
      EXPECT_EQ(w[at + 3], (*row)["verdict"].get<std::string>()) << w[0];
      values += 4;
    }
  }
  // correlate: the committed measured set against the table scene, every pair and FRAC row.
  const std::string corr = std::string(MMVLAB_SOURCE_DIR) + "/scenes/mmv-table.yaml --measured " + MMVLAB_SOURCE_DIR +
                           "/docs/figures/correlate/measured.uff";
  const Result rt = run("correlate " + corr), rj = run("correlate " + corr + " --json");
  ASSERT_EQ(rt.code, 0) << rt.err;
  const json cor = json::parse(rj.out);
  const auto zetaOf = [](const json& list, const std::string& label) {
    for (const auto& m : list)
      if (m["label"] == label) return m["damping_ratio"].get<double>();
    return std::nan("");
  };
  ASSERT_FALSE(cor["pairs"].empty());
  for (const auto& p : cor["pairs"]) {
    const auto w = rowOf(rt.out, "freq_error_%", {p["test"].get<std::string>()});
    ASSERT_EQ(w.size(), 8u) << p;
    EXPECT_TRUE(printedAs(w[1], p["test_hz"].get<double>())) << w[0];
    EXPECT_TRUE(printedAs(w[2], 100 * zetaOf(cor["test_modes"], w[0]))) << w[0];
    EXPECT_EQ(w[3], p["model"].get<std::string>());
    EXPECT_TRUE(printedAs(w[4], p["model_hz"].get<double>())) << w[0];
    EXPECT_TRUE(printedAs(w[5], 100 * zetaOf(cor["model_modes"], w[3]))) << w[0];
    EXPECT_TRUE(printedAs(w[6], 100 * p["frequency_error"].get<double>())) << w[0];
    EXPECT_TRUE(printedAs(w[7], p["mac"].get<double>())) << w[0];
    values += 7;
  }
  for (const auto& f : cor["frfs"]) {
    const auto w = rowOf(rt.out, "FRAC of the model's", {std::to_string(f["function"].get<int>())});
    ASSERT_EQ(w.size(), 10u) << f;  // the id is "output / input"
    EXPECT_EQ(w[1] + " " + w[2] + " " + w[3], f["id"].get<std::string>());
    EXPECT_EQ(w[4], f["output"].get<std::string>());
    EXPECT_TRUE(printedAs(w[6], f["frac"].get<double>())) << w[0];
    EXPECT_EQ(w[7], f["frac_verdict"].get<std::string>()) << w[0];
    EXPECT_TRUE(printedAs(w[8], f["test_peak_hz"].get<double>())) << w[0];
    EXPECT_TRUE(printedAs(w[9], f["model_peak_hz"].get<double>())) << w[0];
    values += 6;
  }
  EXPECT_GT(values, 400);
  std::printf("[consistency] text against JSON of simulate, frf, place-sensors, compare and correlate: %d values equal "
              "to the text's digits\n", values);
}

}  // namespace
}  // namespace mmv
