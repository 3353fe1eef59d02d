// The shaker's pre-test analysis (sim/linear/exciter.hpp): its levels against the
// closed forms of a single mode and against the modal sum computed from the
// placement's own shapes, its limits met exactly where they bind, and the ranking's
// first-order armature shift against the loaded model's exact one.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>

#include "facility/sensors.hpp"
#include "sim/app/linear_study.hpp"
#include "sim/linear/exciter.hpp"
#include "sim/linear/table_levels.hpp"
#include "sim/modes/system_modes.hpp"
#include "sim/scene/scene.hpp"

namespace mmv {
namespace {

ArticleScene scene(const std::vector<std::string>& sets, double zeta) {
  ArticleScene s = std::get<ArticleScene>(parseScene(defaultSceneYaml(), "<default scene>", sets));
  s.gravity = {0, 0, 0};
  s.damping = DampingSpec{};
  s.damping->modal_ratio = zeta;
  return s;
}

ShakerSceneSpec shaker(const std::string& at, std::array<double, 3> dir, double force, double stroke, double armature) {
  ShakerSceneSpec s;
  s.at = at;
  const double n = std::sqrt(dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2]);
  s.direction = {dir[0] / n, dir[1] / n, dir[2] / n};
  s.hardware.force_limit = force;
  s.hardware.stroke = stroke;
  s.hardware.armature_mass = armature;
  return s;
}

double along(const std::array<double, 3>& u, const std::array<double, 3>& e) { return u[0] * e[0] + u[1] * e[1] + u[2] * e[2]; }

const PlacementCandidate& candidateAt(const PlacementStudy& p, const std::string& station) {
  auto c = std::find_if(p.candidates.begin(), p.candidates.end(), [&](const PlacementCandidate& c) { return c.station == station; });
  EXPECT_NE(c, p.candidates.end()) << station;
  return *c;
}

/// Each chosen sensor direction's shape component for target j.
std::vector<double> sensorShapes(const PlacementStudy& p, std::size_t j) {
  std::vector<char> kept(p.candidates.size(), 0);
  for (int b : p.result.kept_blocks) kept[static_cast<std::size_t>(b)] = 1;
  std::vector<double> u;
  for (const auto& d : p.directions)
    if (kept[static_cast<std::size_t>(d.block)]) u.push_back(along(p.candidates[static_cast<std::size_t>(d.block)].shape[j], d.world));
  return u;
}

// One degree of freedom (link 1 in one segment, the rest rigid): at resonance the
// response is F u_s u_d / (2 zeta) in acceleration and F u_d^2 / (2 zeta omega^2) at the
// driving point; under a flat force spectrum G the driving point's mean square is
// G u_d^4 / (8 zeta omega^3), the integral of |H|^2 over f from 0 to infinity (the
// band's ends cut off less than 0.1 % of it here).
TEST(Exciter, ASingleModeMeetsItsClosedForms) {
  ArticleScene s = scene({"links.link1.segments=1", "links.link2.segments=rigid", "links.link3.segments=rigid"}, 0.02);
  PlacementOptions o;
  o.modes = {ModeNumber(1)};
  o.count = 3;
  const PlacementStudy p = runPlacement(s, o);
  const std::array<double, 3> dir{0.3, 1, 0};
  s.shaker = shaker("link1@2m", dir, 0.01, 10, 0);
  const ExciterStudy e = runExciter(s, p);
  ASSERT_EQ(e.modes.size(), 1u);
  const auto& m = e.modes[0];
  const double zeta = 0.02, w = 2 * M_PI * p.target_frequencies_hz[0], F = 0.01;
  EXPECT_NEAR(m.loaded_hz / p.target_frequencies_hz[0], 1.0, 1e-10);
  EXPECT_NEAR(m.zeta, zeta, 1e-10);
  const double ud = along(candidateAt(p, "link1@2m").shape[0], s.shaker->direction);
  double us = 0;
  for (double u : sensorShapes(p, 0)) us = std::max(us, std::abs(u));
  ASSERT_GT(std::abs(ud) * us, 0.0);
  EXPECT_EQ(m.sine_limit, "force");
  EXPECT_NEAR(m.sine_acc / (F * us * std::abs(ud) / (2 * zeta)), 1.0, 1e-8);
  EXPECT_NEAR(m.sine_stroke_m / (F * ud * ud / (2 * zeta * w * w)), 1.0, 1e-8);
  const facility::SensorSpec acc = facility::accelerometerSpec();
  EXPECT_NEAR(m.sine_snr_db, 20 * std::log10(m.sine_acc / acc.resolution), 1e-9);
  // Random: the RMS force is F / 3 (the crest factor) over the band.
  const auto& r = e.random;
  EXPECT_EQ(r.limit, "force");
  const double G = std::pow(F / 3, 2) / (r.f_max_hz - r.f_min_hz);
  EXPECT_NEAR(r.stroke_rms_m / std::sqrt(G * std::pow(ud, 4) / (8 * zeta * w * w * w)), 1.0, 0.01);
  const double noise = acc.resolution * acc.resolution / (6 * s.simulation.sample_rate_hz);
  EXPECT_NEAR(m.random_snr_db, 10 * std::log10(std::pow(us * ud / (2 * zeta), 2) * G / noise), 1e-6);
}

// Four modes, each a target: at each target's frequency the response is the modal sum
// over all four, built here from the placement's station shapes (a second way to the
// linear model's Jacobian rows and its modal solution).
TEST(Exciter, SineLevelsAreTheModalSumOfThePlacementsShapes) {
  ArticleScene s = scene({}, 0.015);
  overrideSegments(s, 1);
  PlacementOptions o;
  o.modes = {ModeNumber(1), ModeNumber(2), ModeNumber(3), ModeNumber(4)};
  o.count = 6;
  const PlacementStudy p = runPlacement(s, o);
  ASSERT_EQ(p.target_modes.size(), 4u);
  s.shaker = shaker("link2@1m", {1, 1, 0}, 1e-3, 10, 0);
  const ExciterStudy e = runExciter(s, p);
  const auto& d = candidateAt(p, "link2@1m");
  std::vector<std::vector<double>> us;
  for (std::size_t k = 0; k < 4; ++k) us.push_back(sensorShapes(p, k));
  for (std::size_t r = 0; r < 4; ++r) {
    const double w = 2 * M_PI * p.target_frequencies_hz[r];
    double best = 0, stroke = 0;
    for (std::size_t c = 0; c < us[0].size(); ++c) {
      std::complex<double> a = 0, x = 0;
      for (std::size_t k = 0; k < 4; ++k) {
        const double wk = 2 * M_PI * p.target_frequencies_hz[k], ud = along(d.shape[k], s.shaker->direction);
        const std::complex<double> h = 1.0 / std::complex<double>(wk * wk - w * w, 2 * 0.015 * wk * w);
        a += w * w * us[k][c] * ud * h;
        if (c == 0) x += ud * ud * h;
      }
      best = std::max(best, std::abs(a));
      if (c == 0) stroke = std::abs(x);
    }
    EXPECT_NEAR(e.modes[r].sine_acc / (1e-3 * best), 1.0, 1e-8) << "mode " << r + 1;
    EXPECT_NEAR(e.modes[r].sine_stroke_m / (1e-3 * stroke), 1.0, 1e-8) << "mode " << r + 1;
  }
}

// Where a limit binds, the level sits exactly on it and the force is below the shaker's.
TEST(Exciter, StrokeAndRangeBindExactly) {
  ArticleScene s = scene({}, 0.01);
  overrideSegments(s, 2);
  PlacementOptions o;
  o.count = 10;
  const PlacementStudy p = runPlacement(s, o);
  ASSERT_GE(p.target_modes.size(), 4u);
  s.shaker = shaker("link2@1.2m", {0, 1, 0}, 100, 1e-7, 0);
  const ExciterStudy tight = runExciter(s, p);
  for (const auto& m : tight.modes) {
    EXPECT_EQ(m.sine_limit, "stroke") << m.mode.number();
    EXPECT_NEAR(m.sine_stroke_m, 1e-7, 1e-18);
    EXPECT_LT(m.sine_force_n, 100);
  }
  EXPECT_EQ(tight.random.limit, "stroke");
  EXPECT_NEAR(3 * tight.random.stroke_rms_m, 1e-7, 1e-18);
  s.shaker = shaker("link2@1.2m", {0, 1, 0}, 1e6, 10, 0);
  const ExciterStudy strong = runExciter(s, p);
  for (const auto& m : strong.modes) {
    EXPECT_EQ(m.sine_limit, "range") << m.mode.number();
    EXPECT_NEAR(m.sine_acc, strong.range, 1e-9 * strong.range);
    EXPECT_NEAR(m.sine_snr_db, 20 * std::log10(strong.range / strong.resolution), 1e-9);
  }
  EXPECT_EQ(strong.random.limit, "range");
  EXPECT_NEAR(3 * strong.random.rms_acc, strong.range, 1e-9 * strong.range);
}

// The ranking's first-order armature shift, -m_a (u . d)^2 / 2, against the loaded
// model's exact frequencies for a light armature; and its order: scores in [0, 1],
// falling within each group, every attachment that loads the article after every one
// that does not; `auto` attaches at the first.
TEST(Exciter, TheRankingsArmatureShiftIsFirstOrderAndItsOrderHolds) {
  ArticleScene s = scene({}, 0.01);
  overrideSegments(s, 4);
  PlacementOptions o;
  o.count = 8;
  const PlacementStudy p = runPlacement(s, o);
  const double armature = 2e-4;
  s.shaker = shaker("link2@1.3m", {0, 1, 0}, 1, 1, armature);
  const ExciterStudy e = runExciter(s, p);
  const auto& d = candidateAt(p, "link2@1.3m");
  for (std::size_t j = 0; j < e.modes.size(); ++j) {
    const double first = -0.5 * armature * std::pow(along(d.shape[j], {0, 1, 0}), 2);
    const double exact = e.modes[j].loaded_hz / e.modes[j].frequency_hz - 1;
    EXPECT_EQ(e.modes[j].loaded_mode, e.modes[j].mode);
    EXPECT_LE(exact, 0.0);
    EXPECT_NEAR(exact, first, 0.01 * std::abs(first) + 1e-12) << "mode " << j + 1;
  }
  const std::vector<ExciterCandidate> heavy = rankExciterCandidates(p, 0.5);
  ASSERT_EQ(heavy.size(), p.directions.size());
  bool loads_seen = false;
  int loading = 0;
  for (std::size_t i = 0; i < heavy.size(); ++i) {
    const auto& c = heavy[i];
    EXPECT_GE(c.score, 0.0);
    EXPECT_LE(c.score, 1.0);
    EXPECT_EQ(c.loads, std::abs(c.max_shift) > kArmatureShiftLimit);
    if (loads_seen) EXPECT_TRUE(c.loads) << "an attachment that does not load after one that does";
    loads_seen = loads_seen || c.loads;
    loading += c.loads;
    if (i > 0 && heavy[i - 1].loads == c.loads) EXPECT_GE(heavy[i - 1].score, c.score);
    double largest = 0;  // the shift again, from the candidate's shapes
    const auto& cand = p.candidates[static_cast<std::size_t>(p.directions[static_cast<std::size_t>(c.direction)].block)];
    for (const auto& u : cand.shape) largest = std::max(largest, 0.5 * 0.5 * std::pow(along(u, c.world), 2));
    EXPECT_NEAR(-c.max_shift, largest, 1e-15);
  }
  EXPECT_GT(loading, 0);  // half a kilogram on the 8 g branches of link 3 loads them
  EXPECT_LT(loading, static_cast<int>(heavy.size()));
  s.shaker = shaker("auto", {0, 1, 0}, 1, 1, 0.5);
  s.shaker->direction = {0, 0, 0};
  s.shaker->auto_direction = true;
  const ExciterStudy chosen = runExciter(s, p);
  EXPECT_TRUE(chosen.chosen);
  EXPECT_EQ(chosen.at, heavy.front().station);
  EXPECT_EQ(chosen.axis, heavy.front().axis);
}

}  // namespace
}  // namespace mmv

