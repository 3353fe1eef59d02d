// Field lists of correlate, converge, HAM-SAS's modes and compare (sim/io/fields.hpp):
// each JSON record, CSV row and text table cell comes from one list, and each is checked
// here against the others, value by value.
#include <gtest/gtest.h>

#include <iterator>
#include <sstream>

#include "sim/io/compare_fields.hpp"
#include "sim/io/convergence_fields.hpp"
#include "sim/io/correlation_report.hpp"
#include "sim/io/hamsas_report.hpp"
#include "sim/io/report.hpp"
#include "sim/io/report_compare.hpp"
#include "sim/modes/converge.hpp"
#include "sim/scene/scene.hpp"
#include "support/field_checks.hpp"

namespace mmv {
namespace {

using namespace field_checks;

// correlate's pairs: correlation.json's pairs, pairs.csv and the text table from
// correlationPairFields(), on a damped model (a model damping ratio) and a pair whose
// model mode has none (null in JSON, empty in the CSV, "-" in the text).
TEST(CorrelationPairFields, JsonCsvAndTextComeFromOneList) {
  CorrelationResult r;
  r.test_modes = {{1, 2.0, 0.02, {}, {}}, {2, 5.0, 0.01, {}, {}}};
  ModeInfo m1, m2;
  m1.number = ModeNumber(1), m1.frequency_hz = 2.04, m1.has_damping = true, m1.damping_ratio = 0.015;
  m2.number = ModeNumber(3), m2.frequency_hz = 4.9, m2.has_damping = false;
  r.model_modes = {m1, m2};
  r.model_damped = true;
  r.damping_model = "modal";
  r.mac = Eigen::MatrixXd::Identity(2, 2);
  r.pairs = {{0, 0, 0.987654}, {1, 1, 0.912345}};
  ArticleScene scene = loadDefaultScene();
  const json pairs = correlationJson(scene, r)["pairs"];
  std::istringstream csv(correlationPairsCsv(r));
  const std::vector<std::string> columns = headerIsTheFieldKeys(csv, correlationPairFields());
  std::string line;
  ASSERT_EQ(pairs.size(), 2u);
  for (const auto& rec : pairs) {
    ASSERT_TRUE(std::getline(csv, line));
    expectCellsAreTheRecord(splitCsvLine(line), 0, columns, rec, 1e-5, 1e-6);
    EXPECT_EQ(rec.size(), columns.size());
  }
  EXPECT_NEAR(pairs[0]["frequency_error"].get<double>(), 0.02, 1e-12);  // 2.04 / 2 - 1
  EXPECT_NEAR(pairs[1]["frequency_error"].get<double>(), -0.02, 1e-12);
  EXPECT_NEAR(pairs[0]["model_damping_ratio"].get<double>(), 0.015, 1e-15);
  EXPECT_TRUE(pairs[1]["model_damping_ratio"].is_null());
  // The text table's rows, cell by cell: the same values in the text's units (%).
  std::istringstream text(correlationText(scene, r));
  std::vector<std::vector<std::string>> rows;
  for (std::string l; std::getline(text, l);) {
    std::istringstream words(l);
    std::vector<std::string> cells{std::istream_iterator<std::string>(words), {}};
    if (!cells.empty() && (cells[0] == "T1" || cells[0] == "T2")) rows.push_back(cells);
  }
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0], (std::vector<std::string>{"T1", "2.0000", "2", "M1", "2.0400", "1.5", "+2.00", "0.988"}));
  EXPECT_EQ(rows[1], (std::vector<std::string>{"T2", "5.0000", "1", "M3", "4.9000", "-", "-2.00", "0.912"}));
}

// converge's ladder: converge.csv's rows carry each mode's record (converge.json) and
// the record's per-run values; the discretization estimate of `modes` writes the same
// record (one list, one "unchecked" for a mode without an estimate).
TEST(ConvergenceFields, CsvRowsAreTheModeRecordsRunByRun) {
  ArticleScene s = loadDefaultScene();
  const ConvergenceStudy c = runConvergence(s, 4, 3);
  const json doc = convergenceToJson(c);
  std::istringstream csv(convergenceCsv(c));
  const std::vector<std::string> columns = headerIsTheFieldKeys(csv, convergencePointFields());
  std::string line;
  int rows = 0;
  for (const auto& rec : doc["modes"])
    for (std::size_t k = 0; k < c.runs.size(); ++k) {
      ASSERT_TRUE(std::getline(csv, line));
      const std::vector<std::string> cells = splitCsvLine(line);
      json point = {{"mode", rec["number"]},
                    {"segments", doc["runs"][k]["segments"]},
                    {"dofs", doc["runs"][k]["dofs"]},
                    {"frequency_hz", rec["frequency_hz_by_run"][k]},
                    {"relative_error", rec["relative_error_by_run"][k]},
                    {"richardson_hz", rec["richardson_hz"]},
                    {"observed_order", rec["observed_order"]},
                    {"check", rec["check"]}};
      expectCellsAreTheRecord(cells, 0, columns, point, 2e-4, 1e-6);  // observed_order keeps 4 digits
      ++rows;
    }
  EXPECT_EQ(rows, 9);  // 3 modes at 1, 2 and 4 segments
  EXPECT_FALSE(std::getline(csv, line));
  std::vector<std::string> keys;
  for (const auto& f : convergenceModeFields()) keys.push_back(f.key);
  keys.push_back("relative_error_by_run");
  std::vector<std::string> got;
  for (const auto& [k, v] : doc["modes"][0].items()) got.push_back(k);
  EXPECT_EQ(got, keys);
  DiscretizationEstimate d;
  d.available = true;
  d.modes = {assessLadder(ModeNumber(1), {1.0})};  // one run: no estimate
  const json est = discretizationJson(d)["modes"][0];
  EXPECT_EQ(est["check"], "unchecked");
  EXPECT_EQ(est.size(), convergenceModeFields().size());
}

