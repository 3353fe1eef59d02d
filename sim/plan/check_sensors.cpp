// Sensor lines of `mmvlab check` (sim/plan/check.hpp): each sensor's peak signal
// against its range, and its signal-to-resolution ratio.
#include <algorithm>
#include <cmath>
#include <complex>

#include "facility/sensors.hpp"
#include "sim/core/text.hpp"
#include "sim/core/units.hpp"
#include "sim/linear/state_space.hpp"
#include "sim/linear/time_response.hpp"
#include "sim/model/stations.hpp"
#include "sim/plan/check_parts.hpp"
#include "sim/scene/programs.hpp"

namespace mmv::plan {

namespace {

constexpr double kMinRatioDb = 20;
constexpr double kEdgePct = 2;  ///< a peak within 2 % of the range is at its edge, whatever --margin asks.

/// Display scale and unit: angles in deg, rates in deg/s, accelerations in m/s^2.
std::pair<double, std::string> displayUnit(const std::string& type) {
  if (type == "encoder") return {kRadToDeg, "deg"};
  if (type == "rate_gyro") return {kRadToDeg, "deg/s"};
  if (type == "strain") return {1e6, "microstrain"};
  return {1.0, "m/s^2"};
}

/// A sensor's line: peak (measured unit) against its range, its ratio to the resolution;
/// a peak within `margin_pct` (--margin, at least 2 %) of the range warns.
CheckLine sensorLine(const ArticleScene& scene, const SensorSceneSpec& s, const std::string& id, const std::string& during, double peak,
                     int saturated, const std::string& how, double margin_pct) {
  const facility::SensorSpec spec = instrumentOf(scene, s).spec;  // its instrument's range and resolution
  const auto [scale, unit] = displayUnit(s.type);
  const std::string what = s.instrument.empty() || s.instrument == s.type ? s.type : s.type + " " + s.instrument;
  CheckLine l = makeLine("sensors", "sensor." + s.name + "." + id, s.name + " (" + what + " at " + s.target + ") " + during, peak * scale,
                         spec.range * scale, unit, "", 0);
  const double ratio_db = peak > 0 ? 20 * std::log10(peak / spec.resolution) : -INFINITY;
  l.note = how + (peak > 0 ? strf("; %.1f dB above its resolution of %.3g %s", ratio_db, spec.resolution * scale, unit.c_str())
                           : "; no signal");
  if (saturated > 0 || peak > spec.range) {
    l.verdict = Verdict::Fail;
    l.note += saturated > 0 ? strf("; saturated in %d samples", saturated) : std::string("; would saturate");
  } else if (peak >= (1 - std::max(margin_pct, kEdgePct) / 100) * spec.range) {
    l.verdict = Verdict::Warn;
    l.note += strf("; within %.3g %% of its range (its margin rule: --margin, at least %.0f %%): a larger motion saturates it",
                   std::max(margin_pct, kEdgePct), kEdgePct);
  } else if (peak <= 0) {
    l.verdict = Verdict::Info;
  } else {
    l.verdict = ratio_db < kMinRatioDb ? Verdict::Warn : Verdict::Pass;
    if (ratio_db < kMinRatioDb) l.note += strf(": under %.0f dB, the signal is a few counts", kMinRatioDb);
  }
  return l;
}

void addRunLines(const CheckInputs& in, std::vector<CheckLine>& out) {
  const SimulationResult& r = *in.rigid_run;
  for (const auto& s : in.scene.sensors) {
    const auto& cols = r.record.columns;
    const auto summary = std::find_if(r.sensors.begin(), r.sensors.end(), [&](const SensorSummary& x) { return x.name == s.name; });
    if (summary == r.sensors.end()) continue;
    if (s.type == "strain") {  // rigid links do not bend
      CheckLine l = sensorLine(in.scene, s, "run", "during the scene's run", 0, 0, "rigid links do not bend: `mmvlab simulate` gives its reading", 0);
      l.verdict = Verdict::NotChecked;
      l.note = "rigid links do not bend: `mmvlab simulate` gives its reading";
      out.push_back(l);
      continue;
    }
    const auto col = std::find(cols.begin(), cols.end(), s.name + "_" + summary->unit) - cols.begin();
    double peak = 0;
    for (const auto& row : r.record.rows) peak = std::max(peak, std::abs(row[col]));
    out.push_back(sensorLine(in.scene, s, "run", "during the scene's run", peak, summary->saturated_samples,
                             strf("rigid links, %.3g s as recorded (band limits, noise, quantization)", in.scene.simulation.duration),
                             in.options.required_margin_pct));
  }
}

/// Peak steady-state specific force along an accelerometer's axis under the table's
/// program, from the response per unit table acceleration h(f) (complex): the random
/// program's 3 sigma, and the steady state a sine or sweep would reach given time.
struct ProgramPeak {
  double value = 0;
  std::string how;
};

template <typename H>
ProgramPeak programPeak(const TableMotion& m, const H& h) {
  const auto accel = [](double f) { return std::pow(2 * M_PI * f, 2); };
  if (m.type == TableMotion::Type::Sine)
    return {std::abs(h(m.frequency_hz)) * accel(m.frequency_hz) * m.amplitude, strf("steady state of the %.3g Hz sine", m.frequency_hz)};
  const double f0 = std::max(std::min(m.from_hz, m.to_hz), 1e-3), f1 = std::max(m.from_hz, m.to_hz);
  const int n = 2000;
  std::vector<double> f(n), g(n);
  for (int i = 0; i < n; ++i) {
    f[i] = f0 * std::pow(f1 / f0, i / (n - 1.0));
    g[i] = std::abs(h(f[i])) * accel(f[i]);
  }
  if (m.type == TableMotion::Type::Sweep)
    return {m.amplitude * *std::max_element(g.begin(), g.end()), strf("steady state, worst over the %.3g-%.3g Hz sweep", f0, f1)};
  double var = 0;  // random: flat displacement spectrum rms^2 / (f1 - f0) over the band
  for (int i = 1; i < n; ++i) var += 0.5 * (g[i] * g[i] + g[i - 1] * g[i - 1]) * (f[i] - f[i - 1]);
  return {3 * std::sqrt(var * m.rms * m.rms / (f1 - f0)), strf("3 sigma of the %.3g-%.3g Hz random program", f0, f1)};
}

/// An accelerometer's reading from the linear model's outputs for it (its rows from
/// `row` on: the acceleration's world components, then the point's small rotation): the
/// acceleration along its axis, less dphi . (e x g), gravity read along the turned axis.
struct AccelerometerRows {
  Eigen::Index row = 0;
  int dims = 2, rots = 1;
  SimTK::Vec3 axis, e_x_g;
  template <class Y>
  auto reading(const Y& y) const {  // y(i): output i
    auto v = 0.0 * y(row);
    for (int a = 0; a < dims; ++a) v += axis[a] * y(row + a);
    for (int r = 0; r < rots; ++r) v -= e_x_g[3 - rots + r] * y(row + dims + r);
    return v;
  }
};

/// The largest reading of `live` over a run of the outputs (rows: samples), starting
/// from gravity's static reading `g_along`.
double runPeak(const AccelerometerRows& a, const Eigen::MatrixXd& run, double g_along, facility::Sensor& live) {
  double peak = 0;
  for (Eigen::Index s = 0; s < run.rows(); ++s)
    peak = std::max(peak, std::abs(live.sample(g_along + a.reading([&](Eigen::Index i) { return run(s, i); }))));
  return peak;
}

void addTableSensorLines(const CheckInputs& in, std::vector<CheckLine>& out) {
  const ArticleScene& scene = in.scene;
  const auto& motion = scene.article.base.motion;
  std::vector<OutputSpec> outputs;
  std::vector<const SensorSceneSpec*> accels;
  const bool spatial = scene.article.model == ArticleModel::Spatial;
  const int dims = spatial ? 3 : 2;  // the acceleration's world components
  // The point's small rotation too (about z; spatial: x, y, z): an accelerometer turning
  // by dphi reads gravity along its turned axis, -dphi . (e x g), as the time run's does
  // (4 % of link 3a's transverse reading under the table's 2 Hz sine).
  const int rots = spatial ? 3 : 1;
  for (const auto& s : scene.sensors)
    if (s.type == "accelerometer") {
      accels.push_back(&s);
      for (int axis = 0; axis < dims; ++axis)
        outputs.push_back({s.name + "_" + "xyz"[axis], OutputKind::Acceleration, s.target, axis, true});
      for (int r = 0; r < rots; ++r)
        outputs.push_back({s.name + "_r" + "xyz"[3 - rots + r], OutputKind::Displacement, s.target, 6 - rots + r, false});
    }
  if (accels.empty() || !motion || scene.article.base.type != BaseType::Table) return;
  if (motion->type == TableMotion::Type::Profile) {
    for (const auto* s : accels) {
      CheckLine l = sensorLine(scene, *s, "table", "under the table's profile", 0, 0, "a CSV profile: run `mmvlab simulate`", 0);
      l.verdict = Verdict::NotChecked;
      out.push_back(l);
    }
    return;
  }
  DampingSpec damping;
  if (scene.damping) damping = *scene.damping;
  const LinearModel lm = buildLinearModel(scene, {{"table_x", InputKind::BaseAcceleration, "", 0}}, outputs, damping);
  const Model& model = *lm.solved.model;
  // The run's samples of the outputs (sines and sweeps): table acceleration in, from rest.
  Eigen::MatrixXd run;
  if (motion->type != TableMotion::Type::Random) {
    const auto program = makeTableProgram(*motion);
    const int steps = std::max(1, static_cast<int>(std::ceil(scene.simulation.duration * scene.simulation.sample_rate_hz)));
    run = timeResponse(lm.full, [&](double t) { return Eigen::VectorXd::Constant(1, program->acceleration(t)); },
                       scene.simulation.duration / steps, steps);  // simulate's sample times
  }
  SimTK::State at = lm.solved.equilibrium.state;
  model.getSystem().realize(at, SimTK::Stage::Position);
  for (std::size_t k = 0; k < accels.size(); ++k) {
    std::string error;
    const auto ref = PointRef::resolve(model, scene.article, accels[k]->target, error);
    AccelerometerRows rows{(dims + rots) * static_cast<Eigen::Index>(k), dims, rots, ref->localAxis(at, accels[k]->axis), {}};
    rows.e_x_g = rows.axis % model.getGravity();
    const facility::Sensor sensor(instrumentOf(scene, *accels[k]).spec, scene.simulation.sample_rate_hz);
    const auto h = [&](double f) {
      const Eigen::MatrixXcd H = lm.second_order.response(2 * M_PI * f);
      return rows.reading([&](Eigen::Index i) { return H(i, 0); }) * sensor.bandGain(f);
    };
    const ProgramPeak p = programPeak(*motion, h);
    if (motion->type == TableMotion::Type::Random) {
      out.push_back(sensorLine(scene, *accels[k], "table", "under the table's program", p.value, 0, "flexible linear model, " + p.how,
                               in.options.required_margin_pct));
      continue;
    }
    // A sine or sweep: the linear model's response over the scene's run, from rest, what
    // `simulate` records (gravity's static reading along the axis included, through the
    // same sensor model at the same sample rate). A sweep passes each resonance in a few
    // cycles and a lightly damped mode's sine builds up over 1 / (zeta omega): the
    // steady state overstated the run's peak (61 against the run's 7.6 m/s^2).
    const double g_along = -(~model.getGravity() * rows.axis);
    facility::Sensor live(instrumentOf(scene, *accels[k]).spec, scene.simulation.sample_rate_hz);
    const double peak = runPeak(rows, run, g_along, live);
    // Gravity's static reading is in the demand unless the sensor's high-pass removes it
    // (its filters start at rest under the first value): the note says which.
    const double low_cut = instrumentOf(scene, *accels[k]).spec.low_cut_hz;
    const std::string gravity = low_cut > 0 ? strf("gravity's %.3g m/s^2 along the axis not in it: its %.3g Hz high-pass removes the "
                                                   "static reading", g_along, low_cut)
                                            : strf("gravity's %.3g m/s^2 along the axis included", g_along);
    out.push_back(sensorLine(scene, *accels[k], "table", "under the table's program", peak, live.saturatedSamples(),
                             strf("flexible linear model over the scene's %.3g s run from rest, sampled as simulate samples "
                                  "(%s); the %s would read %.3g m/s^2",
                                  scene.simulation.duration, gravity.c_str(), p.how.c_str(), p.value),
                             in.options.required_margin_pct));
  }
}

}  // namespace

void addSensorLines(const CheckInputs& in, std::vector<CheckLine>& out) {
  const std::size_t first = out.size();
  if (in.rigid_run) addRunLines(in, out);
  addTableSensorLines(in, out);
  // One verdict per sensor: where the rigid run and the flexible linear model both
  // estimate its peak, the larger is judged and the other stated (before, a rigid line's
  // low signal warned the check while the flexible line of the same sensor read 42 dB).
  for (const auto& s : in.scene.sensors) {
    CheckLine *run = nullptr, *table = nullptr;
    for (std::size_t i = first; i < out.size(); ++i) {
      if (out[i].id == "sensor." + s.name + ".run") run = &out[i];
      if (out[i].id == "sensor." + s.name + ".table") table = &out[i];
    }
    if (!run || !table || run->verdict == Verdict::NotChecked || table->verdict == Verdict::NotChecked) continue;
    CheckLine& judged = table->demand >= run->demand ? *table : *run;
    CheckLine& other = &judged == table ? *run : *table;
    other.verdict = Verdict::Info;
    other.note += strf("; not judged: the %s estimate's %.4g %s is the larger and is judged (%s)",
                       &judged == table ? "flexible linear model's" : "rigid run's", judged.demand, judged.unit.c_str(), judged.id.c_str());
  }
}

}  // namespace mmv::plan
