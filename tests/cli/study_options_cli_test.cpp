// The study layer's promise (sim/app/study.hpp): every option a study takes is checked
// once, by the study, before any model is built, and a bad one is refused with the
// option's name. The scene here cannot be built (a horizontal pendulum held by nothing:
// its equilibrium is singular), so a refusal that came after the model would be exit 1
// (numerical failure), not 64; each good value is shown to reach that failure.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "support/cli.hpp"

namespace mmv::cli_testing {
namespace {

struct OptionCase {
  std::string verb, flag, bad, good;
};

TEST_F(Cli, EveryStudyOptionIsRefusedByNameBeforeAnyModelIsBuilt) {
  const std::string scene = write("singular.yaml", singularPendulumScene("2")).string();
  const std::vector<OptionCase> cases = {
      {"modes", "--modes", "-1", "3"},
      {"modes", "--points", "l9.tip", "l1.tip"},
      {"modes", "--target-error", "-1", ""},
      {"converge", "--max-segments", "1025", "2"},
      {"converge", "--modes", "0", "1"},
      {"compare", "--component-modes", "0", "1"},
      {"compare", "--modes", "501", "2"},
      {"compare", "--bc", "welded", "pinned-free"},
      {"compare", "--tip-mass", "-1", "0.5"},
      {"compare", "--topology", "ring", "open"},
      {"check", "--margin", "100", "99"},
      {"check", "--band", "5:1", "0:50"},
      {"place-sensors", "--count", "0", "2"},
      {"place-sensors", "--count", "100001", ""},
      {"place-sensors", "--spacing", "0.0009", "0.001"},
      {"place-sensors", "--below-hz", "0", "20"},
      {"place-sensors", "--method", "best", "mke"},
      {"frf", "--points", "1", "2"},
      {"frf", "--rom-modes", "0", "1"},
      {"frf", "--damping", "1.01", "1"},
      {"frf", "--rom-target", "-0.1", "0"},
      {"frf", "--target-error", "0.51", ""},
      {"frf", "--input", "push:l1.tip", "force:l1.tip:y"},
      {"frf", "--output", "l9.tip:y", "l1.tip:y"},
      {"frf", "--output", "l1.tip:rx", "l1.tip:rz"},
      {"frf", "--input", "force:l1.tip:z", "force:l1.tip:x"},
      {"modes", "--target-error", "1", "0.5"},
      {"rom", "--time-budget", "-1", ""},
      {"simulate", "--duration", "0", "0.1"},
      {"simulate", "--sample-rate", "nan", "100"},
      {"simulate", "--accuracy", "1", "0.001"},
      {"simulate", "--integrator", "rk45", "rk_merson"},
      {"simulate", "--absolute-tolerance", "-1e-6", ""},
      {"simulate --integrator cvode_bdf", "--absolute-tolerance", "1", "0.999"},
      {"trade", "--accuracies", "1", "0.999"},
      {"trade", "--modes-accuracies", "0", ""},
      {"trade", "--integrators", "rk45", ""},
      // sweep-config lists a point whose model fails and goes on (exit 0): no good value to show here.
      {"sweep-config", "--grid", "j9:0:10:10", ""},
      {"sweep-config", "--grid", "j1:10:0:10", ""},
      {"sweep-config --grid j1:90:90:1", "--modes", "101", ""},
      {"sweep-config --grid j1:90:90:1", "--component-modes", "0", ""},
      {"sweep-config --grid j1:90:90:1", "--component-modes", "201", ""},
      {"sweep-config --grid j1:90:90:1", "--modes", "0", ""},
      {"sweep-config --grid j1:90:90:1", "--method", "guyan", ""},
      {"sweep-config --grid j1:90:90:1", "--bc", "welded", ""},
      {"trade", "--segment-ladder", "0", "1"},
      {"trade", "--segment-ladder", "1025", ""},
      {"trade", "--modes-ladder", "-1", "0"},
      {"trade", "--duration", "0", "0.1"},
      {"trade", "--target-error", "0", "1e-3"},
      {"trade", "--run-budget", "-1", "1"},
      {"trade", "--time-budget", "0", ""},
      {"simulate", "--verify-target", "0", ""},
  };
  for (const OptionCase& c : cases) {
    const std::string out = c.verb == "rom" ? " --out " + (dir_ / "rom").string() : "";
    const Result bad = run(c.verb + " " + scene + " " + c.flag + " " + c.bad + out);
    EXPECT_EQ(bad.code, 64) << c.verb << " " << c.flag << " " << c.bad << ": " << bad.err;
    EXPECT_NE(bad.err.find(c.flag), std::string::npos) << c.verb << " " << c.flag << ": " << bad.err;
    EXPECT_EQ(bad.err.find("numerical failure"), std::string::npos) << c.verb << " " << c.flag << ": " << bad.err;
    if (c.good.empty()) continue;
    const Result good = run(c.verb + " " + scene + " " + c.flag + " " + c.good + out);
    EXPECT_EQ(good.code, 1) << c.verb << " " << c.flag << " " << c.good << " (the model is built, and fails): " << good.err;
  }
}

// correlate's options, with a measured file the default scene's frf wrote: each bad value
// is refused by name before the file is read or the model built.
TEST_F(Cli, EveryCorrelateOptionIsRefusedByNameBeforeAnyModelIsBuilt) {
  ASSERT_EQ(run("frf --segments 2 --out " + (dir_ / "measured").string()).code, 0);
  const std::string scene = write("singular.yaml", singularPendulumScene("2")).string();
  const std::string measured = " --measured " + (dir_ / "measured" / "frf.uff").string();
  const std::vector<OptionCase> cases = {
      {"correlate", "--pair-distance", "0", "100"},       {"correlate", "--pair-distance", "100.1", ""},
      {"correlate", "--modes", "501", "500"},             {"correlate", "--modes", "0", ""},
      {"correlate", "--mac-threshold", "1.01", "1"},      {"correlate", "--mac-threshold", "-0.01", "0"},
      {"correlate", "--max-frequency-error", "0", "1e-6"}, {"correlate", "--damping", "1.01", "1"},
      {"correlate", "--pair", "1=l9.tip", "1=l1.tip"},   {"correlate", "--pair", "x=l1.tip", ""},
      {"correlate", "--pair", "1=l1@2", "1=l1@1"},
  };
  for (const OptionCase& c : cases) {
    const Result bad = run(c.verb + " " + scene + measured + " " + c.flag + " " + c.bad);
    EXPECT_EQ(bad.code, 64) << c.flag << " " << c.bad << ": " << bad.err;
    EXPECT_NE(bad.err.find(c.flag), std::string::npos) << c.flag << ": " << bad.err;
    if (c.good.empty()) continue;
    const Result good = run(c.verb + " " + scene + measured + " " + c.flag + " " + c.good);
    EXPECT_EQ(good.code, 1) << c.flag << " " << c.good << " (the model is built, and fails): " << good.err;
  }
  // A node the file does not define: refused with the file's name, before the model.
  const Result node = run("correlate " + scene + measured + " --pair 999=l1.tip");
  EXPECT_EQ(node.code, 65) << node.err;
  EXPECT_NE(node.err.find("--pair 999=l1.tip: the file defines no node 999"), std::string::npos) << node.err;
}

}  // namespace
}  // namespace mmv::cli_testing