// HAM-SAS's modes: modes.json's records and modes.csv from hamsasModeFields().
TEST(HamsasModeFields, JsonAndCsvComeFromOneList) {
  const HamsasScene h = loadHamsasSceneFile(std::string(MMVLAB_SOURCE_DIR) + "/scenes/hamsas.yaml");
  const HamsasModes m = analyseHamsas(h.isolator);
  const json modes = hamsasModesJson(h, m, 8)["modes"];
  std::istringstream csv(hamsasModesCsv(m, 8));
  std::string line;
  ASSERT_TRUE(std::getline(csv, line));
  const std::vector<std::string> columns = csvKeys(hamsasModeFields());
  EXPECT_EQ(splitCsvLine(line), columns);
  ASSERT_EQ(modes.size(), 8u);
  for (const auto& rec : modes) {
    ASSERT_TRUE(std::getline(csv, line));
    expectCellsAreTheRecord(splitCsvLine(line), 0, columns, rec, 1e-7, 1e-6);
    EXPECT_EQ(rec.size(), hamsasModeFields().size());
    double kinetic = 0;
    for (const auto& [k, v] : rec["kinetic_share"].items()) kinetic += v.get<double>();
    EXPECT_NEAR(kinetic, 1.0, 1e-6);  // the groups' shares (not the directions') sum to one
  }
  EXPECT_FALSE(std::getline(csv, line));
}


// compare's system modes and synthesized modes: compare.json's records, system_modes.csv
// and synthesis.csv from systemModeFields() and synthesisFields(), on the spatial model
// (a family per mode: a CSV column of the system modes, JSON only for the synthesis).
TEST(CompareFields, JsonAndCsvComeFromOneList) {
  ArticleScene s = std::get<ArticleScene>(parseScene(defaultSceneYaml(), "<default scene>", {"model=spatial"}));
  overrideSegments(s, 2);
  CompareOptions o;
  o.system_modes = 6;
  const CompareReport r = runCompare(s, o);
  const json doc = compareToJson(r);
  std::string system_csv, synthesis_csv;
  for (const auto& [name, text] : compareCsvFiles(r)) {
    if (name == "system_modes.csv") system_csv = text;
    if (name == "synthesis.csv") synthesis_csv = text;
  }
  std::istringstream sys(system_csv);
  const std::vector<std::string> columns = csvKeys(systemModeFields());
  std::string line;
  ASSERT_TRUE(std::getline(sys, line));
  EXPECT_EQ(splitCsvLine(line), columns);  // the spatial model's family included
  ASSERT_EQ(doc["system_modes"].size(), r.system.size());
  for (const auto& rec : doc["system_modes"]) {
    ASSERT_TRUE(std::getline(sys, line));
    expectCellsAreTheRecord(splitCsvLine(line), 0, columns, rec, 1e-5, 1e-6);
    EXPECT_TRUE(rec.contains("stable") && rec.contains("family"));
  }
  std::istringstream syn(synthesis_csv);
  const std::vector<std::string> syn_columns = csvKeys(synthesisFields());
  ASSERT_TRUE(std::getline(syn, line));
  EXPECT_EQ(splitCsvLine(line), syn_columns);
  int rows = 0;
  for (const char* method : {"assumed_modes", "craig_bampton"})
    for (json rec : doc["synthesis"][method]["modes"]) {
      EXPECT_FALSE(rec.contains("method"));  // the rows sit under their method
      EXPECT_TRUE(rec.contains("family"));
      rec["method"] = csvEscape(doc["synthesis"][method]["method"].get<std::string>());
      ASSERT_TRUE(std::getline(syn, line));
      expectCellsAreTheRecord(splitCsvLine(line), 0, syn_columns, rec, 1e-5, 1e-6);
      ++rows;
    }
  EXPECT_EQ(rows, static_cast<int>(r.assumed.rows.size() + r.craig_bampton.rows.size()));
  EXPECT_GT(rows, 0);
}

}  // namespace
}  // namespace mmv
