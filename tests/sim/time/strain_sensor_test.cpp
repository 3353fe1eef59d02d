// A strain sensor in a time run (`type: strain`, `span: [A, B]`): a gauge (no high-pass)
// on a horizontal cantilever sagging under its own weight reads the beam's mean surface
// strain over its span, computed here from the bending moment w (L - x)^2 / 2; the
// report's piezo film (0.1 Hz high-pass, assumed) holds no static strain and reads zero.
#include <gtest/gtest.h>

#include <cmath>
#include <tuple>

#include "sim/time/simulation.hpp"
#include "support/record_column.hpp"

namespace mmv {
namespace {

const char* kCantilever = R"(name: sagging cantilever
gravity: [0, -9.81, 0]
materials:
  steel: {density: 7800, youngs_modulus: 2.0e11, poisson_ratio: 0.3}
sections:
  flat: {shape: rectangle, b: 0.05, h: 0.01}
joints:
  - {name: j1, parent: base, angle_deg: 0, hold: locked}
links:
  - {name: beam, joint: j1, material: steel, section: flat, length: 1.0, segments: 32}
simulation: {duration: 0.05, sample_rate_hz: 200, start: equilibrium}
instruments:
  gauge: {type: strain, band_hz: [0, 50], resolution: 1.0e-9}
sensors:
  - {name: g, instrument: gauge, span: [beam@0.2m, beam@0.6m]}
  - {name: film, type: strain, span: [beam@0.2m, beam@0.6m]}
  - {name: g_reversed, instrument: gauge, span: [beam@0.6m, beam@0.2m]}
)";

TEST(StrainSensor, AGaugeReadsTheSaggingBeamsStrainAndTheFilmHoldsNone) {
  const ArticleScene s = std::get<ArticleScene>(parseScene(kCantilever, "cantilever.yaml"));
  const SimulationResult r = simulate(s);
  // Mean of c M(x) / (E I) over [a, b] with M = w (L - x)^2 / 2: the top face in tension.
  const double E = 2.0e11, b = 0.05, h = 0.01, rho = 7800, g = 9.81, L = 1.0, xa = 0.2, xb = 0.6;
  const double w = rho * b * h * g, EI = E * b * h * h * h / 12, c = h / 2;
  const double expected = c / EI * w * (std::pow(L - xa, 3) - std::pow(L - xb, 3)) / (6 * (xb - xa));
  using testing::column;
  const int gauge = column(r.record, "g_m_per_m"), film = column(r.record, "film_m_per_m"), back = column(r.record, "g_reversed_m_per_m");
  ASSERT_FALSE(r.record.rows.empty());
  for (const auto& row : r.record.rows) {
    EXPECT_NEAR(row[gauge], expected, 0.005 * expected) << "t = " << row[0];  // 42.9 microstrain
    EXPECT_NEAR(row[back], row[gauge], 1e-9);  // the span's order does not change the strain
    EXPECT_NEAR(row[film], 0.0, 1e-8);         // one count of its resolution
  }
  std::printf("[strain] gauge %.6g against %.6g (%.3f %%)\n", r.record.rows[0][gauge], expected,
              100 * (r.record.rows[0][gauge] / expected - 1));
}

TEST(StrainSensor, BadSpansAreRefusedAtTheirKeys) {
  const std::string base = kCantilever;
  const std::string good = "span: [beam@0.2m, beam@0.6m]";
  struct Case {
    std::string replace, message;
  };
  for (const Case& k : {Case{"span: [beam@0.2m]", "sensors[0].span must be [STATION, STATION]"},
                        Case{"span: [beam@0.2m, beam@0.2m]", "sensors[0].span: the span is empty"},
                        Case{"span: [beam@0.2m+0.005m, beam@0.6m]", "without an offset"},
                        Case{"span: [beam.h3, beam@0.6m]", "a strain spans two stations of one link"},
                        Case{"span: [beam@0.2m, beam@1.6m]", "beam@1.6m"},
                        Case{"span: [beam@0.2m, beam@0.6m], point: beam.tip", "a strain sensor reads its span"}}) {
    std::string text = base;
    text.replace(text.find(good), good.size(), k.replace);
    try {
      parseScene(text, "c.yaml");
      ADD_FAILURE() << k.replace << ": accepted";
    } catch (const SceneError& e) {
      EXPECT_NE(std::string(e.what()).find(k.message), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("c.yaml:"), std::string::npos) << e.what();
    }
  }
  std::string rigid = base;
  rigid.replace(rigid.find("segments: 32"), 12, "segments: rigid");
  EXPECT_THROW(parseScene(rigid, "c.yaml"), SceneError);
  // Bending out of the plane: the spatial model's; the planar one is refused at the key,
  // as is a word other than in or out.
  for (const auto& [extra, bending, message] :
       {std::tuple{"", "out", "sensors[0].bending: the planar model does not bend out of its plane"},
        std::tuple{"model: spatial\n", "sideways", "sensors[0].bending: 'sideways' is not in or out"}}) {
    std::string text = base + extra;
    text.replace(text.find(good), good.size(), good + ", bending: " + bending);
    try {
      parseScene(text, "c.yaml");
      ADD_FAILURE() << bending << ": accepted";
    } catch (const SceneError& e) {
      EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << e.what();
    }
  }
  std::string accel = base;
  const std::string film = "- {name: film, type: strain, span: [beam@0.2m, beam@0.6m]}";
  accel.replace(accel.find(film), film.size(),
                "- {name: film, type: accelerometer, point: beam.tip, bending: in}");
  EXPECT_THROW(parseScene(accel, "c.yaml"), SceneError);
}

// The spatial model (issue 34: the report's film reads deflection in and out of the
// plane): the same cantilever under a 10 N tip load along -z (a dead load; gravity stays
// in the plane) bends about its 50 mm width, I = h b^3 / 12, and the +z face's gauge
// (bending: out) reads the closed form c P (L - x_mid) / (E I) with c = b / 2, while the
// in-plane gauge reads nothing; sagging in the plane under gravity, the spatial model's
// in-plane gauge reads the planar closed form (two models, one number).
TEST(StrainSensor, TheSpatialModelsGaugesReadBendingInAndOutOfThePlane) {
  const double E = 2.0e11, b = 0.05, h = 0.01, rho = 7800, g = 9.81, L = 1.0, xa = 0.2, xb = 0.6, P = 10;
  const double w = rho * b * h * g, sag = w * (std::pow(L - xa, 3) - std::pow(L - xb, 3)) / (6 * (xb - xa));
  const double in_plane = h / 2 * sag / (E * b * h * h * h / 12), out_of_plane = b / 2 * P * (L - 0.5 * (xa + xb)) / (E * h * b * b * b / 12);
  std::string text = kCantilever;
  text += "model: spatial\n";
  const std::string film = "- {name: film, type: strain, span: [beam@0.2m, beam@0.6m]}";
  text.replace(text.find(film), film.size(), "- {name: out, instrument: gauge, span: [beam@0.2m, beam@0.6m], bending: out}");
  using testing::column;
  const SimulationResult sag_in = simulate(std::get<ArticleScene>(parseScene(text, "c.yaml")));
  text.replace(text.find("gravity: [0, -9.81, 0]"), 22, "gravity: [0, 0, 0]");
  text += "loads:\n  - {point: beam.tip, force: [0, 0, -10]}\n";
  const SimulationResult load_out = simulate(std::get<ArticleScene>(parseScene(text, "c.yaml")));
  for (const auto* r : {&sag_in, &load_out}) ASSERT_FALSE(r->record.rows.empty());
  const int gi = column(sag_in.record, "g_m_per_m"), go = column(load_out.record, "out_m_per_m");
  const double read_in = sag_in.record.rows[0][gi], read_out = load_out.record.rows[0][go];
  std::printf("[strain] spatial: in the plane %.6g against %.6g, out of it %.6g against %.6g\n", read_in, in_plane, read_out, out_of_plane);
  EXPECT_NEAR(read_in, in_plane, 0.005 * in_plane);
  EXPECT_NEAR(read_out, out_of_plane, 0.005 * out_of_plane);  // the +z face in tension under a load towards -z
  EXPECT_NEAR(sag_in.record.rows[0][column(sag_in.record, "out_m_per_m")], 0.0, 1e-6 * in_plane);
  EXPECT_NEAR(load_out.record.rows[0][column(load_out.record, "g_m_per_m")], 0.0, 1e-6 * out_of_plane);
  // A load out of the plane is the spatial model's: the planar one refuses it at its key.
  std::string planar = kCantilever;
  planar += "loads:\n  - {point: beam.tip, force: [0, 0, -10]}\n";
  try {
    parseScene(planar, "c.yaml");
    ADD_FAILURE() << "a load along z on the planar model: accepted";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("loads[0].force[2] must be 0 N: the planar article"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace mmv
