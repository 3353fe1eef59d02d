// mmvlab check (and, below it, sweep) as a user runs them.
#include <nlohmann/json.hpp>

#include "support/cli.hpp"

namespace mmv::cli_testing {
namespace {

TEST_F(Cli, CheckDefaultSceneNamesTheTorquersWorstCase) {
  const Result r = run("check");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("joint1 holding torque, worst over +-45 deg"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("overall: pass (3 requirements not checked: no capacity given)"), std::string::npos) << r.out;
}

TEST_F(Cli, CheckJsonAndMarkdownCarryTheOverridesAndVerdicts) {
  const Result r = run("check " + std::string(MMVLAB_SOURCE_DIR) + "/scenes/mmv.yaml --set joints.joint1.torque_capacity=100 --json --out " + (dir_ / "ck").string());
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["overall"], "FAIL");  // about 129 N*m needed at joint 1
  EXPECT_EQ(j["overrides"][0], "joints.joint1.torque_capacity=100");
  bool found = false;
  for (const auto& l : j["lines"])
    if (l["requirement"].get<std::string>().rfind("joint1 holding", 0) == 0) {
      found = true;
      EXPECT_EQ(l["verdict"], "FAIL");
      EXPECT_DOUBLE_EQ(l["capacity"].get<double>(), 100);
      EXPECT_LT(l["margin_pct"].get<double>(), 0);
    }
  EXPECT_TRUE(found);
  EXPECT_EQ(nlohmann::json::parse(slurp(dir_ / "ck" / "check.json")), j);
  const std::string md = slurp(dir_ / "ck" / "check.md");
  EXPECT_NE(md.find("| torquers | joint1 holding torque"), std::string::npos) << md;
  EXPECT_NE(md.find("`--set joints.joint1.torque_capacity=100`"), std::string::npos);
}

TEST_F(Cli, CheckRefusesABadBandAndAnIsolatorAndWritesNothing) {
  Result r = run("check --band 50:0.1 --out " + (dir_ / "ck").string());
  EXPECT_EQ(r.code, 64);
  EXPECT_NE(r.err.find("--band"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir_ / "ck"));
  r = run("check " + std::string(MMVLAB_SOURCE_DIR) + "/scenes/hamsas.yaml");
  EXPECT_EQ(r.code, 64);
  EXPECT_NE(r.err.find("HAM-SAS"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace mmv::cli_testing
