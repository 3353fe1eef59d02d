// Sensor lines of `mmvlab check` (sim/plan/check.hpp): each sensor's peak signal
// against its range, and its signal-to-resolution ratio.
#include <algorithm>
#include <cmath>
#include <complex>

#include "facility/sensors.hpp"
#include "sim/core/text.hpp"
#include "sim/linear/state_space.hpp"
#include "sim/model/stations.hpp"
#include "sim/plan/check_parts.hpp"

namespace mmv::plan {

namespace {

constexpr double kRadToDeg = 180 / M_PI;
constexpr double kMinRatioDb = 20;
constexpr double kEdge = 0.98;  ///< a peak within 2 % of the range is at its edge.  ///< below: fewer than 10 counts of resolution in the peak.

facility::SensorSpec specOf(const SensorSceneSpec& s) { return facility::sensorSpecFor(s.type); }

/// Display scale and unit: angles in deg, rates in deg/s, accelerations in m/s^2.
std::pair<double, std::string> displayUnit(const std::string& type) {
  if (type == "encoder") return {kRadToDeg, "deg"};
  if (type == "rate_gyro") return {kRadToDeg, "deg/s"};
  return {1.0, "m/s^2"};
}

/// A sensor's line: peak (measured unit) against its range, its ratio to the resolution.
CheckLine sensorLine(const SensorSceneSpec& s, const std::string& id, const std::string& during, double peak, int saturated, const std::string& how) {
  const facility::SensorSpec spec = specOf(s);
  const auto [scale, unit] = displayUnit(s.type);
  CheckLine l = makeLine("sensors", "sensor." + s.name + "." + id, s.name + " (" + s.type + " at " + s.target + ") " + during, peak * scale, spec.range * scale, unit, "", 0);
  const double ratio_db = peak > 0 ? 20 * std::log10(peak / spec.resolution) : -INFINITY;
  l.note = how + (peak > 0 ? strf("; %.1f dB above its resolution of %.3g %s", ratio_db, spec.resolution * scale, unit.c_str())
                           : "; no signal");
  if (saturated > 0 || peak > spec.range) {
    l.verdict = Verdict::Fail;
    l.note += saturated > 0 ? strf("; saturated in %d samples", saturated) : std::string("; would saturate");
  } else if (peak >= kEdge * spec.range) {
    l.verdict = Verdict::Warn;
    l.note += "; at the edge of its range: a larger motion saturates it";
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
    const auto col = std::find(cols.begin(), cols.end(), s.name + "_" + summary->unit) - cols.begin();
    double peak = 0;
    for (const auto& row : r.record.rows) peak = std::max(peak, std::abs(row[col]));
    out.push_back(sensorLine(s, "run", "during the scene's run", peak, summary->saturated_samples,
                             strf("rigid links, %.3g s as recorded (band limits, noise, quantization)", in.scene.simulation.duration)));
  }
}

/// Peak steady-state specific force along an accelerometer's axis under the table's
/// program, from the response per unit table acceleration h(f) (complex).
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

void addTableLines(const CheckInputs& in, std::vector<CheckLine>& out) {
  const ArticleScene& scene = in.scene;
  const auto& motion = scene.article.base.motion;
  std::vector<OutputSpec> outputs;
  std::vector<const SensorSceneSpec*> accels;
  const int dims = scene.article.model == ArticleModel::Spatial ? 3 : 2;  // the acceleration's world components
  for (const auto& s : scene.sensors)
    if (s.type == "accelerometer") {
      accels.push_back(&s);
      for (int axis = 0; axis < dims; ++axis)
        outputs.push_back({s.name + "_" + "xyz"[axis], OutputKind::Acceleration, s.target, axis, true});
    }
  if (accels.empty() || !motion || scene.article.base.type != BaseType::Table) return;
  if (motion->type == TableMotion::Type::Profile) {
    for (const auto* s : accels) {
      CheckLine l = sensorLine(*s, "table", "under the table's profile", 0, 0, "a CSV profile: run `mmvlab simulate`");
      l.verdict = Verdict::NotChecked;
      out.push_back(l);
    }
    return;
  }
  DampingSpec damping;
  if (scene.damping) damping = *scene.damping;
  const LinearModel lm = buildLinearModel(scene, {{"table_x", InputKind::BaseAcceleration, "", 0}}, outputs, damping);
  const Model& model = *lm.solved.model;
  SimTK::State at = lm.solved.equilibrium.state;
  model.getSystem().realize(at, SimTK::Stage::Position);
  for (std::size_t k = 0; k < accels.size(); ++k) {
    std::string error;
    const auto ref = PointRef::resolve(model, scene.article, accels[k]->target, error);
    const SimTK::Vec3 axis = ref->localAxis(at, accels[k]->axis);
    const facility::Sensor sensor(specOf(*accels[k]), scene.simulation.sample_rate_hz);
    const auto h = [&](double f) {
      const Eigen::MatrixXcd H = lm.second_order.response(2 * M_PI * f);
      std::complex<double> along = 0;
      for (int a = 0; a < dims; ++a) along += axis[a] * H(dims * k + a, 0);
      return along * sensor.bandGain(f);
    };
    const ProgramPeak p = programPeak(*motion, h);
    out.push_back(sensorLine(*accels[k], "table", "under the table's program", p.value, 0, "flexible linear model, " + p.how));
  }
}

}  // namespace

void addSensorLines(const CheckInputs& in, std::vector<CheckLine>& out) {
  if (in.rigid_run) addRunLines(in, out);
  addTableLines(in, out);
}

}  // namespace mmv::plan
