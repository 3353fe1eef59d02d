// `mmvlab update` end to end: a "measured" set written by `frf --out` from the table
// scene with link 2's modulus +8 % (its own material here) and link 1's tip mass -5 %;
// the update's outputs against each other (JSON and CSV from one field list), the updated
// scene against the input (only the parameters' lines differ), `correlate` on the
// updated scene (a second route to the "after"), and the refused requests with their
// exit codes and nothing written.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <regex>
#include <sstream>

#include "support/cli.hpp"

namespace mmv::cli_testing {
namespace {

using json = nlohmann::json;

class Update : public Cli {
 protected:
  fs::path scene(const std::string& name, const std::string& e, const std::string& tip) {
    std::string s = slurp(fs::path(MMVLAB_SOURCE_DIR) / "scenes/mmv-table.yaml");
    s = std::regex_replace(s, std::regex("\nmaterials:\n"), "\nmaterials:\n  cc_link2: {density: 1650, youngs_modulus: " + e + "}\n");
    const auto l2 = s.find("name: link2"), m = s.find("material:", l2);
    s.replace(m, s.find('\n', m) - m, "material: cc_link2");
    const auto l1 = s.find("name: link1"), seg = s.find('\n', s.find("segments:", l1));
    s.insert(seg, "\n    tip_mass: {mass: " + tip + "}");
    return write(name, s);
  }
  void SetUp() override {
    Cli::SetUp();
    nominal_ = scene("nominal.yaml", "41.4e9", "2.0").string();
    const Result r = run("frf " + scene("test.yaml", "44.712e9", "1.9").string() + " --segments 6 --out " + (dir_ / "m").string());
    ASSERT_EQ(r.code, 0) << r.err;
    measured_ = (dir_ / "m" / "frf.uff").string();
  }
  std::string update(const std::string& params) const {
    return "update " + nominal_ + " --segments 6 --measured " + measured_ + " --modes 12 --params " + params;
  }
  std::string nominal_, measured_;
};

TEST_F(Update, RecoversTheKnownChangeAndWritesTheUpdatedScene) {
  const fs::path out = dir_ / "u";
  const Result r = run(update("materials.cc_link2.youngs_modulus,links.link1.tip_mass.mass") + " --out " + out.string());
  ASSERT_EQ(r.code, 0) << r.err;
  const json j = json::parse(slurp(out / "update.json"));
  EXPECT_TRUE(j["converged"].get<bool>());
  EXPECT_NEAR(j["parameters"][0]["updated"].get<double>() / 44.712e9, 1, 1e-4);
  EXPECT_NEAR(j["parameters"][1]["updated"].get<double>() / 1.9, 1, 1e-4);
  // parameters.csv holds the JSON's records, field by field (one list makes both).
  std::istringstream csv(slurp(out / "parameters.csv"));
  std::string header, row;
  std::getline(csv, header);
  EXPECT_EQ(header, "key,line,nominal,lower,upper,updated,change,standard_error,interval_low,interval_high,at_bound,determined");
  for (int k = 0; k < 2; ++k) {
    ASSERT_TRUE(std::getline(csv, row));
    std::vector<std::string> cells;
    std::stringstream ss(row);
    for (std::string c; std::getline(ss, c, ',');) cells.push_back(c);
    ASSERT_EQ(cells.size(), 12u) << row;
    EXPECT_EQ(cells[0], j["parameters"][k]["key"].get<std::string>());
    EXPECT_EQ(std::stod(cells[5]), j["parameters"][k]["updated"].get<double>());  // %.17g: exact
    EXPECT_NEAR(std::stod(cells[8]), j["parameters"][k]["interval_low"].get<double>(), 1e-9 * std::abs(std::stod(cells[8])));
  }
  // The updated scene: the nominal's text with two lines changed, each commented.
  std::istringstream a(slurp(nominal_)), b(slurp(out / "updated_scene.yaml"));
  int changed = 0;
  for (std::string x, y; std::getline(a, x) && std::getline(b, y);)
    if (x != y) {
      ++changed;
      EXPECT_NE(y.find("# mmvlab update: nominal"), std::string::npos) << y;
    }
  EXPECT_EQ(changed, 2);
  // correlate on the updated scene: the "after" by a second route, the same errors.
  const Result c = run("correlate " + (out / "updated_scene.yaml").string() + " --segments 6 --modes 12 --json --measured " + measured_);
  ASSERT_EQ(c.code, 0) << c.err;
  const json cj = json::parse(c.out);
  ASSERT_EQ(cj["pairs"].size(), j["pairs"].size());
  for (std::size_t k = 0; k < cj["pairs"].size(); ++k)
    EXPECT_NEAR(cj["pairs"][k]["model_hz"].get<double>(), j["pairs"][k]["after_hz"].get<double>(), 1e-9) << k;
  for (const char* f : {"pairs.csv", "iterations.csv", "frequency_errors.png", "mac.png", "iterations.png"}) EXPECT_TRUE(fs::exists(out / f)) << f;
}

TEST_F(Update, RefusedRequestsExitWithTheirCodeAndWriteNothing) {
  const fs::path out = dir_ / "never";
  const auto refused = [&](const std::string& args, int code, const std::string& says) {
    const Result r = run(args + " --out " + out.string());
    EXPECT_EQ(r.code, code) << args << "\n" << r.err;
    EXPECT_NE(r.err.find(says), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(out)) << args;
  };
  refused(update("materials.cc_link2.young"), 64, "--params materials.cc_link2.young: the scene has no value");
  refused(update("materials.cc_link2.youngs_modulus:45e9:50e9"), 64, "exclude the nominal 41.4e9");
  refused(update("links.link1.tip_mass.mass") + " --frequency-sigma 2", 64, "--frequency-sigma");
  refused(update("links.link1.tip_mass.mass") + " --max-iterations 0", 64, "--max-iterations");
  // No test mode pairs with a model mode (the nominal is over 0.1 % off every one): a data error.
  refused("update " + nominal_ + " --segments 6 --measured " + measured_ + " --max-frequency-error 1e-6 --params links.link1.tip_mass.mass",
          65, "no measured mode pairs with a model mode");
  refused("update " + nominal_ + " --measured " + (dir_ / "absent.uff").string() + " --params links.link1.tip_mass.mass", 66, "absent.uff");
}

}  // namespace
}  // namespace mmv::cli_testing
