// "No silent wrong answers" through the command line: a value the user gave that is
// clamped, a rule that would quietly win over another, or a likely unit slip is said on
// stderr or refused, never passed over with exit 0 and nothing said.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "support/cli.hpp"

namespace mmv::cli_testing {
namespace {

using json = nlohmann::json;

class Honesty : public Cli {};

// Before: exit 0 and a 900 km deflection from frf and simulate; only check warned.
TEST_F(Honesty, EveryCommandWarnsOfAUnitSlipAndStrictRefusesIt) {
  const std::string slip = " --set materials.s_glass_epoxy.youngs_modulus=61";
  for (const std::string cmd : {"modes --no-error-estimate", "frf --points 20", "simulate --duration 0.01", "check"}) {
    SCOPED_TRACE(cmd);
    const Result r = run(cmd + slip);
    // A FAIL of check is its answer (exit 3), as a 61 Pa rod's sag and stress make it.
    EXPECT_EQ(r.code, r.out.find("overall: FAIL") != std::string::npos ? 3 : 0) << r.err;
    EXPECT_NE(r.err.find("--set materials.s_glass_epoxy.youngs_modulus=61"), std::string::npos) << r.err;  // where
    EXPECT_NE(r.err.find("youngs_modulus 61 Pa is softer than rubber: GPa or MPa written as Pa?"), std::string::npos) << r.err;
    const Result strict = run(cmd + slip + " --strict");
    EXPECT_EQ(strict.code, 65) << strict.err;
    EXPECT_TRUE(strict.out.empty());
    EXPECT_NE(strict.err.find("--strict"), std::string::npos) << strict.err;
  }
  const Result fine = run("modes --no-error-estimate --strict");
  EXPECT_EQ(fine.code, 0) << fine.err;
  EXPECT_EQ(fine.err.find("warning"), std::string::npos) << fine.err;
}

// Before: --modes 100 on a 64-mode model, and a link's modes above its hinges after
// --segments, were clamped without a word; --modes with --below-hz quietly used --modes.
TEST_F(Honesty, ClampsAreSaidAndConflictingRulesRefused) {
  const Result many = run("modes --modes 100 --no-error-estimate --json");
  ASSERT_EQ(many.code, 0) << many.err;
  const json j = json::parse(many.out);
  EXPECT_EQ(j["modes"].size(), 64u);
  EXPECT_NE(j["warnings"].dump().find("100 modes asked for; the model has 64"), std::string::npos) << j["warnings"];
  const Result exact = run("modes --modes 64 --no-error-estimate --json");
  ASSERT_EQ(exact.code, 0);
  EXPECT_EQ(json::parse(exact.out)["warnings"].dump().find("modes asked for"), std::string::npos);

  const Result clamp = run("simulate --duration 0.01 --integrator cvode_bdf --set links.link1.modes=3 --segments 2");
  ASSERT_EQ(clamp.code, 0) << clamp.err;
  EXPECT_NE(clamp.err.find("link link1 in 2 segments keeps 2 of the 3 modes"), std::string::npos) << clamp.err;

  // A link whose tip station's 4-digit name rounded past the tip: an internal error (70)
  // before; now the station keeps its digits and the request is judged on its merits.
  const Result tiny = run("place-sensors --set links.link3.length=0.000898394 --count 2");
  EXPECT_EQ(tiny.code, 64) << tiny.err;
  EXPECT_NE(tiny.err.find("needs at least one measured direction per target mode"), std::string::npos) << tiny.err;

  const Result both = run("place-sensors --modes 1-4 --below-hz 30 --count 4");
  EXPECT_EQ(both.code, 64) << both.err;
  EXPECT_NE(both.err.find("excludes"), std::string::npos) << both.err;
}

}  // namespace
}  // namespace mmv::cli_testing
