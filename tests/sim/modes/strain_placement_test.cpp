// Strain gauges and piezo films as placement candidates (issue 34, place-sensors
// --strain-span): each candidate's row is the mean surface strain over its span per unit
// modal coordinate, the row `modes --strain` reports for the same span (two ways), and on
// a uniform cantilever the Euler-Bernoulli mode's curvature averaged over the span, as
// the closed form written here gives it; one film for the first mode goes at the root,
// where its curvature is largest; SEREP on the chosen films reproduces the targets.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "article/beam_theory.hpp"
#include "sim/app/plan_studies.hpp"
#include "sim/core/errors.hpp"
#include "sim/core/text.hpp"
#include "sim/io/placement_report.hpp"
#include "sim/modes/place_sensors.hpp"
#include "sim/modes/system_modes.hpp"
#include "sim/scene/stations.hpp"
#include "sim/scene/scene.hpp"

namespace mmv {
namespace {

// A 1 m steel cantilever, 20 x 10 mm, bending about its 10 mm depth in the plane.
const char* kCantilever = R"(name: strained cantilever
gravity: [0, 0, 0]
materials:
  steel: {density: 7800, youngs_modulus: 2.0e11}
sections:
  bar: {shape: rectangle, b: 0.02, h: 0.01}
joints:
  - {name: j1, parent: base, angle_deg: 0, hold: locked}
links:
  - {name: beam, joint: j1, material: steel, section: bar, length: 1.0, segments: 32}
)";

std::string spatialCantilever() {
  std::string text = std::string(kCantilever) + "model: spatial\n";
  return text.replace(text.find("youngs_modulus: 2.0e11}"), 23, "youngs_modulus: 2.0e11, poisson_ratio: 0.3}");
}

ArticleScene cantilever() { return std::get<ArticleScene>(parseScene(kCantilever, "cantilever.yaml")); }

TEST(StrainPlacement, ACandidatesRowIsModesStrainOverItsSpan) {
  const ArticleScene scene = std::get<ArticleScene>(loadSceneFile(std::string(MMVLAB_SOURCE_DIR) + "/scenes/mmv.yaml"));
  PlacementOptions o;
  o.modes = modeNumbers({1, 2, 3, 4, 5, 6});
  o.count = 8;
  o.strain_span_m = 0.3;
  o.spacing_m = 0.2;
  const PlacementStudy p = runPlacement(scene, o);
  ASSERT_TRUE(p.strain);
  ASSERT_GT(p.candidates.size(), 20u);
  ModesOptions m;
  m.max_modes = 6;
  for (const PlacementCandidate& c : p.candidates) {
    const auto colon = c.station.find(':');
    ASSERT_NE(colon, std::string::npos) << c.station;
    StrainGaugeSpec g{c.station, c.station.substr(0, colon), c.station.substr(colon + 1), 0, 0};
    std::string why;
    const auto span = strainSpan(scene.article, g.a, g.b, why);
    ASSERT_TRUE(span.has_value()) << why;
    g.surface_m = span->surface_m, g.span_m = span->x_b - span->x_a;
    EXPECT_NEAR(g.span_m, 0.3, 1e-9) << c.station;
    EXPECT_EQ(c.axis, "strain");
    m.strains.push_back(g);
  }
  const ModesReport r = runModes(scene, m);
  double worst = 0, scale = 0;
  for (std::size_t i = 0; i < p.candidates.size(); ++i)
    for (std::size_t j = 0; j < 6; ++j) {
      const double by_modes = r.modes[j].strains[i].strain, by_placement = p.candidates[i].strain[j];
      worst = std::max(worst, std::abs(by_modes - by_placement));
      scale = std::max(scale, std::abs(by_modes));
    }
  EXPECT_GT(scale, 0.0);
  EXPECT_LT(worst, 1e-10 * scale);
  // Every chosen film's span lies on its link, none in the other's stretch twice.
  EXPECT_EQ(p.result.kept_blocks.size(), 8u);
  EXPECT_GT(p.result.fisher_determinant, 0.0);
}

TEST(StrainPlacement, OnACantileverTheRowIsTheModesMeanCurvatureAndOneFilmGoesAtTheRoot) {
  const ArticleScene scene = cantilever();
  PlacementOptions o;
  o.modes = modeNumbers({1, 2});
  o.count = 2;
  o.strain_span_m = 0.1;
  o.spacing_m = 0.05;
  // Euler-Bernoulli: phi(x) = cosh bx - cos bx - s (sinh bx - sin bx), with int phi^2 = L,
  // mass-normalised by 1 / sqrt(rho A L); the strain over [a, b] is -c (phi'(b) - phi'(a)) / (b - a).
  const double L = 1.0, rhoA = 7800 * 0.02 * 0.01, c = 0.005;
  const std::vector<double> roots = beamRoots(BeamEnd::Clamped, BeamEnd::Free, 0.0, 0.0, 2);
  // The largest difference over every span and both modes, over the mode's largest strain.
  auto gap = [&](const PlacementStudy& p) {
    double worst = 0;
    for (int j = 0; j < 2; ++j) {
      const double beta = roots[static_cast<std::size_t>(j)] / L;
      const double bl = beta * L, sg = (std::cosh(bl) + std::cos(bl)) / (std::sinh(bl) + std::sin(bl));
      const auto slope = [&](double x) {
        return beta * (std::sinh(beta * x) + std::sin(beta * x) - sg * (std::cosh(beta * x) - std::cos(beta * x))) / std::sqrt(rhoA * L);
      };
      double peak = 0, err = 0;
      for (const PlacementCandidate& cand : p.candidates) {
        const double xa = cand.x_m - 0.05, xb = cand.x_m + 0.05;
        const double closed = -c * (slope(xb) - slope(xa)) / (xb - xa);
        peak = std::max(peak, std::abs(closed));  // the model's sign is its own
        err = std::max(err, std::abs(std::abs(cand.strain[static_cast<std::size_t>(j)]) - std::abs(closed)));
      }
      worst = std::max(worst, err / peak);
    }
    return worst;
  };
  const double at32 = gap(runPlacement(scene, o));
  ArticleScene fine = scene;
  overrideSegments(fine, 64);
  const double at64 = gap(runPlacement(fine, o));
  std::printf("[strain placement] cantilever: rows against the closed form's mean curvature, %.3g of the peak at 32 segments, "
              "%.3g at 64\n", at32, at64);
  EXPECT_LT(at32, 0.015);  // measured 1.15 % (mode 2), 0.29 % for mode 1
  EXPECT_LT(at64, 0.003);
  EXPECT_GT(at32 / at64, 3.5);  // converging to the closed form at second order (measured 5.9x)

  // One film for mode 1: at the root, where the first mode's curvature is largest.
  o.modes = modeNumbers({1});
  o.count = 1;
  const PlacementStudy one = runPlacement(scene, o);
  EXPECT_EQ(one.candidates[static_cast<std::size_t>(one.result.kept_blocks[0])].station, "beam@0m:beam@0.1m");

  // SEREP on films for the first three modes reproduces them.
  o.modes = modeNumbers({1, 2, 3});
  o.count = 3;
  o.tam = {TamMethod::Serep};
  const PlacementStudy three = runPlacement(scene, o);
  ASSERT_EQ(three.tams.size(), 1u);
  for (const auto& m : three.tams[0].modes) EXPECT_NEAR(m.frequency_error, 0.0, 1e-6);
  EXPECT_TRUE(three.tams[0].pass);
}

// The spatial model: every span is two candidates, the +y face's bending in the plane and
// the +z face's out of it (A:B:out). Each row is modes --strain's over the same span and
// face (two ways), and an out-of-plane mode's is the Euler-Bernoulli mode's mean
// curvature about the 20 mm width (c = b / 2, I = h b^3 / 12) written here; one film for
// that mode goes at the root, on the +z face.
TEST(StrainPlacement, OnTheSpatialModelFilmsReadBendingOutOfThePlaneToo) {
  ArticleScene scene = std::get<ArticleScene>(parseScene(spatialCantilever(), "cantilever.yaml"));
  PlacementOptions o;
  o.modes = modeNumbers({1, 2, 3, 4});
  o.count = 4;
  o.strain_span_m = 0.1;
  o.spacing_m = 0.05;
  const PlacementStudy p = runPlacement(scene, o);
  ModesOptions m;
  m.max_modes = 4;
  int out = 0;
  for (const PlacementCandidate& c : p.candidates) {
    const auto parts = split(c.station, ':');
    ASSERT_TRUE(parts.size() == 2 || (parts.size() == 3 && parts[2] == "out")) << c.station;
    std::string why;
    const auto span = strainSpan(scene.article, parts[0], parts[1], why, parts.size() == 3);
    ASSERT_TRUE(span.has_value()) << why;
    m.strains.push_back({c.station, parts[0], parts[1], span->surface_m, span->x_b - span->x_a, parts.size() == 3});
    out += parts.size() == 3 ? 1 : 0;
  }
  EXPECT_EQ(2 * out, static_cast<int>(p.candidates.size()));
  const ModesReport r = runModes(scene, m);
  double worst = 0, scale = 0;
  for (std::size_t i = 0; i < p.candidates.size(); ++i)
    for (std::size_t j = 0; j < 4; ++j) {
      worst = std::max(worst, std::abs(r.modes[j].strains[i].strain - p.candidates[i].strain[j]));
      scale = std::max(scale, std::abs(r.modes[j].strains[i].strain));
    }
  EXPECT_GT(scale, 0.0);
  EXPECT_LT(worst, 1e-10 * scale);
  // The first out-of-plane mode: bending about the 20 mm width, 2x the in-plane frequency.
  const double L = 1.0, rhoA = 7800 * 0.02 * 0.01, b = 0.02, h = 0.01, E = 2.0e11, I_out = h * b * b * b / 12;
  const double beta = beamRoots(BeamEnd::Clamped, BeamEnd::Free, 0.0, 0.0, 1)[0] / L;
  const double f_out = beta * beta * std::sqrt(E * I_out / rhoA) / (2 * M_PI);
  std::size_t j = 4;
  for (std::size_t k = 0; k < 4; ++k)
    if (std::abs(r.modes[k].frequency_hz / f_out - 1) < 0.01) j = k;
  ASSERT_LT(j, 4u) << "no mode near " << f_out << " Hz";
  const double bl = beta * L, sg = (std::cosh(bl) + std::cos(bl)) / (std::sinh(bl) + std::sin(bl));
  const auto slope = [&](double x) {
    return beta * (std::sinh(beta * x) + std::sin(beta * x) - sg * (std::cosh(beta * x) - std::cos(beta * x))) / std::sqrt(rhoA * L);
  };
  double peak = 0, err = 0, in_plane = 0;
  for (const PlacementCandidate& c : p.candidates) {
    if (c.station.find(":out") == std::string::npos) {
      in_plane = std::max(in_plane, std::abs(c.strain[j]));  // the out-of-plane mode bends no +y face
      continue;
    }
    const double closed = b / 2 * (slope(c.x_m + 0.05) - slope(c.x_m - 0.05)) / 0.1;
    peak = std::max(peak, std::abs(closed));
    err = std::max(err, std::abs(std::abs(c.strain[j]) - std::abs(closed)));
  }
  std::printf("[strain placement] spatial cantilever: out-of-plane mode %zu (%.4g Hz) against the closed form, %.3g of the peak\n",
              j + 1, r.modes[j].frequency_hz, err / peak);
  EXPECT_LT(err / peak, 0.015);
  EXPECT_LT(in_plane, 1e-9 * peak);
  o.modes = modeNumbers({static_cast<int>(j) + 1});
  o.count = 1;
  const PlacementStudy one = runPlacement(scene, o);
  EXPECT_EQ(one.candidates[static_cast<std::size_t>(one.result.kept_blocks[0])].station, "beam@0m:beam@0.1m:out");
}

TEST(StrainPlacement, RequestsTheFilmsCannotMeetAreRefusedByName) {
  const Scene scene = cantilever();
  const Scene isolator = loadSceneFile(std::string(MMVLAB_SOURCE_DIR) + "/scenes/hamsas.yaml");
  const auto refused = [](const Scene& s, app::PlacementRequest r, const std::string& message) {
    r.count = 2;
    try {
      app::runPlacementStudy(s, r);
      ADD_FAILURE() << message << ": accepted";
    } catch (const UsageError& e) {
      EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << e.what();
    }
  };
  app::PlacementRequest r;
  r.modes = {1, 2};
  r.strain_span_m = 0.1;
  app::PlacementRequest bad = r;
  bad.strain_span_m = 0.00099;  // one past the 1 mm bound
  refused(scene, bad, "--strain-span");
  bad.strain_span_m = 100.1;
  refused(scene, bad, "--strain-span");
  bad.strain_span_m = 100;  // at the bound: accepted, and no link is that long
  refused(scene, bad, "no flexible link is that long");
  bad = r, bad.method = "mke";
  refused(scene, bad, "effective independence only");
  bad = r, bad.triaxial = true;
  refused(scene, bad, "place them uniaxial");
  bad = r, bad.sensor_mass_kg = 0.001;
  refused(scene, bad, "massless");
  refused(isolator, r, "applies to the article's scenes");
  bad = r, bad.strain_span_m = 0.001;  // at the bound: a 1 mm gauge, placed
  bad.count = 2;
  bad.spacing_m = 0.1;
  const app::PlacementStudyResult ok = app::runPlacementStudy(scene, bad);
  EXPECT_EQ(ok.study.result.kept_blocks.size(), 2u);
  EXPECT_NE(ok.channels_csv.find(",strain,m/m,"), std::string::npos) << ok.channels_csv;
  EXPECT_TRUE(ok.geometry_uff.empty());
}

// Films do not overlap on a link's face, over seeded random requests (spans, spacings,
// counts, separations); when that leaves fewer than asked for, the text says so.
TEST(StrainPlacement, ChosenFilmsNeverOverlapAndAShortfallIsWarned) {
  const ArticleScene scene = std::get<ArticleScene>(loadSceneFile(std::string(MMVLAB_SOURCE_DIR) + "/scenes/mmv.yaml"));
  ArticleScene coarse = scene;
  overrideSegments(coarse, 8);
  std::mt19937 rng(34);
  std::uniform_real_distribution<double> span(0.05, 0.5), spacing(0.02, 0.2), separation(0, 0.3);
  int shortfalls = 0;
  for (int k = 0; k < 20; ++k) {
    PlacementOptions o;
    o.modes = modeNumbers({1, 2, 3, 4});
    o.strain_span_m = span(rng);
    o.spacing_m = spacing(rng);
    o.min_separation_m = k % 2 ? separation(rng) : 0.0;
    o.count = 4 + k;
    PlacementStudy p;
    try {
      p = runPlacement(coarse, o);
    } catch (const UsageError& e) {  // too few spans left for the modes: refused by name
      EXPECT_NE(std::string(e.what()).find("--"), std::string::npos) << e.what();
      continue;
    }
    for (std::size_t i = 0; i < p.result.kept_blocks.size(); ++i)
      for (std::size_t j = i + 1; j < p.result.kept_blocks.size(); ++j) {
        const PlacementCandidate &a = p.candidates[static_cast<std::size_t>(p.result.kept_blocks[i])],
                                 &b = p.candidates[static_cast<std::size_t>(p.result.kept_blocks[j])];
        if (a.link == b.link) EXPECT_GE(std::abs(a.x_m - b.x_m), o.strain_span_m * (1 - 1e-6)) << a.station << " and " << b.station;
      }
    const bool short_of = static_cast<int>(p.result.kept_blocks.size()) < o.count;
    shortfalls += short_of;
    EXPECT_EQ(placementText(p).find(strf("warning: %zu of the %d asked for", p.result.kept_blocks.size(), o.count)) != std::string::npos,
              short_of);
  }
  EXPECT_GT(shortfalls, 0);  // the warning's case occurred
}

}  // namespace
}  // namespace mmv
