#include <gtest/gtest.h>

#include <cctype>
#include <cmath>
#include <cstdio>
#include <string>

#include "sim/scene/scene.hpp"

namespace mmv {
namespace {

ArticleScene parseArticle(const std::string& text, const std::string& source) {
  return std::get<ArticleScene>(parseScene(text, source));
}

// A small valid scene; each bad-input test edits one line of it.
const char* kGood = R"(name: two links
gravity: [0, -9.81, 0]
materials:
  steel: {density: 7800, youngs_modulus: 2.0e11}
sections:
  bar: {shape: rectangle, b: 0.02, h: 0.01}
joints:
  - name: j1
    parent: base
    angle_deg: 30
  - name: j2
    parent: l1
    hold: free
links:
  - name: l1
    joint: j1
    material: steel
    section: bar
    length: 1.0
    segments: 4
  - name: l2
    joint: j2
    material: steel
    section: bar
    length: 0.5
    segments: rigid
    branches: {count: 2, angle_deg: 20}
)";

std::string replaceLine(const std::string& text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  std::string out = text;
  out.replace(at, from.size(), to);
  return out;
}

std::string errorOf(const std::string& text) {
  try {
    parseArticle(text, "s.yaml");
  } catch (const SceneError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(SceneYaml, GoodSceneParses) {
  const ArticleScene s = parseArticle(kGood, "s.yaml");
  EXPECT_EQ(s.name, "two links");
  ASSERT_EQ(s.article.links.size(), 3u);  // l2 expands into two branches
  EXPECT_EQ(s.article.links[1].name, "l2a");
  EXPECT_EQ(s.article.links[2].name, "l2b");
  EXPECT_NEAR(s.article.links[1].mount_angle, -10 * M_PI / 180, 1e-15);
  EXPECT_NEAR(s.article.links[2].mount_angle, 10 * M_PI / 180, 1e-15);
  EXPECT_TRUE(s.article.links[1].rigid);
  EXPECT_EQ(s.article.links[0].segments, 4);
  EXPECT_NEAR(s.article.joints[0].angle, M_PI / 6, 1e-15);
  EXPECT_EQ(s.article.joints[1].hold, JointHold::Free);
}

TEST(SceneYaml, DefaultSceneParsesAndMatchesReportTable1) {
  const ArticleScene s = loadDefaultScene();
  ASSERT_EQ(s.article.links.size(), 4u);
  EXPECT_EQ(s.article.findLink("link1")->length, 2.44);
  EXPECT_EQ(s.article.findLink("link3b")->length, 0.762);
  EXPECT_EQ(s.article.findMaterial("carbon_carbon")->youngs_modulus, 41.4e9);
}

struct BadCase {
  const char* what;  // also the test name
  const char* from;
  const char* to;
  const char* expected;  // the whole message
};

class SceneYamlBad : public ::testing::TestWithParam<BadCase> {};

TEST_P(SceneYamlBad, OneLineErrorWithPosition) {
  const BadCase& c = GetParam();
  EXPECT_EQ(errorOf(replaceLine(kGood, c.from, c.to)), c.expected) << c.what;
}

INSTANTIATE_TEST_SUITE_P(
    Classes, SceneYamlBad,
    ::testing::Values(
        BadCase{"malformed", "gravity: [0, -9.81, 0]", "gravity: [0, -9.81, 0",
                "s.yaml:3:10: malformed YAML: end of sequence flow not found"},
        BadCase{"unknown key", "    angle_deg: 30", "    angel_deg: 30",
                "s.yaml:10:5: unknown key 'joints[0].angel_deg' (did you mean 'angle_deg' or 'range_deg'?) (allowed: name, parent, angle_deg, hold, servo_stiffness, torquer, slew, torque_capacity, torque, range_deg)"},
        BadCase{"duplicate key", "    length: 1.0\n", "    length: 1.0\n    length: 2.0\n",
                "s.yaml:20:5: duplicate key 'links[0].length'"},
        BadCase{"missing key", "    length: 0.5\n", "",
                "s.yaml:21:5: links[1] is missing required key 'length'"},
        BadCase{"wrong type", "    length: 1.0", "    length: [1.0]",
                "s.yaml:19:13: links[0].length must be a number (got a list)"},
        BadCase{"not a number", "    length: 1.0", "    length: 1.0m",
                "s.yaml:19:13: links[0].length must be a number (got 1.0m)"},
        BadCase{"length <= 0", "    length: 1.0", "    length: -0.76",
                "s.yaml:19:13: links[0].length must be > 0 m (got -0.76)"},
        BadCase{"E <= 0", "youngs_modulus: 2.0e11", "youngs_modulus: 0",
                "s.yaml:4:42: materials.steel.youngs_modulus must be > 0 Pa (got 0)"},
        BadCase{"rho <= 0", "density: 7800", "density: -1",
                "s.yaml:4:20: materials.steel.density must be > 0 kg/m^3 (got -1)"},
        BadCase{"A <= 0", "bar: {shape: rectangle, b: 0.02, h: 0.01}", "bar: {shape: explicit, area: 0, second_moment: 1e-9}",
                "s.yaml:6:32: sections.bar.area must be > 0 m^2 (got 0)"},
        BadCase{"I <= 0", "bar: {shape: rectangle, b: 0.02, h: 0.01}", "bar: {shape: explicit, area: 1e-4, second_moment: -1e-9}",
                "s.yaml:6:53: sections.bar.second_moment must be > 0 m^4 (got -1e-9)"},
        BadCase{"segments < 1", "    segments: 4", "    segments: 0",
                "s.yaml:20:15: links[0].segments must be an integer from 1 to 1024 or 'rigid' (got 0)"},
        BadCase{"modes beyond the hinges", "    segments: 4", "    segments: 4\n    modes: 5",
                "s.yaml:21:12: links[0].modes must be 1 to the link's 4 hinges (one per segment) (got 5)"},
        BadCase{"modes of a rigid link", "    segments: rigid", "    segments: rigid\n    modes: 1",
                "s.yaml:27:12: links[1].modes must be 1 to the link's hinges (a rigid link has none) (got 1)"},
        BadCase{"unknown material", "    material: steel\n    section: bar\n    length: 1.0",
                "    material: steal\n    section: bar\n    length: 1.0",
                "s.yaml:17:15: links[0].material: unknown material 'steal' (did you mean 'steel'?) (known: steel)"},
        BadCase{"unknown link", "    parent: l1", "    parent: l9",
                "s.yaml:12:13: joints[1].parent: unknown parent 'l9' (known: base, l1, l2a, l2b)"},
        BadCase{"unknown joint", "    joint: j2", "    joint: j7",
                "s.yaml:22:12: links[1].joint: unknown joint 'j7' (did you mean 'j1' or 'j2'?) (known: j1, j2)"},
        BadCase{"nan", "    length: 1.0", "    length: .nan",
                "s.yaml:19:13: links[0].length must be a finite number (got .nan)"},
        BadCase{"gimbal beyond range", "gravity: [0, -9.81, 0]",
                "gravity: [0, -9.81, 0]\nbase:\n  gimbal:\n    pitch: {angle_deg: 50}",
                "s.yaml:5:24: base.gimbal.pitch.angle_deg: 50 deg is beyond the gimbal's +-45 deg pitch range"},
        BadCase{"gimbal slew beyond range", "gravity: [0, -9.81, 0]",
                "gravity: [0, -9.81, 0]\nbase:\n  gimbal:\n    roll: {slew: {to_deg: -95}}",
                "s.yaml:5:27: base.gimbal.roll.slew.to_deg: -95 deg is beyond the gimbal's +-90 deg roll range"},
        BadCase{"gimbal unknown axis", "gravity: [0, -9.81, 0]",
                "gravity: [0, -9.81, 0]\nbase:\n  gimbal:\n    tilt: {angle_deg: 5}",
                "s.yaml:5:5: unknown key 'base.gimbal.tilt' (allowed: yaw, pitch, roll, ring_mass, ring_inertia)"},
        BadCase{"out of plane gravity", "gravity: [0, -9.81, 0]", "gravity: [0, -9.81, 1]",
                "s.yaml:2:21: gravity[2] must be 0 m/s^2: the article moves in the x-y plane (got 1)"},
        // Programs and slews are built by the facility models while the scene is read,
        // so what they refuse is reported at its key, before any model is built.
        BadCase{"table stroke", "gravity: [0, -9.81, 0]",
                "gravity: [0, -9.81, 0]\nbase:\n  type: table\n  motion: {type: sine, amplitude: 0.2, frequency_hz: 1}",
                "s.yaml:5:11: base.motion: sine dwell 0.2 m at 1 Hz: peak displacement 0.2 m exceeds the table's +-0.15 m stroke"},
        BadCase{"unreadable profile", "gravity: [0, -9.81, 0]",
                "gravity: [0, -9.81, 0]\nbase:\n  type: table\n  motion: {type: csv, file: /dev/null}",
                "s.yaml:5:29: base.motion.file: cannot read profile '/dev/null': is not a regular file (a device, FIFO or socket)"},
        BadCase{"view looking along up", "gravity: [0, -9.81, 0]",
                "gravity: [0, -9.81, 0]\nviews:\n  down: {eye: [0, 5, 0], target: [0, 0, 0], up: [0, 1, 0]}",
                "s.yaml:4:9: views.down.up must not be parallel to the line of sight (or zero)"},
        BadCase{"view fov", "gravity: [0, -9.81, 0]",
                "gravity: [0, -9.81, 0]\nviews:\n  wide: {eye: [0, 0, 5], target: [0, 0, 0], fov_deg: 175}",
                "s.yaml:4:54: views.wide.fov_deg must be below 170 deg (got 175)"},
        BadCase{"lab hole wider than the platform", "gravity: [0, -9.81, 0]",
                "gravity: [0, -9.81, 0]\nlab: {hole_side_m: 7}",
                "s.yaml:3:20: lab.hole_side_m: the hole (7 m) must be smaller than the platform (6.096 m x 8.8392 m)"},
        BadCase{"lab platform above the ceiling", "gravity: [0, -9.81, 0]",
                "gravity: [0, -9.81, 0]\nlab:\n  platform_height_m: 30",
                "s.yaml:4:22: lab.platform_height_m: the platform (30 m, 0.3 m thick) must be below the ceiling (27.432 m)"},
        BadCase{"lab unknown key", "gravity: [0, -9.81, 0]", "gravity: [0, -9.81, 0]\nlab: {hole_m: 1}",
                "s.yaml:3:7: unknown key 'lab.hole_m' (allowed: floor_length_m, floor_width_m, ceiling_height_m, "
                "platform_height_m, hole_side_m, platform_length_m, platform_width_m, platform_thickness_m, "
                "base_below_platform_m)"},
        BadCase{"lab negative size", "gravity: [0, -9.81, 0]", "gravity: [0, -9.81, 0]\nlab: {floor_width_m: -3}",
                "s.yaml:3:22: lab.floor_width_m must be > 0 m (got -3)"},
        BadCase{"joint slew beyond a half turn", "    angle_deg: 30",
                "    angle_deg: 30\n    slew: {to_deg: 200}",
                "s.yaml:11:11: joints[0].slew: slew: angle 200 deg is outside the joint's +-45 deg range"},
        // The report's torquers move +-45 deg: a 60 deg slew and a 400 deg angle are refused.
        BadCase{"joint slew beyond the torquers range", "    angle_deg: 30",
                "    angle_deg: 30\n    slew: {to_deg: 60}",
                "s.yaml:11:11: joints[0].slew: slew: angle 60 deg is outside the joint's +-45 deg range"},
        BadCase{"held angle beyond the torquers range", "    angle_deg: 30", "    angle_deg: 400",
                "s.yaml:10:16: joints[0].angle_deg: 400 deg is beyond the joint's +-45 deg range (its torquer's; range_deg sets another)"},
        BadCase{"joint range beyond a half turn", "    angle_deg: 30", "    angle_deg: 30\n    range_deg: 200",
                "s.yaml:11:16: joints[0].range_deg must be <= 180 deg, or unlimited (got 200)"},
        BadCase{"samples beyond the limit", "gravity: [0, -9.81, 0]",
                "gravity: [0, -9.81, 0]\nsimulation: {duration: 1000, sample_rate_hz: 10000}",
                "s.yaml:3:46: simulation: 1000 s at 10000 Hz is 1e+07 samples, above the limit of 1000000 (a rate or a "
                "duration in the wrong unit?)"},
        BadCase{"free joint beyond a half turn", "    hold: free", "    hold: free\n    angle_deg: 270",
                "s.yaml:14:16: joints[1].angle_deg: 270 deg is beyond the joint's +-180 deg"},
        BadCase{"spatial model without a shear modulus", "gravity: [0, -9.81, 0]", "gravity: [0, -9.81, 0]\nmodel: spatial",
                "s.yaml:3:8: model: spatial twists link 'l1': materials.steel needs shear_modulus (Pa) or poisson_ratio"},
        BadCase{"unknown model", "gravity: [0, -9.81, 0]", "gravity: [0, -9.81, 0]\nmodel: spacial",
                "s.yaml:3:8: model: unknown model 'spacial' (known: planar, spatial)"},
        BadCase{"a spatial link without a shear modulus", "    segments: 4\n", "    segments: 4\n    model: spatial\n",
                "s.yaml:21:12: links[0].model: spatial twists link 'l1': materials.steel needs shear_modulus (Pa) or "
                "poisson_ratio"},
        BadCase{"unknown link model", "    segments: 4\n", "    segments: 4\n    model: flat\n",
                "s.yaml:21:12: links[0].model: unknown model 'flat' (known: planar, spatial)"},
        BadCase{"poisson ratio out of range", "youngs_modulus: 2.0e11}", "youngs_modulus: 2.0e11, poisson_ratio: 0.7}",
                "s.yaml:4:65: materials.steel.poisson_ratio must be in (-1, 0.5) for an isotropic solid (got 0.7)"},
        BadCase{"yield above ultimate", "youngs_modulus: 2.0e11}",
                "youngs_modulus: 2.0e11, yield_strength: 300e6, ultimate_strength: 250e6}",
                "s.yaml:4:66: materials.steel.yield_strength 300e6 Pa exceeds its ultimate_strength 250e6 Pa: a material "
                "yields before it fails"},
        // The factors' stated bound (docs/strength.md): 1 is accepted (StrengthKeys), below it refused.
        BadCase{"factor of safety below one", "gravity: [0, -9.81, 0]", "gravity: [0, -9.81, 0]\nstrength: {yield_factor: 0.99}",
                "s.yaml:3:26: strength.yield_factor must be >= 1 (a factor of safety below 1 accepts a stress above the "
                "allowable; got 0.99)"},
        BadCase{"fibre distance on a shape that has its own", "h: 0.01}", "h: 0.01, fibre_distance: 0.005}",
                "s.yaml:6:61: sections.bar.fibre_distance does not apply to shape 'rectangle'"},
        BadCase{"shear modulus and poisson ratio", "youngs_modulus: 2.0e11}",
                "youngs_modulus: 2.0e11, shear_modulus: 8e10, poisson_ratio: 0.3}",
                "s.yaml:4:86: materials.steel: give shear_modulus or poisson_ratio, not both"},
        BadCase{"spatial model with an explicit section lacking its torsion constant",
                "2.0e11}\nsections:\n  bar: {shape: rectangle, b: 0.02, h: 0.01}",
                "2.0e11, poisson_ratio: 0.3}\nsections:\n  bar: {shape: explicit, area: 1e-4, second_moment: 1e-9, "
                "second_moment_out: 2e-9}\nmodel: spatial",
                "s.yaml:7:8: model: spatial bends link 'l1' out of its plane: sections.bar needs second_moment_out and "
                "torsion_constant (m^4)"},
        BadCase{"branches out of the plane on the planar model", "angle_deg: 20}", "angle_deg: 20, plane: out}",
                "s.yaml:27:48: links[1].branches.plane: branches out of the plane need model: spatial"},
        BadCase{"an accelerometer along the normal on the planar model", "gravity: [0, -9.81, 0]",
                "gravity: [0, -9.81, 0]\nsensors:\n  - {name: az, type: accelerometer, point: l1.tip, axis: normal}",
                "s.yaml:4:58: sensors[0].axis: an accelerometer along the normal axis reads motion out of the plane: it "
                "needs model: spatial"},
        BadCase{"a gyro about the link on the planar model", "gravity: [0, -9.81, 0]",
                "gravity: [0, -9.81, 0]\nsensors:\n  - {name: g, type: rate_gyro, point: l1.tip, axis: axial}",
                "s.yaml:4:53: sensors[0].axis: a rate gyro about the axial axis reads motion out of the plane: it needs "
                "model: spatial"},
        BadCase{"a mass offset out of the plane on the planar model", "    segments: 4\n",
                "    segments: 4\n    tip_mass: {mass: 0.1, offset: [0, 0.01]}\n",
                "s.yaml:21:35: links[0].tip_mass.offset: a mass offset out of the plane needs model: spatial"},
        BadCase{"a mass offset that is not [y, z]", "    segments: 4\n",
                "    segments: 4\n    tip_mass: {mass: 0.1, offset: [0, 0.01, 0]}\n",
                "s.yaml:21:35: links[0].tip_mass.offset must be [y, z] in m, across the link's section (got a list)"},
        BadCase{"an unknown fidelity", "gravity: [0, -9.81, 0]",
                "gravity: [0, -9.81, 0]\nsimulation: {fidelity: modal}",
                "s.yaml:3:24: simulation.fidelity: unknown fidelity 'modal' (known: auto, segments)"},
        BadCase{"the table's y axis on the planar model", "gravity: [0, -9.81, 0]",
                "gravity: [0, -9.81, 0]\nbase: {type: table, motion_z: {type: sine, amplitude: 0.001, frequency_hz: 2}}",
                "s.yaml:3:31: base.motion_z moves the table across the plane of motion: it needs model: spatial"}),
    [](const ::testing::TestParamInfo<BadCase>& info) {
      std::string name = info.param.what;
      for (char& ch : name)
        if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
      return name;
    });

TEST(SceneYaml, SpatialModelReadsShearModulusAndBranchesOutOfThePlane) {
  const ArticleScene s = parseArticle(
      replaceLine(replaceLine(replaceLine(kGood, "gravity: [0, -9.81, 0]", "gravity: [0, -9.81, 0]\nmodel: spatial"),
                              "youngs_modulus: 2.0e11}", "youngs_modulus: 2.0e11, poisson_ratio: 0.25}"),
                  "angle_deg: 20}", "angle_deg: 20, plane: out}"),
      "s.yaml");
  EXPECT_EQ(s.article.model, ArticleModel::Spatial);
  EXPECT_NEAR(s.article.findMaterial("steel")->shear_modulus, 2.0e11 / 2.5, 1e-3);
  EXPECT_NEAR(s.article.findLink("l2a")->tilt, -10 * M_PI / 180, 1e-15);
  EXPECT_NEAR(s.article.findLink("l2b")->tilt, 10 * M_PI / 180, 1e-15);
  EXPECT_EQ(s.article.findLink("l2b")->mount_angle, 0.0);
  EXPECT_EQ(parseArticle(kGood, "s.yaml").article.model, ArticleModel::Planar);
}

// A link's own model: a planar link of a spatial scene bends in its plane only, so its
// material needs no shear modulus; a spatial link makes the article spatial, and the
// links without a model of their own keep the scene's.
TEST(SceneYaml, EachLinkMayChooseItsModel) {
  // The scene with link l1's own model and one other edit; which links bend out of the plane.
  const auto bending = [](const std::string& l1_model, const std::string& from, const std::string& to) {
    const ArticleScene s = parseArticle(
        replaceLine(replaceLine(kGood, from, to), "    segments: 4\n", "    segments: 4\n    model: " + l1_model + "\n"),
        "s.yaml");
    EXPECT_EQ(s.article.model, ArticleModel::Spatial);
    std::string out;
    for (const char* l : {"l1", "l2a", "l2b"}) out += s.article.bendsOutOfPlane(*s.article.findLink(l)) ? 'S' : 'P';
    return out;
  };
  EXPECT_EQ(bending("planar", "gravity: [0, -9.81, 0]", "gravity: [0, -9.81, 0]\nmodel: spatial"), "PSS");
  EXPECT_EQ(bending("spatial", "youngs_modulus: 2.0e11}", "youngs_modulus: 2.0e11, poisson_ratio: 0.3}"), "SPP");
}

// Links in modal coordinates need a planar open tree (sim/time/modal_links.hpp): a
// closure is refused at the link's key; without it the count is read.
TEST(SceneYaml, ModesOnlyOnAPlanarOpenTree) {
  const std::string modal = replaceLine(kGood, "    segments: 4", "    segments: 4\n    modes: 2");
  EXPECT_EQ(parseArticle(modal, "s.yaml").article.links[0].modes, 2);
  EXPECT_EQ(parseArticle(modal, "s.yaml").article.links[1].modes, 0);
  EXPECT_EQ(errorOf(modal + "closures:\n  - {point: l1.tip}\n"),
            "s.yaml:21:12: links[0].modes: links in modal coordinates need a planar open tree (this article is closed)");
}

TEST(SceneYaml, JointRangeWidensWhenTheSceneSaysSo) {
  const ArticleScene s = parseArticle(replaceLine(kGood, "    angle_deg: 30", "    angle_deg: 80\n    range_deg: 90\n    slew: {to_deg: -85}"), "s.yaml");
  EXPECT_NEAR(s.article.joints[0].range, M_PI / 2, 1e-15);
  EXPECT_NEAR(s.article.joints[0].angle, 80 * M_PI / 180, 1e-15);
  EXPECT_NEAR(parseArticle(kGood, "s.yaml").article.joints[0].range, M_PI / 4, 1e-15);  // the report's +-45 deg
}

TEST(SceneYaml, LabOnlyWhenNamedWithTheReportsDimensions) {
  EXPECT_FALSE(parseArticle(kGood, "s.yaml").lab);
  const ArticleScene s = parseArticle(replaceLine(kGood, "gravity: [0, -9.81, 0]", "gravity: [0, -9.81, 0]\nlab: {}"), "s.yaml");
  ASSERT_TRUE(s.lab);
  // docs/sources.md section 2: 53.5 ft x 29.0 ft floor, 90 ft ceiling, platform at 42.5 ft, 5 ft hole.
  EXPECT_NEAR(s.lab->floor_length, 16.3068, 1e-12);
  EXPECT_NEAR(s.lab->floor_width, 8.8392, 1e-12);
  EXPECT_NEAR(s.lab->ceiling_height, 27.432, 1e-12);
  EXPECT_NEAR(s.lab->platform_height, 12.954, 1e-12);
  EXPECT_NEAR(s.lab->hole_side, 1.524, 1e-12);
  const ArticleScene t = parseArticle(
      replaceLine(kGood, "gravity: [0, -9.81, 0]", "gravity: [0, -9.81, 0]\nlab: {platform_height_m: 10, base_below_platform_m: 0}"),
      "s.yaml");
  EXPECT_EQ(t.lab->platform_height, 10.0);
  const facility::LabLevels y = facility::labLevels(*t.lab, -1.0);
  EXPECT_EQ(y.platform_top, -1.0);
  EXPECT_EQ(y.floor, -11.0);
  EXPECT_NEAR(y.ceiling, -11.0 + 27.432, 1e-12);
}

TEST(SceneYaml, GimbalOnlyWhenNamed) {
  EXPECT_FALSE(parseArticle(kGood, "s.yaml").article.base.gimbal);
  const ArticleScene s = parseArticle(replaceLine(kGood, "gravity: [0, -9.81, 0]",
                                         "gravity: [0, -9.81, 0]\nbase:\n  gimbal:\n    roll: {angle_deg: -90, "
                                         "torque_capacity: 60}\n    pitch: {slew: {to_deg: 45}}\n    ring_mass: 4"),
                             "s.yaml");
  ASSERT_TRUE(s.article.base.gimbal);
  const GimbalSpec& g = *s.article.base.gimbal;
  EXPECT_NEAR(g.roll.angle, -M_PI / 2, 1e-15);
  EXPECT_EQ(g.roll.torque_capacity, 60.0);
  EXPECT_EQ(g.yaw.torque_capacity, 200.0);  // docs/sources.md section 2 defaults
  ASSERT_TRUE(g.pitch.slew);
  EXPECT_NEAR(g.pitch.slew->to, M_PI / 4, 1e-15);
  EXPECT_EQ(g.ring_mass, 4.0);
  EXPECT_EQ(s.article.torqueCapacity("gimbal.roll"), 60.0);
}

TEST(SceneYaml, LoopOfJointsIsNotConnected) {
  const std::string text = replaceLine(kGood, "    parent: base", "    parent: l2a");
  EXPECT_EQ(errorOf(text), "s.yaml:15:5: links[0]: link 'l1' is not connected to the base (its joints form a loop)");
}

TEST(SceneYaml, ClosureAndLoadKeys) {
  std::string text = std::string(kGood) +
                     "closures:\n  - {name: prop, point: l1.tip, type: slider, direction_deg: 90}\n"
                     "  - {point: l2a.tip, to: l1.h2}\n"
                     "loads:\n  - {point: j2, force: [0, -10, 0]}\n";
  const ArticleScene s = parseArticle(text, "s.yaml");
  ASSERT_EQ(s.article.closures.size(), 2u);
  EXPECT_EQ(s.article.closures[0].type, ClosureType::Slider);
  EXPECT_NEAR(s.article.closures[0].direction, M_PI / 2, 1e-15);
  EXPECT_EQ(s.article.closures[0].where, "s.yaml:29:5");
  EXPECT_EQ(s.article.closures[1].to, "l1.h2");
  EXPECT_EQ(s.article.closures[1].name, "closure2");
  ASSERT_EQ(s.article.loads.size(), 1u);
  EXPECT_EQ(s.article.loads[0].force[1], -10);
}

TEST(SceneYaml, ClosureNamingAnUnknownPoint) {
  const std::string text = std::string(kGood) + "closures:\n  - {point: l3.tip}\n";
  EXPECT_EQ(errorOf(text),
            "s.yaml:29:13: closures[0].point: unknown point 'l3.tip' (points are <joint>, <link>.root, <link>.tip and "
            "<link>.h1 .. <link>.h<segments>)");
  const std::string hinge = std::string(kGood) + "closures:\n  - {point: l1.h5}\n";  // l1 has 4 segments
  EXPECT_NE(errorOf(hinge).find("unknown point 'l1.h5'"), std::string::npos);
  const std::string at = std::string(kGood) + "closures:\n  - {point: l1.tip, to: l1.h2, at: [0, 0, 0]}\n";
  EXPECT_NE(errorOf(at).find("closures[0].at applies only to closures to the ground"), std::string::npos);
}

TEST(SceneYaml, DampingAndTable) {
  std::string text = replaceLine(kGood, "gravity: [0, -9.81, 0]",
                                 "gravity: [0, -9.81, 0]\nbase: {type: table, table_mass: 50, motion: {type: sine, amplitude: 0.002, "
                                 "frequency_hz: 3}}\ndamping: {hinge_beta: 0.01}");
  const ArticleScene s = parseArticle(text, "s.yaml");
  EXPECT_EQ(s.article.base.type, BaseType::Table);
  EXPECT_EQ(s.article.base.table_mass, 50);
  ASSERT_TRUE(s.article.base.motion.has_value());
  EXPECT_EQ(s.article.base.motion->frequency_hz, 3);
  ASSERT_TRUE(s.damping.has_value());
  EXPECT_EQ(s.damping->kind, DampingSpec::Kind::HingeViscous);
  EXPECT_EQ(s.damping->hinge_beta, 0.01);
  EXPECT_EQ(errorOf(replaceLine(kGood, "gravity: [0, -9.81, 0]", "gravity: [0, -9.81, 0]\ndamping: {modal_ratio: 0.02, hinge_beta: 0.01}")),
            "s.yaml:3:10: damping must give exactly one of modal_ratio, rayleigh, hinge_beta");
  EXPECT_EQ(errorOf(replaceLine(kGood, "gravity: [0, -9.81, 0]", "gravity: [0, -9.81, 0]\nbase: {table_mass: 5}")),
            "s.yaml:3:20: base.table_mass applies only with type: table");
  EXPECT_EQ(errorOf(replaceLine(kGood, "gravity: [0, -9.81, 0]",
                                "gravity: [0, -9.81, 0]\nbase: {type: table, motion: {type: sine, amplitude: 1, frequency_hz: 0}}")),
            "s.yaml:3:70: base.motion.frequency_hz must be > 0 Hz (got 0)");
}

TEST(SceneYaml, Sensors) {
  const std::string good = std::string(kGood) +
                           "sensors:\n  - {name: e1, type: encoder, joint: j1}\n"
                           "  - {name: a1, type: accelerometer, point: l1.tip, axis: transverse, noise_sigma: 0.01}\n";
  const ArticleScene s = parseArticle(good, "s.yaml");
  ASSERT_EQ(s.sensors.size(), 2u);
  EXPECT_EQ(s.sensors[1].axis, 1);
  EXPECT_EQ(errorOf(std::string(kGood) + "sensors:\n  - {name: g, type: rate_gyro, point: l7.tip}\n"),
            "s.yaml:29:39: sensors[0].point: unknown point 'l7.tip' (points are <joint>, <link>.root, <link>.tip and "
            "<link>.h1 .. <link>.h<segments>)");
  EXPECT_NE(errorOf(std::string(kGood) + "sensors:\n  - {name: x, type: lidar, point: l1.tip}\n").find("unknown sensor 'lidar'"),
            std::string::npos);
  EXPECT_NE(errorOf(std::string(kGood) + "sensors:\n  - {name: e, type: encoder, joint: j9}\n").find("unknown joint 'j9'"),
            std::string::npos);
}

TEST(SceneYaml, EmptyScene) {
  EXPECT_EQ(errorOf(""), "s.yaml:1:1: the scene is empty (expected a mapping with 'links' and 'joints')");
}

TEST(SceneYaml, MissingFile) {
  EXPECT_THROW(loadSceneFile("/nonexistent/scene.yaml"), SceneFileError);
}

}  // namespace
}  // namespace mmv

namespace mmv {
namespace {

TEST(SceneYaml, TorqueInputOnlyOnAMovingJoint) {
  const ArticleScene s = parseArticle(replaceLine(kGood, "    hold: free", "    hold: free\n    torque: {type: sine, amplitude: 2.5, frequency_hz: 3}"),
                             "s.yaml");
  ASSERT_TRUE(s.article.joints[1].torque_input.has_value());
  EXPECT_EQ(s.article.joints[1].torque_input->amplitude, 2.5);
  EXPECT_EQ(errorOf(replaceLine(kGood, "    angle_deg: 30", "    angle_deg: 30\n    torque: {type: sine, amplitude: 1, frequency_hz: 1}")),
            "s.yaml:11:13: joints[0].torque: a commanded torque needs a joint that moves (hold: free or servo)");
  EXPECT_EQ(errorOf(replaceLine(kGood, "    hold: free", "    hold: free\n    torque: {type: random, rms: -1, from_hz: 1, to_hz: 2, duration: 1}")),
            "s.yaml:14:33: joints[1].torque.rms must be >= 0 N*m (got -1)");
}

// Prescribed motion past a half turn: a spin-up needs a continuous joint (range_deg:
// unlimited), its keys are its own, and an angle program is read from its CSV and must
// start at the joint's angle; every refusal at its line and column.
TEST(SceneYaml, SpinUpsAndAngleProgramsAreCheckedAtTheirKeys) {
  const std::string j = "    angle_deg: 30";
  const auto with = [&](const std::string& extra) { return replaceLine(kGood, j, j + "\n" + extra); };
  const std::string spin = "    slew: {shape: spin_up, rate_deg_s: 90, ramp_s: 1}";
  EXPECT_EQ(errorOf(with(spin)), "s.yaml:11:11: joints[0].slew: a spin-up turns past any angle: it needs range_deg: unlimited (a "
                                 "slip ring), not a +-45 deg travel");
  const ArticleScene s = parseArticle(with("    range_deg: unlimited\n" + spin), "s.yaml");
  EXPECT_TRUE(s.article.joints[0].continuous);
  EXPECT_NEAR(s.article.joints[0].range, M_PI, 1e-15);  // the travel a holding torque is worst over
  ASSERT_TRUE(s.article.joints[0].slew);
  EXPECT_NEAR(s.article.joints[0].slew->spin_rate, M_PI / 2, 1e-15);
  EXPECT_EQ(s.article.joints[0].slew->spin_ramp, 1.0);
  EXPECT_FALSE(parseArticle(kGood, "s.yaml").article.joints[0].continuous);
  const std::string u = "    range_deg: unlimited\n";
  EXPECT_EQ(errorOf(with(u + "    slew: {shape: spin_up, rate_deg_s: 0, ramp_s: 1}")),
            "s.yaml:12:40: joints[0].slew.rate_deg_s must not be 0 (its sign is the direction)");
  EXPECT_EQ(errorOf(with(u + "    slew: {shape: spin_up, rate_deg_s: 90, ramp_s: 1, to_deg: 10}")),
            "s.yaml:12:63: joints[0].slew.to_deg does not apply to a spin_up slew");
  EXPECT_EQ(errorOf(with(u + "    slew: {shape: spin_up, rate_deg_s: 90, ramp_s: 0}")),
            "s.yaml:12:52: joints[0].slew.ramp_s must be > 0 s (got 0)");
  EXPECT_EQ(errorOf(with(u + "    slew: {shape: spin, rate_deg_s: 90}")),
            "s.yaml:12:19: joints[0].slew.shape: unknown shape 'spin' (known: cycloidal, trapezoidal, spin_up, program)");
  EXPECT_EQ(errorOf(with("    range_deg: 180.001")).rfind("s.yaml:11:16: joints[0].range_deg must be <= 180 deg, or unlimited", 0), 0u);
  EXPECT_NEAR(parseArticle(with("    range_deg: 180"), "s.yaml").article.joints[0].range, M_PI, 1e-15);
  EXPECT_EQ(errorOf(with("    slew: {shape: program, file: /nonexistent/p.csv}"))
                .rfind("s.yaml:11:34: joints[0].slew.file: cannot read the angle program '/nonexistent/p.csv'", 0),
            0u);
  // An angle program: from the joint's 30 deg, or refused with where it starts.
  const std::string csv = ::testing::TempDir() + "/mmv_angle_program.csv";
  const auto write = [&](const std::string& text) {
    FILE* f = std::fopen(csv.c_str(), "w");
    ASSERT_NE(f, nullptr);
    std::fputs(text.c_str(), f);
    std::fclose(f);
  };
  write("time_s,angle_deg\n0,30\n1,40\n2,-20\n");
  const ArticleScene p = parseArticle(with("    slew: {shape: program, file: " + csv + "}"), "s.yaml");
  ASSERT_TRUE(p.article.joints[0].slew);
  EXPECT_EQ(p.article.joints[0].slew->program_source, csv);
  write("time_s,angle_deg\n0,10\n1,40\n");
  EXPECT_EQ(errorOf(with("    slew: {shape: program, file: " + csv + "}")),
            "s.yaml:11:11: joints[0].slew: angle program: it starts at 10 deg, the joint at 30 deg (its angle_deg): the first "
            "angle must be the joint's");
  write("time_s,angle_deg\n0,30\n1,44\n2,44\n");  // the cubic overshoots 45 deg between 1 and 2 s
  EXPECT_EQ(errorOf(with("    slew: {shape: program, file: " + csv + "}")).rfind("s.yaml:11:11: joints[0].slew: angle program: ", 0), 0u);
  std::remove(csv.c_str());
}

}  // namespace
}  // namespace mmv
