#include "sim/linear/table_levels.hpp"

#include <algorithm>
#include <cmath>
#include <complex>

#include "sim/core/errors.hpp"
#include "sim/core/progress.hpp"
#include "sim/core/text.hpp"
#include "sim/linear/exciter.hpp"
#include "sim/linear/state_space.hpp"
#include "sim/linear/strength_levels.hpp"

namespace mmv {

namespace {

/// Each channel's absolute acceleration per unit table acceleration along x at f.
std::vector<double> channelGains(const LinearModel& lm, const std::vector<SensorChannel>& channels, int axes, double f_hz) {
  const Eigen::MatrixXcd H = lm.second_order.response(2 * M_PI * f_hz);
  std::vector<double> out;
  for (std::size_t c = 0; c < channels.size(); ++c) {
    std::complex<double> v = 0;
    for (int a = 0; a < axes; ++a) v += H(static_cast<Eigen::Index>(c) * axes + a, 0) * channels[c].world[static_cast<std::size_t>(a)];
    out.push_back(std::abs(v));
  }
  return out;
}

/// The random program (TableLevels::Random): the channels' mean squares under a flat
/// displacement spectrum G over the band, integrated on a grid that resolves every mode
/// in it; then the RMS at the stroke (or the range), and each target's SNR in it.
void randomLevels(const LinearModel& lm, const std::vector<SensorChannel>& channels, int axes, double sample_rate_hz,
                  const StrengthOutputs& strength, TableLevels& t) {
  TableLevels::Random& r = t.random;
  double lo = INFINITY;
  for (const auto& m : t.modes)
    if (m.within_bandwidth) lo = std::min(lo, std::max(0.1, 0.5 * m.frequency_hz));
  if (!std::isfinite(lo) || channels.empty()) return;
  r.program = true;
  r.f_min_hz = lo, r.f_max_hz = t.table.bandwidth_hz;
  std::vector<double> ratios, fn, zeta;
  const ModalSolution modes = dampedModes(lm, ratios);
  for (Eigen::Index k = 0; k < modes.omega2.size(); ++k)
    if (modes.omega2[k] > 0) fn.push_back(std::sqrt(modes.omega2[k]) / (2 * M_PI)), zeta.push_back(ratios[static_cast<std::size_t>(k)]);
  const std::vector<double> f = resolveResonances(logFrequencies(r.f_min_hz, r.f_max_hz, 800), fn, zeta, 8);
  r.grid_points = static_cast<int>(f.size());
  // Per unit displacement spectrum (G = 1 m^2/Hz): the table's acceleration spectrum is (2 pi f)^4.
  // Each channel's and then each stress output's spectrum per unit G, integrated.
  const std::size_t stress_rows = strength.stressRows();
  std::vector<double> ms(channels.size() + stress_rows, 0.0);
  const auto psd = [&](double fi) {
    std::vector<double> g = channelGains(lm, channels, axes, fi);
    const Eigen::MatrixXcd H = stress_rows ? lm.second_order.response(2 * M_PI * fi) : Eigen::MatrixXcd();
    for (std::size_t k = 0; k < stress_rows; ++k) g.push_back(std::abs(H(static_cast<Eigen::Index>(strength.stressRow(k)), 0)));
    for (double& x : g) x = x * x * std::pow(2 * M_PI * fi, 4);
    return g;
  };
  std::vector<double> prev = psd(f[0]);
  for (std::size_t i = 1; i < f.size(); ++i) {  // trapezoids
    const std::vector<double> next = psd(f[i]);
    for (std::size_t c = 0; c < ms.size(); ++c) ms[c] += 0.5 * (f[i] - f[i - 1]) * (prev[c] + next[c]);
    prev = next;
  }
  const std::vector<double> stress_ms(ms.begin() + static_cast<std::ptrdiff_t>(channels.size()), ms.end());
  ms.resize(channels.size());
  const std::size_t worst = static_cast<std::size_t>(std::max_element(ms.begin(), ms.end()) - ms.begin());
  const double band = r.f_max_hz - r.f_min_hz;
  r.rms_m = t.table.stroke / kTableCrestFactor, r.limit = "stroke";
  double G = r.rms_m * r.rms_m / band;
  if (kTableCrestFactor * std::sqrt(ms[worst] * G) > t.range) {
    G = std::pow(t.range / kTableCrestFactor, 2) / ms[worst];
    r.rms_m = std::sqrt(G * band), r.limit = "range";
  }
  // The crest factor times each link's RMS stress over its static stress within its limit.
  if (const std::string link = strength.capRandom(stress_ms, kTableCrestFactor, G); !link.empty())
    r.rms_m = std::sqrt(G * band), r.limit = "stress (" + link + ")";
  r.rms_acc = std::sqrt(ms[worst] * G), r.rms_channel = channels[worst].name;
  r.noise_psd = t.resolution * t.resolution / (6 * sample_rate_hz);
  for (auto& m : t.modes) {
    m.random_snr_db = NAN;
    if (!m.within_bandwidth) continue;
    std::vector<double> s = psd(m.frequency_hz);
    s.resize(channels.size());  // the sensors' spectra, not the stresses'
    m.random_snr_db = 10 * std::log10(std::max(*std::max_element(s.begin(), s.end()) * G, 1e-24 * r.noise_psd) / r.noise_psd);
  }
}

}  // namespace

TableLevels runTableLevels(const ArticleScene& scene, const PlacementStudy& study, double max_deflection_m) {
  MMV_DEMAND(scene.article.base.type == BaseType::Table);
  TableLevels t;
  t.max_deflection_m = max_deflection_m;
  const facility::SensorSpec& acc = study.instrument.spec;  // the placed instrument's
  MMV_DEMAND(acc.kind == "accelerometer" && acc.range > 0);
  t.resolution = acc.resolution, t.range = acc.range;
  const ProgressStage stage("the table's levels per target mode");
  const bool spatial = scene.article.model == ArticleModel::Spatial;
  const int axes = spatial ? 3 : 2;
  const std::vector<SensorChannel> channels = chosenSensorChannels(study);
  std::vector<InputSpec> inputs{{"table_x", InputKind::BaseAcceleration, "", 0}};
  if (spatial) inputs.push_back({"table_z", InputKind::BaseAcceleration, "", 2});
  std::vector<OutputSpec> outputs;
  for (const auto& c : channels)
    for (int a = 0; a < axes; ++a) outputs.push_back({c.name + " " + std::to_string(a), OutputKind::Acceleration, c.station, a, true});
  StrengthOutputs strength(scene, axes, outputs);  // after the channels' rows
  DampingSpec damping;  // frf's default: 1 % in every mode, unless the scene says otherwise
  if (scene.damping) damping = *scene.damping;
  const LinearModel lm = buildLinearModel(scene, inputs, outputs, damping);
  strength.setStaticStress(scene, lm);
  for (std::size_t j = 0; j < study.target_modes.size(); ++j) {
    TableLevels::Mode m;
    m.mode = study.target_modes[j];
    m.frequency_hz = study.target_frequencies_hz[j];
    const double w = 2 * M_PI * m.frequency_hz;
    const Eigen::MatrixXcd H = lm.second_order.response(w);  // per m/s^2 of the table
    m.snr_db = -1e300;
    for (std::size_t i = 0; i < inputs.size(); ++i) {
      std::vector<double> a1;  // each channel's amplitude per unit table acceleration
      std::size_t best = 0;
      for (std::size_t c = 0; c < channels.size(); ++c) {
        std::complex<double> v = 0;
        for (int a = 0; a < axes; ++a)
          v += H(static_cast<Eigen::Index>(c) * axes + a, static_cast<Eigen::Index>(i)) * channels[c].world[static_cast<std::size_t>(a)];
        a1.push_back(std::abs(v));
        if (a1.back() > a1[best]) best = c;
      }
      TableLevels::Mode level = m;
      level.table_acc = t.table.stroke * w * w;
      level.limit = "stroke";
      if (!a1.empty() && a1[best] * level.table_acc > t.range) level.table_acc = t.range / a1[best], level.limit = "range";
      level.strength = strength.hold(H, static_cast<Eigen::Index>(i), max_deflection_m, level.table_acc, level.limit);
      const double table_acc = level.table_acc;
      const double peak = a1.empty() ? 0.0 : a1[best] * table_acc;
      const double snr = 20 * std::log10(std::max(peak, 1e-12 * t.resolution) / t.resolution);  // -240 dB: nothing
      if (snr <= m.snr_db) continue;
      m = level;
      m.axis = i == 0 ? "x" : "z", m.table_amplitude_m = table_acc / (w * w);
      m.acc = peak, m.best_channel = a1.empty() ? "" : channels[best].name, m.snr_db = snr, m.channels_seen = 0;
      for (double x : a1) m.channels_seen += 20 * std::log10(std::max(x * table_acc, 1e-300) / t.resolution) >= kSeenSnrDb;
    }
    m.within_bandwidth = m.frequency_hz <= t.table.bandwidth_hz;
    m.seen = m.within_bandwidth && m.snr_db >= kSeenSnrDb;
    t.modes.push_back(m);
  }
  randomLevels(lm, channels, axes, scene.simulation.sample_rate_hz, strength, t);
  return t;
}

}  // namespace mmv
