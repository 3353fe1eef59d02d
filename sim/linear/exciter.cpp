#include "sim/linear/exciter.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <tuple>

#include "facility/sensors.hpp"
#include "sim/core/errors.hpp"
#include "sim/core/progress.hpp"
#include "sim/core/text.hpp"
#include "sim/linear/state_space.hpp"
#include "sim/modes/sensor_loading.hpp"
#include "sim/statics/damping_matrix.hpp"

namespace mmv {
namespace {

double along(const std::array<double, 3>& u, const std::array<double, 3>& e) { return u[0] * e[0] + u[1] * e[1] + u[2] * e[2]; }


/// The loaded model's modes (over the admissible coordinates), its damping per mode,
/// and the target modes followed into it.
struct Loaded {
  LinearModel lm;
  ModalSolution modes;
  std::vector<double> zeta;
  int axes = 2;
  std::optional<StrengthOutputs> strength;  ///< its rows after the channels' and the driving point's
};

/// The article with the armature on it (buildLinearModel: the stinger is stiff along its
/// axis and free across it, so the armature's mass moves with the driving point along
/// the direction only; its weight stays on the shaker's flexures).
Loaded loadedModel(const ArticleScene& scene, const ExciterStudy& e, const std::vector<SensorChannel>& channels) {
  const int axes = scene.article.model == ArticleModel::Spatial ? 3 : 2;
  InputSpec shaker{"shaker", InputKind::PointForce, e.at, -1};
  shaker.direction = e.direction;
  shaker.armature_kg = e.hardware.armature_mass;
  std::vector<OutputSpec> outputs;
  for (const auto& c : channels)
    for (int a = 0; a < axes; ++a) outputs.push_back({c.name + " " + axisName(a), OutputKind::Acceleration, c.station, a, true});
  for (int a = 0; a < axes; ++a) outputs.push_back({"driving point " + std::string(axisName(a)), OutputKind::Displacement, e.at, a, false});
  StrengthOutputs strength(scene, axes, outputs);
  DampingSpec damping;  // frf's default: 1 % in every mode, unless the scene says otherwise
  if (scene.damping) damping = *scene.damping;
  Loaded l{buildLinearModel(scene, {shaker}, outputs, damping), {}, {}, axes, strength};
  l.strength->setStaticStress(scene, l.lm);
  l.modes = dampedModes(l.lm, l.zeta);
  return l;
}

/// Per unit force along the shaker's direction: each channel's acceleration and the
/// driving point's displacement along the direction.
struct Unit {
  std::vector<std::complex<double>> acc;
  std::complex<double> stroke;
  Eigen::MatrixXcd H;  ///< every output per N (the strength rows too)
};

Unit unitResponse(const Loaded& l, const ExciterStudy& e, const std::vector<SensorChannel>& channels, double f_hz) {
  Unit u;
  u.H = l.lm.second_order.response(2 * M_PI * f_hz);
  const int axes = l.axes;
  const Eigen::VectorXcd h = u.H.col(0);  // per N of the shaker's force
  for (std::size_t c = 0; c < channels.size(); ++c) {
    std::complex<double> v = 0;
    for (int a = 0; a < axes; ++a) v += h[static_cast<Eigen::Index>(c) * axes + a] * channels[c].world[static_cast<std::size_t>(a)];
    u.acc.push_back(v);
  }
  const Eigen::Index d0 = static_cast<Eigen::Index>(channels.size()) * axes;
  for (int a = 0; a < axes; ++a) u.stroke += h[d0 + a] * e.direction[static_cast<std::size_t>(a)];
  return u;
}

/// Sine dwell at each target's loaded frequency.
void sineLevels(ExciterStudy& e, const Loaded& l, const std::vector<SensorChannel>& channels, double max_deflection_m) {
  for (auto& m : e.modes) {
    const Unit u = unitResponse(l, e, channels, m.loaded_hz);
    std::size_t best = 0;
    for (std::size_t c = 0; c < u.acc.size(); ++c)
      if (std::abs(u.acc[c]) > std::abs(u.acc[best])) best = c;
    const double a1 = u.acc.empty() ? 0.0 : std::abs(u.acc[best]), x1 = std::abs(u.stroke);
    m.sine_force_n = e.hardware.force_limit;
    m.sine_limit = "force";
    if (x1 * m.sine_force_n > e.hardware.stroke) m.sine_force_n = e.hardware.stroke / x1, m.sine_limit = "stroke";
    if (a1 * m.sine_force_n > e.range) m.sine_force_n = e.range / a1, m.sine_limit = "range";
    m.strength = l.strength->hold(u.H, 0, max_deflection_m, m.sine_force_n, m.sine_limit);
    m.sine_acc = a1 * m.sine_force_n;
    m.sine_stroke_m = x1 * m.sine_force_n;
    m.best_channel = channels.empty() ? "" : channels[best].name;
    m.sine_snr_db = 20 * std::log10(std::max(m.sine_acc, 1e-12 * e.resolution) / e.resolution);  // -240 dB: nothing
    for (const auto& a : u.acc) m.channels_seen += 20 * std::log10(std::max(std::abs(a) * m.sine_force_n, 1e-300) / e.resolution) >= kSeenSnrDb;
    m.seen = m.sine_snr_db >= kSeenSnrDb;
  }
}

/// Random: a flat force spectrum over the band, integrated on a grid that resolves every
/// loaded mode inside it.
void randomLevels(ExciterStudy& e, const Loaded& l, const std::vector<SensorChannel>& channels) {
  ExciterStudy::Random& r = e.random;
  double lo = 0.1, hi = 50;  // the accelerometers' band, widened to hold every target
  for (const auto& m : e.modes) lo = std::min(lo, 0.5 * m.loaded_hz), hi = std::max(hi, 1.25 * m.loaded_hz);
  r.f_min_hz = lo, r.f_max_hz = hi;
  std::vector<double> fn, zeta;
  for (Eigen::Index k = 0; k < l.modes.omega2.size(); ++k)
    if (l.modes.omega2[k] > 0) fn.push_back(std::sqrt(l.modes.omega2[k]) / (2 * M_PI)), zeta.push_back(l.zeta[static_cast<std::size_t>(k)]);
  const std::vector<double> f = resolveResonances(logFrequencies(lo, hi, 800), fn, zeta, 8);
  r.grid_points = static_cast<int>(f.size());
  const double rms_force = e.hardware.force_limit / e.hardware.crest_factor, G = rms_force * rms_force / (hi - lo);
  std::vector<double> acc2(channels.size(), 0.0), stress2(l.strength->stressRows(), 0.0);  // per unit spectrum for the stresses
  double stroke2 = 0;
  Unit prev = unitResponse(l, e, channels, f[0]);
  for (std::size_t i = 1; i < f.size(); ++i) {  // trapezoids
    const Unit next = unitResponse(l, e, channels, f[i]);
    const double df = 0.5 * (f[i] - f[i - 1]) * G;
    for (std::size_t c = 0; c < channels.size(); ++c) acc2[c] += df * (std::norm(prev.acc[c]) + std::norm(next.acc[c]));
    stroke2 += df * (std::norm(prev.stroke) + std::norm(next.stroke));
    for (std::size_t k = 0; k < stress2.size(); ++k) {
      const Eigen::Index row = static_cast<Eigen::Index>(l.strength->stressRow(k));
      stress2[k] += 0.5 * (f[i] - f[i - 1]) * (std::norm(prev.H(row, 0)) + std::norm(next.H(row, 0)));
    }
    prev = next;
  }
  std::size_t worst = 0;
  for (std::size_t c = 0; c < acc2.size(); ++c)
    if (acc2[c] > acc2[worst]) worst = c;
  double scale = 1;
  r.limit = "force";
  const double crest = e.hardware.crest_factor;
  if (crest * std::sqrt(stroke2) > e.hardware.stroke) scale = e.hardware.stroke / (crest * std::sqrt(stroke2)), r.limit = "stroke";
  if (!acc2.empty() && crest * std::sqrt(acc2[worst]) * scale > e.range) scale = e.range / (crest * std::sqrt(acc2[worst])), r.limit = "range";
  double spectrum = G * scale * scale;  // N^2/Hz: the crest factor times each link's RMS stress within its room
  if (const std::string link = l.strength->capRandom(stress2, crest, spectrum); !link.empty())
    scale = std::sqrt(spectrum / G), r.limit = "stress (" + link + ")";
  r.rms_force_n = rms_force * scale;
  r.rms_acc = acc2.empty() ? 0.0 : std::sqrt(acc2[worst]) * scale;
  r.rms_channel = acc2.empty() ? "" : channels[worst].name;
  r.stroke_rms_m = std::sqrt(stroke2) * scale;
  const double noise = e.resolution * e.resolution / (6 * e.sample_rate_hz), Gused = G * scale * scale;
  for (auto& m : e.modes) {
    const Unit u = unitResponse(l, e, channels, m.loaded_hz);
    double peak = 0;
    for (const auto& a : u.acc) peak = std::max(peak, std::norm(a) * Gused);
    m.random_snr_db = 10 * std::log10(std::max(peak, 1e-24 * noise) / noise);
  }
}

}  // namespace

std::vector<ExciterCandidate> rankExciterCandidates(const PlacementStudy& study, double armature_kg) {
  const std::size_t k = study.target_modes.size();
  std::vector<ExciterCandidate> out;
  std::vector<std::vector<double>> residue;
  bool any_free = false;  // a candidate whose armature leaves the article as it is
  for (const auto& d : study.directions) {
    const PlacementCandidate& c = study.candidates[static_cast<std::size_t>(d.block)];
    ExciterCandidate e{static_cast<int>(out.size()), c.station, d.axis, d.world, c.node, 0, ModeNumber(1), 0, false};
    std::vector<double> r(k);
    for (std::size_t j = 0; j < k; ++j) {
      r[j] = std::pow(along(c.shape[j], d.world), 2);
      const double shift = -0.5 * armature_kg * r[j];
      if (std::abs(shift) > std::abs(e.max_shift)) e.max_shift = shift;
    }
    e.loads = std::abs(e.max_shift) > kArmatureShiftLimit;
    any_free = any_free || !e.loads;
    residue.push_back(r);
    out.push_back(e);
  }
  // Each mode's best residue among the attachments that may be used (all, when every one loads).
  std::vector<double> best(k, 0.0);
  for (std::size_t i = 0; i < out.size(); ++i)
    if (!out[i].loads || !any_free)
      for (std::size_t j = 0; j < k; ++j) best[j] = std::max(best[j], residue[i][j]);
  for (std::size_t i = 0; i < out.size(); ++i) {
    ExciterCandidate& c = out[i];
    c.score = 2;
    for (std::size_t j = 0; j < k; ++j) {
      const double s = best[j] > 0 ? std::min(residue[i][j] / best[j], 1.0) : 0.0;
      if (s < c.score) c.score = s, c.weakest = study.target_modes[j];
    }
  }
  std::stable_sort(out.begin(), out.end(), [](const ExciterCandidate& a, const ExciterCandidate& b) {
    return std::tie(a.loads, b.score) < std::tie(b.loads, a.score);
  });
  return out;
}

ExciterStudy runExciter(const ArticleScene& scene, const PlacementStudy& study, double max_deflection_m) {
  MMV_DEMAND(scene.shaker.has_value() && !study.target_modes.empty());
  const ShakerSceneSpec& spec = *scene.shaker;
  ExciterStudy e;
  e.hardware = spec.hardware;
  e.ranking = rankExciterCandidates(study, spec.hardware.armature_mass);
  MMV_DEMAND(!e.ranking.empty());
  e.chosen = spec.autoAt();
  e.at = e.chosen ? e.ranking.front().station : spec.at;
  e.direction = e.chosen ? e.ranking.front().world : spec.direction;
  e.axis = e.chosen ? e.ranking.front().axis : "";
  e.damping = describeDamping(scene.damping.value_or(DampingSpec{})) + (scene.damping ? " (the scene's)" : " (the scene has no damping:)");
  const facility::SensorSpec& acc = study.instrument.spec;  // the placed instrument's
  MMV_DEMAND(acc.kind == "accelerometer" && acc.range > 0);
  e.resolution = acc.resolution, e.range = acc.range;
  e.sample_rate_hz = scene.simulation.sample_rate_hz;
  const std::vector<SensorChannel> channels = chosenSensorChannels(study);
  const ProgressStage stage("the shaker: its armature on the model, sine and random levels");
  int highest = 0;
  for (const ModeNumber m : study.target_modes) highest = std::max(highest, m.number());
  const Loaded l = loadedModel(scene, e, channels);
  // The bare article's target shapes, from the linear model's own linearization (the
  // same equilibrium the placement solved; no second model is built).
  const LinearizedModel& lin = l.lm.solved.linearized;
  const int n = static_cast<int>(lin.Z.cols());
  const ModalSolution bare = solveModes(lin.M, lin.K, lin.Z, highest + 6 >= n ? 0 : highest + 6);
  const Eigen::MatrixXd loaded_shapes = l.lm.Z * l.modes.shapes;  // over the coordinates, as bare's
  for (std::size_t j = 0; j < study.target_modes.size(); ++j) {
    ExciterStudy::Mode m;
    m.mode = study.target_modes[j];
    m.frequency_hz = study.target_frequencies_hz[j];
    std::tie(m.loaded_mode, m.mac) = followMode(lin.M, bare.shapes.col(m.mode.index()), loaded_shapes);
    m.loaded_hz = l.modes.frequencyHz(m.loaded_mode.index());
    m.zeta = l.zeta[static_cast<std::size_t>(m.loaded_mode.index())];
    // Undamped, a resonance's response is unbounded: its levels would be round-off.
    if (!(m.zeta > kLeastDampingRatio))
      throw SceneError(scene.positions.where("damping") +
                       strf(": the shaker's levels need damping: mode %d of the article with the armature (%.4g Hz, following "
                            "target mode %d) has a damping ratio of %.3g, so its resonance has no bound; give the scene a "
                            "damping: (modal_ratio, rayleigh or hinge_beta)",
                            m.loaded_mode.number(), m.loaded_hz, m.mode.number(), m.zeta));
    e.modes.push_back(m);
  }
  sineLevels(e, l, channels, max_deflection_m);
  randomLevels(e, l, channels);
  return e;
}

ModalSolution dampedModes(const LinearModel& lm, std::vector<double>& zeta) {
  ModalSolution modes = solveModes(lm.Mz, lm.Kz);
  zeta.clear();
  for (Eigen::Index k = 0; k < modes.shapes.cols(); ++k) {
    const Eigen::VectorXd psi = modes.shapes.col(k);
    const double w = std::sqrt(std::max(modes.omega2[k], 0.0));
    zeta.push_back(w > 0 ? psi.dot(lm.Cz * psi) / (2 * w) : 0.0);
  }
  return modes;
}

std::vector<SensorChannel> chosenSensorChannels(const PlacementStudy& study) {
  std::vector<char> kept(study.candidates.size(), 0);
  for (int b : study.result.kept_blocks) kept[static_cast<std::size_t>(b)] = 1;
  std::vector<SensorChannel> out;
  for (const auto& d : study.directions)
    if (kept[static_cast<std::size_t>(d.block)]) {
      const std::string& station = study.candidates[static_cast<std::size_t>(d.block)].station;
      out.push_back({station, station + " " + d.axis, d.world});
    }
  return out;
}

}  // namespace mmv
