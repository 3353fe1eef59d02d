#include "sim/linear/table_levels.hpp"

#include <cmath>
#include <complex>

#include "sim/core/errors.hpp"
#include "sim/core/progress.hpp"
#include "sim/core/text.hpp"
#include "sim/linear/exciter.hpp"
#include "sim/linear/state_space.hpp"

namespace mmv {

TableLevels runTableLevels(const ArticleScene& scene, const PlacementStudy& study) {
  MMV_DEMAND(scene.article.base.type == BaseType::Table);
  TableLevels t;
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
  DampingSpec damping;  // frf's default: 1 % in every mode, unless the scene says otherwise
  if (scene.damping) damping = *scene.damping;
  const LinearModel lm = buildLinearModel(scene, inputs, outputs, damping);
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
      double table_acc = t.table.stroke * w * w;
      std::string limit = "stroke";
      if (!a1.empty() && a1[best] * table_acc > t.range) table_acc = t.range / a1[best], limit = "range";
      const double peak = a1.empty() ? 0.0 : a1[best] * table_acc;
      const double snr = 20 * std::log10(std::max(peak, 1e-12 * t.resolution) / t.resolution);  // -240 dB: nothing
      if (snr <= m.snr_db) continue;
      m.axis = i == 0 ? "x" : "z", m.table_acc = table_acc, m.table_amplitude_m = table_acc / (w * w), m.limit = limit;
      m.acc = peak, m.best_channel = a1.empty() ? "" : channels[best].name, m.snr_db = snr, m.channels_seen = 0;
      for (double x : a1) m.channels_seen += 20 * std::log10(std::max(x * table_acc, 1e-300) / t.resolution) >= kSeenSnrDb;
    }
    m.within_bandwidth = m.frequency_hz <= t.table.bandwidth_hz;
    m.seen = m.within_bandwidth && m.snr_db >= kSeenSnrDb;
    t.modes.push_back(m);
  }
  return t;
}

}  // namespace mmv
