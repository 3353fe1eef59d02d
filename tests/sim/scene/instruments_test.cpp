// The sensor catalogue (`instruments:`): the report's three by default, each key
// overridable, new instruments by type; sensors take their instrument's spec; an
// instrument's mass welded where its sensors sit (a triaxial block's once per point);
// every bad entry refused at its key.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

#include "sim/scene/scene.hpp"

namespace mmv {
namespace {

std::string slewText() {
  std::ifstream in(std::string(MMVLAB_SOURCE_DIR) + "/scenes/mmv-slew.yaml");
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

/// The slew scene with `instruments` (YAML, top level) and its sensors replaced by `sensors`.
std::string withCatalogue(const std::string& instruments, const std::string& sensors) {
  std::string text = slewText();
  const auto from = text.find("\nsensors:");
  const auto to = text.find("\n\n", from + 1);
  EXPECT_NE(from, std::string::npos);
  text.replace(from, to - from, "\nsensors:\n" + sensors);
  return text + "\n" + instruments + "\n";
}

ArticleScene parse(const std::string& text) { return std::get<ArticleScene>(parseScene(text, "s.yaml")); }

std::string catalogueErrorOf(const std::string& text) {
  try {
    parse(text);
  } catch (const SceneError& e) {
    return e.what();
  }
  return "(no error)";
}

const std::vector<std::pair<double, double>>& stationMasses(const ArticleScene& s, const std::string& link) {
  return s.article.findLink(link)->station_masses;
}

TEST(Instruments, TheReportsAreThereAndMassless) {
  const ArticleScene s = parse(slewText());
  for (const char* name : {"encoder", "rate_gyro", "accelerometer", "strain"}) {
    const InstrumentSpec* i = findInstrument(s, name);
    ASSERT_NE(i, nullptr) << name;
    const facility::SensorSpec report = facility::sensorSpecFor(name);
    EXPECT_EQ(i->spec.range, report.range) << name;
    EXPECT_EQ(i->spec.resolution, report.resolution) << name;
    EXPECT_EQ(i->spec.low_cut_hz, report.low_cut_hz) << name;
    EXPECT_EQ(i->spec.high_cut_hz, report.high_cut_hz) << name;
    EXPECT_EQ(i->mass_kg, 0.0) << name;
  }
  for (const auto& l : s.article.links) EXPECT_TRUE(l.station_masses.empty()) << l.name;
  // A sensor records through its type's instrument, with its own noise and seed.
  const SensorSceneSpec& acc = s.sensors[3];
  ASSERT_EQ(acc.name, "acc_link2_tip");
  const facility::SensorSpec spec = sensorSpecOf(s, acc);
  EXPECT_EQ(spec.range, facility::accelerometerSpec().range);
  EXPECT_EQ(spec.noise_sigma, 0.005);
  EXPECT_EQ(spec.seed, 7u);
}

TEST(Instruments, AnOverrideChangesOnlyItsKeysAndANewOneStartsFromItsType) {
  const ArticleScene s = parse(withCatalogue(
      "instruments:\n  accelerometer: {mass_kg: 0.005}\n  a_fine: {type: accelerometer, resolution: 0.001, range: 20, band_hz: [0.5, 80]}\n",
      "  - {name: a, type: accelerometer, point: link2@1.0m}\n  - {name: b, instrument: a_fine, point: link3a.tip, axis: transverse}\n"));
  const InstrumentSpec& acc = *findInstrument(s, "accelerometer");
  EXPECT_EQ(acc.mass_kg, 0.005);
  EXPECT_EQ(acc.spec.range, facility::accelerometerSpec().range);
  // "a_fine" sorts before "accelerometer": it starts from the report's, not the override.
  const InstrumentSpec& fine = *findInstrument(s, "a_fine");
  EXPECT_EQ(fine.mass_kg, 0.0);
  EXPECT_EQ(fine.spec.kind, "accelerometer");
  EXPECT_EQ(fine.spec.range, 20.0);
  EXPECT_EQ(fine.spec.resolution, 0.001);
  EXPECT_EQ(fine.spec.low_cut_hz, 0.5);
  EXPECT_EQ(fine.spec.high_cut_hz, 80.0);
  EXPECT_EQ(s.sensors[1].type, "accelerometer");  // from its instrument
  EXPECT_EQ(sensorSpecOf(s, s.sensors[1]).range, 20.0);
  // The 5 g accelerometer welded at its station; the massless one adds nothing.
  EXPECT_EQ(stationMasses(s, "link2"), (std::vector<std::pair<double, double>>{{1.0, 0.005}}));
  EXPECT_TRUE(stationMasses(s, "link3a").empty());
}

TEST(Instruments, ATriaxialBlockWeighsOncePerPoint) {
  const ArticleScene s = parse(withCatalogue(
      "instruments:\n  tri: {type: accelerometer, axes: 3, mass_kg: 0.012}\n  accelerometer: {mass_kg: 0.004}\n",
      "  - {name: x, instrument: tri, point: link1@0.5, axis: axial}\n"
      "  - {name: y, instrument: tri, point: link1@0.5, axis: transverse}\n"
      "  - {name: u1, type: accelerometer, point: link1.tip, axis: axial}\n"
      "  - {name: u2, type: accelerometer, point: link1.tip, axis: transverse}\n"));
  const double half = 0.5 * s.article.findLink("link1")->length;
  const double tip = s.article.findLink("link1")->length;
  // One block at mid-length; two uniaxial housings at the tip.
  EXPECT_EQ(stationMasses(s, "link1"), (std::vector<std::pair<double, double>>{{half, 0.012}, {tip, 0.004}, {tip, 0.004}}));
  // A film's mass at its span's middle, whichever way the span is written.
  const ArticleScene f = parse(withCatalogue("instruments:\n  strain: {mass_kg: 0.001}\n",
                                             "  - {name: f, type: strain, span: [link2@0.6m, link2@0.2m]}\n"));
  ASSERT_EQ(stationMasses(f, "link2").size(), 1u);
  EXPECT_NEAR(stationMasses(f, "link2")[0].first, 0.4, 1e-12);
}

TEST(Instruments, BadEntriesAreRefusedAtTheirKeys) {
  struct Case {
    std::string instruments, sensors, message;
  };
  const std::string acc = "  - {name: a, type: accelerometer, point: link2@1.0m}\n";
  for (const Case& c : std::vector<Case>{
           {"instruments:\n  x: {mass_kg: 0.01}\n", acc, "instruments.x is missing required key 'type'"},
           {"instruments:\n  x: {type: acclerometer}\n", acc, "instruments.x.type: unknown sensor type 'acclerometer' (did you mean 'accelerometer'?)"},
           {"instruments:\n  accelerometer: {type: rate_gyro}\n", acc, "the report's accelerometer stays an accelerometer (got rate_gyro)"},
           {"instruments:\n  g: {type: rate_gyro, axes: 3}\n", acc, "instruments.g.axes: a triaxial block is an accelerometer's"},
           {"instruments:\n  x: {type: accelerometer, axes: 2}\n", acc, "instruments.x.axes must be 1 or 3"},
           {"instruments:\n  x: {type: accelerometer, resolution: 50}\n", acc, "the resolution (50 m/s^2) must be below the range (49.0332 m/s^2)"},
           {"instruments:\n  x: {type: accelerometer, band_hz: [50, 10]}\n", acc, "the low edge (50 Hz) must be below the high edge (10 Hz)"},
           {"instruments:\n  x: {type: accelerometer, band_hz: 50}\n", acc, "instruments.x.band_hz must be [low, high] in Hz"},
           {"instruments:\n  accelerometer: {mass_kg: 10.001}\n", acc, "instruments.accelerometer.mass_kg must be between 0 and 10 kg (got 10.001)"},
           {"instruments:\n  accelerometer: {mass_kg: -0.001}\n", acc, "must be between 0 and 10 kg (got -0.001)"},
           {"instruments:\n  encoder: {mass_kg: 0.1}\n", acc, "its mass is the torquer's"},
           {"instruments:\n  x: {type: accelerometer, color: red}\n", acc, "unknown key 'instruments.x.color'"},
           {"instruments:\n  accelerometer: {mass_kg: 0.005}\n", "  - {name: a, type: accelerometer, point: link2.h3}\n",
            "sensors[0] (a): its instrument accelerometer weighs 0.005 kg, welded on the article where it sits, and 'link2.h3' is a point of the mesh"},
           {"instruments:\n  accelerometer: {mass_kg: 0.005}\n", "  - {name: a, type: accelerometer, point: joint2}\n",
            "'joint2' is not on a link"},
           {"instruments:\n  acc_small: {type: accelerometer}\n", "  - {name: a, instrument: acc_smal, point: link2@1.0m}\n",
            "sensors[0].instrument: unknown instrument 'acc_smal' (did you mean 'acc_small'?)"},
           {"instruments:\n  acc_small: {type: accelerometer}\n", "  - {name: a, type: rate_gyro, instrument: acc_small, point: link2@1.0m}\n",
            "sensors[0].type: rate_gyro, but its instrument acc_small is an accelerometer"},
       }) {
    const std::string e = catalogueErrorOf(withCatalogue(c.instruments, c.sensors));
    EXPECT_NE(e.find(c.message), std::string::npos) << c.instruments << c.sensors << " -> " << e;
    EXPECT_NE(e.find("s.yaml:"), std::string::npos) << e;  // with its position
  }
  // The bounds themselves are accepted.
  for (const char* ok : {"instruments:\n  accelerometer: {mass_kg: 10}\n", "instruments:\n  accelerometer: {mass_kg: 0}\n",
                         "instruments:\n  x: {type: accelerometer, axes: 3, size_m: 1}\n"})
    EXPECT_EQ(catalogueErrorOf(withCatalogue(ok, "  - {name: a, type: accelerometer, point: link2@1.0m}\n")), "(no error)") << ok;
}

}  // namespace
}  // namespace mmv