namespace mmv {
namespace {

/// One mode on the table (link 1 in one segment, the rest rigid, 2 % damping), and its
/// placement of three sensors.
ArticleScene singleModeOnTable() {
  ArticleScene s = scene({"links.link1.segments=1", "links.link2.segments=rigid", "links.link3.segments=rigid"}, 0.02);
  s.article.base.type = BaseType::Table;
  // No allowables: the stroke and the range alone set these levels (a link's strength
  // binding them: tests/sim/linear/table_strength_test.cpp).
  for (auto& m : s.article.materials) m.yield_strength = m.ultimate_strength = 0;
  return s;
}

PlacementStudy singleModePlacement(const ArticleScene& s) {
  PlacementOptions o;
  o.modes = {ModeNumber(1)};
  o.count = 3;
  return runPlacement(s, o);
}

// The base table's dwell levels (sim/linear/table_levels.hpp) against the closed form of
// one mode: per unit table acceleration along x, a sensor direction e reads the table's
// own e_x and, in quadrature at resonance, the mode's Gamma u_e / (2 zeta) (Gamma^2 the
// mode's effective mass along x, from runModes; u_e the placement's station shape along
// e). With a range too large to bind, the stroke sets the dwell (0.15 m x omega^2); with
// a small one, the best sensor sits exactly on it.
TEST(TableLevels, ASingleModeMeetsItsClosedFormAndItsLimitsBindExactly) {
  const ArticleScene s = singleModeOnTable();
  PlacementStudy p = singleModePlacement(s);
  const ModesReport modes = runModes(s);
  ASSERT_FALSE(modes.modes.empty());
  const double gamma = std::sqrt(modes.modes[0].effective_mass_x_kg), zeta = 0.02;
  const double w = 2 * M_PI * p.target_frequencies_hz[0];
  ASSERT_NEAR(modes.modes[0].frequency_hz / p.target_frequencies_hz[0], 1.0, 1e-9);
  const std::vector<double> u = sensorShapes(p, 0);
  const std::vector<SensorChannel> channels = chosenSensorChannels(p);
  ASSERT_EQ(u.size(), channels.size());
  double best = 0;
  for (std::size_t c = 0; c < u.size(); ++c) best = std::max(best, std::hypot(channels[c].world[0], gamma * u[c] / (2 * zeta)));
  ASSERT_GT(gamma * best, 0.0);
  p.instrument.spec.range = 1e9;
  TableLevels t = runTableLevels(s, p);
  ASSERT_EQ(t.modes.size(), 1u);
  EXPECT_EQ(t.modes[0].axis, "x");
  EXPECT_EQ(t.modes[0].limit, "stroke");
  EXPECT_DOUBLE_EQ(t.modes[0].table_amplitude_m, 0.15);
  EXPECT_NEAR(t.modes[0].table_acc, 0.15 * w * w, 1e-12 * w * w);
  EXPECT_NEAR(t.modes[0].acc / (best * t.modes[0].table_acc), 1.0, 1e-8);
  EXPECT_NEAR(t.modes[0].snr_db, 20 * std::log10(t.modes[0].acc / p.instrument.spec.resolution), 1e-9);
  EXPECT_EQ(t.modes[0].within_bandwidth, p.target_frequencies_hz[0] <= 10);
  const double range = 1e-3 * t.modes[0].acc;
  p.instrument.spec.range = range;
  t = runTableLevels(s, p);
  EXPECT_EQ(t.modes[0].limit, "range");
  EXPECT_NEAR(t.modes[0].acc / range, 1.0, 1e-12);
  EXPECT_NEAR(t.modes[0].table_acc / (range / best), 1.0, 1e-8);
}

// The table's random program, two ways: its largest sensor RMS against frf's own
// absolute accelerations integrated here on 100,000 log-spaced frequencies (times the
// table's acceleration spectrum (2 pi f)^4 G of a flat displacement spectrum G), each
// mode's SNR against frf's spectrum at it, and its two limits met exactly where they bind.
TEST(TableLevels, TheRandomProgramIsFrfsSpectrumAtTheStrokeOrTheRange) {
  const ArticleScene s = singleModeOnTable();
  PlacementStudy p = singleModePlacement(s);
  p.instrument.spec.range = 1e9;
  const TableLevels t = runTableLevels(s, p);
  ASSERT_TRUE(t.random.program);
  ASSERT_TRUE(t.modes[0].within_bandwidth);
  const auto& r = t.random;
  EXPECT_EQ(r.limit, "stroke");
  EXPECT_DOUBLE_EQ(r.rms_m, 0.15 / 3);
  EXPECT_NEAR(r.f_min_hz, std::max(0.1, 0.5 * p.target_frequencies_hz[0]), 1e-12);
  EXPECT_EQ(r.f_max_hz, 10.0);
  const std::vector<SensorChannel> channels = chosenSensorChannels(p);
  app::LinearRequest q;
  q.inputs = {"table_x"};
  for (const auto& c : channels) q.outputs.push_back(c.station + ":x:acc_abs"), q.outputs.push_back(c.station + ":y:acc_abs");
  q.f_min = r.f_min_hz, q.f_max = r.f_max_hz, q.range_given = true, q.points = 100000;
  const app::LinearStudy frf = app::runLinearStudy(s, q);
  const double G = r.rms_m * r.rms_m / (r.f_max_hz - r.f_min_hz);
  auto spectrum = [&](std::size_t i, std::size_t c) {  // channel c's acceleration spectrum at frf.f[i]
    const std::complex<double> a = frf.hf[i](2 * c, 0) * channels[c].world[0] + frf.hf[i](2 * c + 1, 0) * channels[c].world[1];
    return std::norm(a) * std::pow(2 * M_PI * frf.f[i], 4) * G;
  };
  double worst = 0;
  for (std::size_t c = 0; c < channels.size(); ++c) {
    double ms = 0;
    for (std::size_t i = 1; i < frf.f.size(); ++i) ms += 0.5 * (frf.f[i] - frf.f[i - 1]) * (spectrum(i - 1, c) + spectrum(i, c));
    worst = std::max(worst, ms);
  }
  std::printf("[table random] RMS %.6g against frf's %.6g m/s^2\n", r.rms_acc, std::sqrt(worst));
  EXPECT_NEAR(r.rms_acc / std::sqrt(worst), 1.0, 1e-4);  // measured 8e-6
  // The SNR at the mode: frf's spectrum there (a grid point of its own run).
  app::LinearRequest at = q;
  at.f_min = p.target_frequencies_hz[0], at.f_max = 2 * at.f_min, at.points = 2;
  const app::LinearStudy one = app::runLinearStudy(s, at);
  double peak = 0;
  for (std::size_t c = 0; c < channels.size(); ++c) {
    const std::complex<double> a = one.hf[0](2 * c, 0) * channels[c].world[0] + one.hf[0](2 * c + 1, 0) * channels[c].world[1];
    peak = std::max(peak, std::norm(a) * std::pow(2 * M_PI * one.f[0], 4) * G);
  }
  EXPECT_NEAR(t.modes[0].random_snr_db, 10 * std::log10(peak / r.noise_psd), 1e-6);
  EXPECT_NEAR(r.noise_psd, std::pow(p.instrument.spec.resolution, 2) / (6 * s.simulation.sample_rate_hz), 1e-30);
  // The range binds: the crest factor times the largest RMS is the range.
  p.instrument.spec.range = 0.5 * 3 * r.rms_acc;
  const TableLevels tight = runTableLevels(s, p);
  EXPECT_EQ(tight.random.limit, "range");
  EXPECT_NEAR(3 * tight.random.rms_acc / p.instrument.spec.range, 1.0, 1e-12);
  EXPECT_NEAR(tight.random.rms_m / r.rms_m, 0.5, 1e-12);
}

// On the table scene: the modes above the table's 10 Hz bandwidth are not counted as
// seen however loud the dwell, those below are, and each level is the frf's response at
// its sensor times the table's acceleration (the same number by frf's own study).
TEST(TableLevels, AboveTheBandwidthIsNotSeenAndEachLevelIsTheFrfs) {
  ArticleScene s = loadArticleSceneFile(std::string(MMVLAB_SOURCE_DIR) + "/scenes/mmv-table.yaml");
  overrideSegments(s, 4);
  s.shaker.reset();
  PlacementOptions o;
  o.below_hz = 30;
  o.count = 8;
  const PlacementStudy p = runPlacement(s, o);
  const TableLevels t = runTableLevels(s, p);
  int above = 0, below = 0;
  for (const auto& m : t.modes) {
    EXPECT_EQ(m.within_bandwidth, m.frequency_hz <= 10) << m.mode.number();
    if (!m.within_bandwidth) {
      ++above;
      EXPECT_FALSE(m.seen) << m.mode.number();
    } else {
      ++below;
      EXPECT_EQ(m.seen, m.snr_db >= kSeenSnrDb) << m.mode.number();
    }
  }
  EXPECT_GT(above, 0);
  EXPECT_GT(below, 0);
  const auto& m = t.modes.front();
  const std::vector<SensorChannel> channels = chosenSensorChannels(p);
  const auto ch = std::find_if(channels.begin(), channels.end(), [&](const SensorChannel& c) { return c.name == m.best_channel; });
  ASSERT_NE(ch, channels.end());
  app::LinearRequest r;
  r.inputs = {"table_x"};
  r.outputs = {ch->station + ":x:acc_abs", ch->station + ":y:acc_abs"};
  r.f_min = m.frequency_hz, r.f_max = 2 * m.frequency_hz, r.range_given = true, r.points = 2;
  const app::LinearStudy frf = app::runLinearStudy(s, r);
  ASSERT_NEAR(frf.f.front(), m.frequency_hz, 1e-12 * m.frequency_hz);
  const std::complex<double> a = frf.hf.front()(0, 0) * ch->world[0] + frf.hf.front()(1, 0) * ch->world[1];
  EXPECT_NEAR(std::abs(a) * m.table_acc / m.acc, 1.0, 1e-9);
}

}  // namespace
}  // namespace mmv
