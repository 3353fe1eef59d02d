// Sweep specs (sim/scene/design_sweep_spec.hpp) and their points; bad specs are refused at
// their line and column before anything runs (sim/app/design_sweep_points.hpp checks keys and
// outputs against the scene).
#include "sim/scene/design_sweep_spec.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <set>

#include "sim/core/errors.hpp"
#include <regex>
#include "sim/app/design_sweep_points.hpp"

namespace mmv {
namespace {

const std::string kScene = std::string("scene: ") + MMVLAB_SOURCE_DIR + "/scenes/mmv.yaml\nsegments: 2\n";

DesignSweepSpec parseSpec(const std::string& body) { return parseSweepSpec(kScene + body, "spec.yaml", "."); }

std::string specErrorOf(const std::string& body) {
  try {
    (void)prepareDesignSweep(parseSpec(body));
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}

TEST(DesignSweepSpec, GridVariesTheLastParameterFastest) {
  const DesignSweepSpec s = parseSpec(
      "parameters:\n  - {key: links.link1.length, values: [2, 3]}\n"
      "  - {key: links.link2.length, range: {from: 1, to: 2, samples: 3}}\noutputs: [mass]\n");
  const auto p = sweepPoints(s);
  ASSERT_EQ(p.size(), 6u);
  EXPECT_EQ(p[0], (std::vector<double>{2, 1}));
  EXPECT_EQ(p[1], (std::vector<double>{2, 1.5}));
  EXPECT_EQ(p[3], (std::vector<double>{3, 1}));
  EXPECT_EQ(pointOverrides(s, p[5]), (std::vector<std::string>{"links.link1.length=3", "links.link2.length=2"}));
}

TEST(DesignSweepSpec, LatinHypercubePutsOnePointInEachStratumAndIsSeeded) {
  const std::string body =
      "parameters:\n  - {key: links.link1.length, range: {from: 1, to: 2, samples: 2}}\n"
      "  - {key: links.link2.length, range: {from: 0.1, to: 10, samples: 2, log: true}}\n"
      "design: {type: latin_hypercube, samples: 20, seed: SEED}\noutputs: [mass]\n";
  auto with = [&](const std::string& seed) { return sweepPoints(parseSpec(std::regex_replace(body, std::regex("SEED"), seed))); };
  const auto a = with("4"), b = with("4"), c = with("5");
  EXPECT_EQ(a, b);
  EXPECT_NE(a, c);
  std::set<int> lin, log;
  for (const auto& x : a) {
    lin.insert(static_cast<int>((x[0] - 1) * 20));
    log.insert(static_cast<int>(std::log(x[1] / 0.1) / std::log(100.0) * 20));
  }
  EXPECT_EQ(lin.size(), 20u);  // every stratum once
  EXPECT_EQ(log.size(), 20u);
}

TEST(DesignSweepSpec, BadSpecsNameTheirPosition) {
  const std::string tail = "outputs: [mass]\n";
  EXPECT_NE(specErrorOf("parameters:\n  - {key: links.link9.length, values: [1]}\n" + tail).find("spec.yaml:4:5: parameters[0] 'links.link9.length'"),
            std::string::npos)
      << specErrorOf("parameters:\n  - {key: links.link9.length, values: [1]}\n" + tail);
  auto refused = [&](const std::string& body, const std::string& what) {
    std::string e;
    try {
      (void)parseSpec(body);
    } catch (const SceneError& x) {
      e = x.what();
    }
    EXPECT_NE(e.find(what), std::string::npos) << "got: " << e;
  };
  refused("parameters:\n  - {key: links.link1.length, range: {from: 2, to: 1, samples: 3}}\n" + tail, "spec.yaml:4:");
  refused("parameters:\n  - {key: links.link1.length, range: {from: 2, to: 1, samples: 3}}\n" + tail, "from 2 is above to 1");
  refused("parameters:\n  - {key: links.link1.length, range: {from: 1, to: 1, samples: 3}}\n" + tail, "is empty");
  refused("parameters:\n  - {key: links.link1.length, range: {from: 1, to: 2, samples: 0}}\n" + tail, "samples must be >= 2");
  refused("parameters:\n  - {key: links.link1.length, values: []}\n" + tail, "must be a non-empty list");
  refused("parameters:\n  - {key: links.link1.length, values: [1]}\noutputs: [masss]\n", "unknown output 'masss'");
  refused("parameters: []\n" + tail, "parameters must be a non-empty list");
  refused("parameters:\n  - {key: a, range: {from: 1, to: 2, samples: 1001}}\n  - {key: b, range: {from: 1, to: 2, samples: 1000}}\n" + tail,
          "the grid has 1.001e+06 points, above the limit of 1000000");
  refused("parameters:\n  - {key: a, values: [1]}\ndesign: {type: latin_hypercube, samples: 0}\n" + tail, "design.samples must be 1 to");
  EXPECT_NE(specErrorOf("parameters:\n  - {key: links.link1.length, values: [1]}\noutputs: [\"json:modes/modes/0/no_such_field\"]\n")
                .find("spec.yaml:5:11: output 'json:modes/modes/0/no_such_field': the nominal scene's JSON has no such field"),
            std::string::npos)
      << specErrorOf("parameters:\n  - {key: links.link1.length, values: [1]}\noutputs: [\"json:modes/modes/0/no_such_field\"]\n");
}

// Each of these exited 65 with no file:line:col (issue 38): the spec's position now
// leads every message, a set: entry named as itself (not as a command-line --set).
TEST(DesignSweepSpec, EmptyScalarHamsasAndBadSetSpecsNameTheirPosition) {
  auto message = [](const std::string& text) {
    try {
      (void)prepareDesignSweep(parseSweepSpec(text, "spec.yaml", "."));
    } catch (const SceneError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_EQ(message("").rfind("spec.yaml:1:1: the sweep spec is empty", 0), 0u) << message("");
  EXPECT_EQ(message("# only a comment\n").rfind("spec.yaml:1:1: the sweep spec is empty", 0), 0u);
  EXPECT_EQ(message("42\n"), "spec.yaml:1:1: a sweep spec is a mapping (scene, parameters, design, outputs), not a scalar");
  EXPECT_EQ(message("- a\n- b\n"), "spec.yaml:1:1: a sweep spec is a mapping (scene, parameters, design, outputs), not a list");
  const std::string body = "parameters:\n  - {key: links.link1.length, values: [2]}\noutputs: [mass]\n";
  EXPECT_EQ(message(kScene + "set: [links.link1.length=3, joints.jointX.angle_deg=5]\n" + body),
            "spec.yaml:3:29: set[1] 'joints.jointX.angle_deg=5': no item 'jointX' (known: joint1, joint2, joint3)");
  const std::string hamsas = std::string("scene: ") + MMVLAB_SOURCE_DIR + "/scenes/hamsas.yaml\nset: [joints.joint1.angle_deg=5]\n";
  const std::string m = message(hamsas + body);
  EXPECT_EQ(m.rfind("spec.yaml:1:8: scene ", 0), 0u) << m;
  EXPECT_NE(m.find("is a HAM-SAS isolator; sweeps take article scenes"), std::string::npos) << m;
  EXPECT_EQ(message(kScene + "parameters:\n  - {key: links.link9.length, values: [1]}\noutputs: [mass]\n"),
            "spec.yaml:4:5: parameters[0] 'links.link9.length': no item 'link9' (known: link1, link2, link3)");
}

TEST(DesignSweepSpec, PointsAreRowsOfTheirOwn) {
  // The same point evaluated twice (and out of order) gives the same cells.
  const DesignSweepContext c = prepareDesignSweep(parseSpec(
      "parameters:\n  - {key: links.link3.length, values: [0.6, 0.9]}\noutputs: [frequencies, mass, check, \"json:modes/modes/0/effective_mass_x_kg\"]\nmodes: 3\n"));
  const auto b1 = evaluateDesignSweepPoint(c, 1), a = evaluateDesignSweepPoint(c, 0), b2 = evaluateDesignSweepPoint(c, 1);
  EXPECT_EQ(b1, b2);
  EXPECT_NE(a, b1);
  ASSERT_EQ(a.size() + 1, c.header.size());
  EXPECT_EQ(a[1], "ok");
  EXPECT_EQ(c.header[3], "mode1_hz");
  EXPECT_EQ(c.header.back(), "modes_modes_0_effective_mass_x_kg");  // a JSON pointer as a CSV column name
}

TEST(DesignSweepSpec, OneColumnListMakesTheHeaderTheFieldsAndTheCells) {
  const DesignSweepContext c = prepareDesignSweep(parseSpec(
      "parameters:\n  - {key: links.link3.length, values: [0.6, 0.9]}\n"
      "outputs: [frequencies, mass, deflection, \"first_mode:link3\", check, \"json:modes/modes/0/effective_mass_x_kg\"]\nmodes: 2\n"));
  const nlohmann::ordered_json fields = sweepFieldsJson(c.columns);
  ASSERT_EQ(fields.size(), c.header.size());
  for (std::size_t k = 0; k < c.header.size(); ++k) EXPECT_EQ(fields[k]["key"], c.header[k]) << k;
  const auto unitOf = [&](const std::string& key) {
    for (const auto& f : fields)
      if (f["key"] == key) return f["unit"].get<std::string>();
    return std::string("(no such column)");
  };
  EXPECT_EQ(unitOf("mode2_hz"), "Hz");
  EXPECT_EQ(unitOf("mode2_mac"), "1");
  EXPECT_EQ(unitOf("mass_kg"), "kg");
  EXPECT_EQ(unitOf("max_deflection_m"), "m");
  EXPECT_EQ(unitOf("first_mode_link3_hz"), "Hz");
  // Each cell of a computed point is a number exactly where its field says so.
  const auto row = evaluateDesignSweepPoint(c, 0);
  ASSERT_EQ(row.size() + 1, fields.size());
  for (std::size_t k = 1; k < fields.size(); ++k) {
    const std::string& v = row[k - 1];
    if (v.empty()) continue;
    char* end = nullptr;
    (void)std::strtod(v.c_str(), &end);
    EXPECT_EQ(*end == '\0', fields[k]["number"].get<bool>()) << fields[k]["key"] << " = " << v;
  }
  // A demand column carries its check line's unit (torque lines are in N*m).
  bool torque = false;
  for (const auto& f : fields)
    if (f["key"].get<std::string>().rfind("torque_", 0) == 0 && f["key"].get<std::string>().find("_demand") != std::string::npos) {
      torque = true;
      EXPECT_FALSE(f["unit"].get<std::string>().empty()) << f["key"];
    }
  EXPECT_TRUE(torque);
}

TEST(DesignSweepSpec, AJsonNullIsAnEmptyCellOfANumberColumn) {
  // check's first line has no capacity (JSON null): the column is a number column and
  // the cell is empty, never the text "null" (which a reader typing the column by its
  // field would refuse).
  const DesignSweepContext c = prepareDesignSweep(parseSpec(
      "parameters:\n  - {key: links.link3.length, values: [0.7]}\n"
      "outputs: [check, \"json:check/lines/0/capacity\"]\n"));
  const nlohmann::ordered_json fields = sweepFieldsJson(c.columns);
  ASSERT_EQ(fields.back()["key"], "check_lines_0_capacity");
  EXPECT_TRUE(fields.back()["number"].get<bool>());
  const auto row = evaluateDesignSweepPoint(c, 0);
  EXPECT_EQ(row[1], "ok");
  EXPECT_EQ(row.back(), "");
}

TEST(DesignSweepSpec, APointTheSceneRefusesIsARowWithItsReason) {
  const DesignSweepContext c = prepareDesignSweep(parseSpec("parameters:\n  - {key: links.link1.length, values: [2.44, -1]}\noutputs: [mass]\n"));
  const auto row = evaluateDesignSweepPoint(c, 1);
  EXPECT_NE(row[1].find("scene error"), std::string::npos) << row[1];
  EXPECT_EQ(row[2], "");  // no mass where there is no scene
}

}  // namespace
}  // namespace mmv
