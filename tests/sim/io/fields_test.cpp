// Field lists (sim/io/fields.hpp). The per-mode list (sim/io/mode_fields.hpp) drives modes.json's mode records and
// modes.csv: on a damped planar, a spatial and an unstable scene, each record holds
// exactly the fields that apply (in the list's order, then the shapes), the CSV header
// is the CSV fields that apply, and every cell read back from the CSV equals the JSON
// value to the digits its format prints: the same number computed two ways.
#include "sim/io/mode_fields.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <fstream>
#include <set>
#include <sstream>

#include "sim/core/text.hpp"
#include "sim/io/report.hpp"
#include "sim/io/check_report.hpp"
#include "sim/io/config_sweep_report.hpp"
#include "sim/io/placement_report.hpp"
#include "sim/io/trade_report.hpp"
#include "sim/plan/check.hpp"
#include "support/field_checks.hpp"
#include "support/scenes.hpp"

namespace mmv {
namespace {

using namespace field_checks;

void expectJsonAndCsvAgree(const ModesReport& r, const std::string& what) {
  const json doc = modesToJson(r);
  std::vector<std::string> keys, columns;
  for (const auto& f : modeFields()) {
    if (!modeFieldApplies(f, r)) continue;
    keys.push_back(f.key);
    if (f.csv_format) columns.push_back(f.key);
  }
  std::istringstream csv(modesCsv(r));
  std::string line;
  ASSERT_TRUE(std::getline(csv, line));
  EXPECT_EQ(splitCsvLine(line), columns) << what;
  ASSERT_EQ(doc["modes"].size(), r.modes.size());
  for (std::size_t i = 0; i < r.modes.size(); ++i) {
    const json& rec = doc["modes"][i];
    std::vector<std::string> got;
    for (const auto& [k, v] : rec.items())
      if (k != "shape" && k != "at_points" && k != "stress_per_mm_of_peak") got.push_back(k);  // lists, not fields
    // The record's keys are the applying fields in order, less those this mode has not.
    std::size_t at = 0;
    for (const auto& k : got) {
      while (at < keys.size() && keys[at] != k) ++at;
      EXPECT_LT(at, keys.size()) << what << ": mode " << i + 1 << " key " << k << " not in the field list, or out of order";
    }
    ASSERT_TRUE(std::getline(csv, line)) << what;
    const std::vector<std::string> cells = splitCsvLine(line);
    ASSERT_EQ(cells.size(), columns.size()) << what << ": " << line;
    for (std::size_t c = 0; c < columns.size(); ++c) {
      const ModeField* f = nullptr;
      for (const auto& x : modeFields())
        if (columns[c] == x.key) f = &x;
      const std::string where = what + ": mode " + std::to_string(i + 1) + " " + columns[c];
      if (!rec.contains(columns[c]) || rec[columns[c]].is_null()) {
        EXPECT_EQ(cells[c], "") << where;
        continue;
      }
      const json& v = rec[columns[c]];
      if (v.is_boolean()) EXPECT_EQ(cells[c], v.get<bool>() ? "1" : "0") << where;
      else if (v.is_string()) EXPECT_EQ(cells[c], csvEscape(v.get<std::string>())) << where;
      else if (v.is_number_integer()) EXPECT_EQ(std::stol(cells[c]), v.get<long>()) << where;
      else EXPECT_NEAR(std::stod(cells[c]), v.get<double>(), precisionOf(f->csv_format) * std::abs(v.get<double>()) + 1e-300) << where;
    }
  }
}

TEST(ModeFields, JsonAndCsvComeFromOneListOnADampedPlanarScene) {
  ArticleScene s = loadArticleSceneFile(std::string(MMVLAB_SOURCE_DIR) + "/scenes/mmv-table.yaml");
  overrideSegments(s, 4);
  ModesOptions o;
  o.damping = s.damping;
  ASSERT_TRUE(o.damping.has_value());
  const ModesReport r = runModes(s, o);
  ASSERT_TRUE(r.damped);
  expectJsonAndCsvAgree(r, "table scene");
  EXPECT_NE(modesCsv(r).find(",damping_ratio,"), std::string::npos);
  EXPECT_EQ(modesCsv(r).find("effective_mass_z_kg"), std::string::npos);  // a planar model's CSV has no z
}

TEST(ModeFields, JsonAndCsvComeFromOneListOnASpatialScene) {
  ArticleScene s = loadDefaultScene();
  s.article.model = ArticleModel::Spatial;
  overrideSegments(s, 2);
  const ModesReport r = runModes(s);
  ASSERT_TRUE(r.spatial);
  expectJsonAndCsvAgree(r, "spatial");
  EXPECT_NE(modesCsv(r).find("effective_mass_z_kg"), std::string::npos);
  EXPECT_EQ(modesCsv(r).find("damping_ratio"), std::string::npos);  // undamped: no damping column
}

TEST(ModeFields, AnUnstableModeHasAnEmptyFrequencyAndItsGrowthRate) {
  ArticleScene s = testing::chainScene(1, 1.0, 2.0, 9.81, 0.0, 1.0);
  s.article.base.direction = M_PI / 2;  // an upright pendulum on a free joint
  const ModesReport r = runModes(s);
  ASSERT_FALSE(r.modes.at(0).stable);
  expectJsonAndCsvAgree(r, "upright pendulum");
  const json rec = modesToJson(r)["modes"][0];
  EXPECT_TRUE(rec["frequency_hz"].is_null());
  EXPECT_NEAR(rec["growth_rate_per_s"].get<double>(), std::sqrt(-r.modes[0].omega2), 1e-12);
}

TEST(ModeFields, EveryFieldIsDescribed) {
  std::set<std::string> seen;
  for (const auto& f : modeFields()) {
    EXPECT_TRUE(seen.insert(f.key).second) << f.key << " twice";
    EXPECT_EQ(csvColumnName(f.key), f.key) << "a key that pandas, numpy and MATLAB keep as it is";
    EXPECT_GT(std::string(f.meaning).size(), 10u) << f.key;
    EXPECT_NE(f.get, nullptr) << f.key;
  }
}

// docs/outputs.md's field table is the list, row for row (a field added, renamed or
// re-described without the docs fails here).
TEST(ModeFields, TheDocsTableIsTheList) {
  std::ifstream in(std::string(MMVLAB_SOURCE_DIR) + "/docs/outputs.md");
  std::stringstream text;
  text << in.rdbuf();
  const std::string docs = text.str();
  const auto at = docs.find("| key | unit | in modes.csv | applies | meaning |");
  ASSERT_NE(at, std::string::npos);
  std::istringstream rows(docs.substr(at));
  std::string line;
  std::getline(rows, line);
  std::getline(rows, line);  // |---|
  for (const auto& f : modeFields()) {
    ASSERT_TRUE(std::getline(rows, line));
    const char* applies = f.applies == ModeField::Applies::Always ? "always" : f.applies == ModeField::Applies::Spatial ? "spatial" : "damped";
    EXPECT_EQ(line, strf("| `%s` | %s | %s | %s | %s |", f.key, *f.unit ? f.unit : "-", f.csv_format ? "yes" : "JSON only", applies,
                         f.meaning));
  }
  ASSERT_TRUE(std::getline(rows, line));
  EXPECT_EQ(line.rfind("|", 0), std::string::npos) << "a row the list does not have: " << line;
}

// A configuration sweep's tracks: sweep.json's points[].tracks[] and sweep.csv's track
// columns from trackFields(), on the default article over joint2.
TEST(TrackFields, JsonAndCsvComeFromOneList) {
  ArticleScene s = loadDefaultScene();
  overrideSegments(s, 2);
  ConfigSweepOptions o;
  o.axes.push_back({"joint2", 0, 20, 10});
  o.modes = 3;
  const ConfigSweepResult r = runConfigSweep(s, o);
  const json doc = configSweepJson(r);
  std::istringstream csv(configSweepCsv(r));
  std::string line;
  ASSERT_TRUE(std::getline(csv, line));
  std::vector<std::string> columns;
  for (const auto& f : trackFields()) columns.push_back(f.key);
  std::vector<std::string> header = {"joint2_deg", "point_kind", "track"};
  header.insert(header.end(), columns.begin(), columns.end());
  EXPECT_EQ(splitCsvLine(line), header);
  int rows = 0;
  for (const auto& p : doc["points"])
    for (const auto& t : p["tracks"]) {
      ASSERT_TRUE(std::getline(csv, line));
      const std::vector<std::string> cells = splitCsvLine(line);
      EXPECT_EQ(std::stod(cells.at(0)), p["angles_deg"][0].get<double>());
      expectCellsAreTheRecord(cells, 3, columns, t, 5e-6, 5e-7);
      EXPECT_EQ(t.size(), columns.size());  // every field, no other key
      ++rows;
    }
  EXPECT_EQ(rows, 9);
}

// The trade's runs: trade.json's records and trade.csv from tradeRunFields(), on a run
// with numbers and one without (its numbers empty in the CSV, absent in the JSON).
TEST(TradeRunFields, JsonAndCsvComeFromOneList) {
  TradeStudy s;
  TradeRun ok{"rk3", 1e-5, 4, 0, true, "ok", "", 1.234567e-4, 0.5, 42, true, true};
  TradeRun cut{"cpodes", 1e-7, 0, 2, false, "over_budget", "cut at 2 s, a \"budget\", here", 0, 0, 0, false, true};
  s.runs = {ok, cut};
  const json runs = tradeJson(s, 1e-3)["runs"];
  std::istringstream csv(tradeCsv(s));
  std::string line;
  const std::vector<std::string> columns = headerIsTheFieldKeys(csv, tradeRunFields());
  for (std::size_t i = 0; i < s.runs.size(); ++i) {
    ASSERT_TRUE(std::getline(csv, line));
    const std::vector<std::string> cells = splitCsvLine(line);
    ASSERT_EQ(cells.size(), columns.size()) << line;
    expectCellsAreTheRecord(cells, 0, columns, runs[i], 1e-5);
  }
  EXPECT_EQ(runs[0]["tip_error_m"].get<double>(), 1.234567e-4);
  EXPECT_FALSE(runs[1].contains("tip_error_m"));
  EXPECT_EQ(runs[1]["failure"], "cut at 2 s, a \"budget\", here");
  EXPECT_FALSE(runs[0].contains("failure"));
}

// check's lines: check.json's records and check.csv from checkLineFields(), on the
// table scene (lines with and without a capacity; text escaped as in every CSV).
TEST(CheckLineFields, JsonAndCsvComeFromOneList) {
  ArticleScene s = loadArticleSceneFile(std::string(MMVLAB_SOURCE_DIR) + "/scenes/mmv-table.yaml");
  overrideSegments(s, 4);
  const CheckReport r = runCheck(s);
  const json lines = checkJson(r)["lines"];
  std::istringstream csv(checkCsv(r));
  std::string line;
  const std::vector<std::string> columns = headerIsTheFieldKeys(csv, checkLineFields());
  ASSERT_EQ(lines.size(), r.lines.size());
  int with_capacity = 0, without = 0;
  for (std::size_t i = 0; i < r.lines.size(); ++i) {
    ASSERT_TRUE(std::getline(csv, line));
    const std::vector<std::string> cells = splitCsvLine(line);
    expectCellsAreTheRecord(cells, 0, columns, lines[i], 1e-7);
    EXPECT_EQ(lines[i].size(), columns.size());  // every field, no other key
    (r.lines[i].has_capacity ? with_capacity : without) += 1;
  }
  EXPECT_GE(with_capacity, 5);
  EXPECT_GT(without, 0);
  EXPECT_FALSE(std::getline(csv, line));
  std::printf("[fields] check: %zu lines (%d with a capacity) the same in JSON and CSV\n", r.lines.size(), with_capacity);
}


// A placement's candidates: candidates.csv's rows and placement.json's chosen records from
// placementFields(): every chosen record is its CSV row (less `chosen`), in the order kept.
TEST(PlacementFields, JsonAndCsvComeFromOneList) {
  ArticleScene s = loadDefaultScene();
  overrideSegments(s, 4);
  PlacementOptions o;
  o.count = 6;
  o.modes = modeNumbers({1, 2, 3});
  const PlacementStudy p = runPlacement(s, o);
  const json chosen = placementJson(p)["chosen"];
  std::istringstream csv(placementCandidatesCsv(p));
  std::string line;
  const std::vector<std::string> columns = headerIsTheFieldKeys(csv, placementFields());
  std::vector<std::string> record = columns;
  record.erase(record.begin() + 7);  // `chosen`: not in a record
  std::map<std::string, std::vector<std::string>> rows;  // chosen rows by station and axis
  std::size_t n = 0;
  for (; std::getline(csv, line); ++n) {
    std::vector<std::string> cells = splitCsvLine(line);
    ASSERT_EQ(cells.size(), columns.size()) << line;
    if (cells[7] == "1") rows[cells[0] + " " + cells[3]] = cells;
    else EXPECT_EQ(cells[8], "") << line;  // no score unless chosen
  }
  EXPECT_EQ(n, p.candidates.size());
  ASSERT_EQ(chosen.size(), 6u);
  ASSERT_EQ(rows.size(), 6u);
  for (std::size_t i = 0; i < chosen.size(); ++i) {
    const json& c = chosen[i];
    EXPECT_EQ(c.size(), record.size());
    EXPECT_EQ(c["station"], p.candidates[p.result.kept_blocks[i]].station);  // in the order kept
    std::vector<std::string> cells = rows.at(c["station"].get<std::string>() + " " + c["axis"].get<std::string>());
    cells.erase(cells.begin() + 7);
    expectCellsAreTheRecord(cells, 0, record, c, 1e-5);
  }
}


}  // namespace
}  // namespace mmv
