// A strain sensor in a time run (`type: strain`, `span: [A, B]`): a gauge (no high-pass)
// on a horizontal cantilever sagging under its own weight reads the beam's mean surface
// strain over its span, computed here from the bending moment w (L - x)^2 / 2; the
// report's piezo film (0.1 Hz high-pass, assumed) holds no static strain and reads zero.
#include <gtest/gtest.h>

#include <cmath>

#include "sim/time/simulation.hpp"
#include "support/record_column.hpp"

namespace mmv {
namespace {

const char* kCantilever = R"(name: sagging cantilever
gravity: [0, -9.81, 0]
materials:
  steel: {density: 7800, youngs_modulus: 2.0e11}
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
  std::string spatial = base + "model: spatial\n";
  EXPECT_THROW(parseScene(spatial, "c.yaml"), SceneError);
}

}  // namespace
}  // namespace mmv
