// `check`'s shaker lines (scenes with `shaker:`): the extra shaker where the scene attaches
// it, planned on the scene's own accelerometers (sim/linear/exciter.hpp, as place-sensors
// plans it on a proposed set): what its armature does to the modes in the band, and
// whether each of those modes is seen above the sensors' resolution at a dwell level the
// shaker's force and stroke and the sensors' range allow.
#include <algorithm>
#include <cmath>
#include <set>
#include <tuple>

#include "sim/core/errors.hpp"
#include "sim/core/text.hpp"
#include "sim/linear/exciter.hpp"
#include "sim/linear/state_space.hpp"
#include "sim/linear/time_response.hpp"
#include "sim/modes/place_sensors.hpp"
#include "sim/plan/check_parts.hpp"
#include "sim/scene/programs.hpp"
#include "sim/scene/stations.hpp"

namespace mmv::plan {

namespace {

/// The scene's accelerometers' instrument for the levels: their coarsest resolution and
/// smallest range when they differ (the plan must hold for every sensor). `directions`:
/// how many distinct measuring directions they make (two at one place and axis are one);
/// `why` says which one is not on a link.
InstrumentSpec levelsInstrument(const ArticleScene& scene, int& directions, bool& mixed, std::string& why) {
  InstrumentSpec out;
  std::set<std::tuple<std::string, double, int>> distinct;
  mixed = false;
  for (const auto& s : scene.sensors) {
    if (s.type != "accelerometer") continue;
    std::string reason;
    const auto at = pointAlongLink(scene.article, s.target, reason);
    if (!at && why.empty()) why = "sensor " + s.name + " (" + s.where + "): " + reason;
    if (at) distinct.insert({at->first, at->second, s.axis});
    const InstrumentSpec& i = instrumentOf(scene, s);
    if (out.name.empty()) {
      out = i;
      continue;
    }
    mixed = mixed || i.name != out.name;
    out.spec.resolution = std::max(out.spec.resolution, i.spec.resolution);
    out.spec.range = std::min(out.spec.range, i.spec.range);
  }
  directions = static_cast<int>(distinct.size());
  return out;
}

/// The shaker's program (`shaker.program`) before any run: the linear model with the
/// armature on the article (as frf's `--input shaker`), driven from rest by the program's
/// force and the table's programs over the scene's run, sampled finely enough for the
/// program's highest frequency (20 samples a period at least, and never coarser than
/// simulate's rate), with the run's damping. The armature's travel is the driving point's displacement along the
/// force (it rides the stinger), the stinger's force the program's less the armature's
/// m a. Against the stroke: what `simulate` records as shaker_stroke_m.
void addProgramLines(const CheckInputs& in, std::vector<CheckLine>& out) {
  const ArticleScene& scene = in.scene;
  const ShakerSceneSpec& sh = *scene.shaker;
  const auto force = makeTableProgram(*sh.program);
  std::vector<InputSpec> inputs;
  InputSpec shaker{"shaker", InputKind::PointForce, sh.at, -1};
  shaker.direction = sh.direction;
  shaker.armature_kg = sh.hardware.armature_mass;
  inputs.push_back(shaker);
  // The table's own programs move the article (and so the driving point) too.
  std::vector<std::shared_ptr<const facility::TableProgram>> programs{force};
  std::vector<int> table_axis{-1};  // the world axis each table program moves the base along
  const auto& base = scene.article.base;
  double f_max = force->maxFrequencyHz();
  for (const auto& [motion, axis] : {std::pair{&base.motion, 0}, std::pair{&base.motion_z, 2}})
    if (base.type == BaseType::Table && *motion) {
      inputs.push_back({axis == 0 ? "table_x" : "table_z", InputKind::BaseAcceleration, "", axis});
      programs.push_back(makeTableProgram(**motion));
      table_axis.push_back(axis);
      f_max = std::max(f_max, programs.back()->maxFrequencyHz());
    }
  const int axes = scene.article.model == ArticleModel::Spatial ? 3 : 2;
  // The driving point's displacement relative to the base (the table's own displacement,
  // its program's, is added below: the armature stands on the floor) and its absolute
  // acceleration (the armature's, for the stinger's force).
  std::vector<OutputSpec> outputs;
  for (int a = 0; a < axes; ++a) outputs.push_back({strf("driving point %s", axisName(a)), OutputKind::Displacement, sh.at, a, false});
  for (int a = 0; a < axes; ++a) outputs.push_back({strf("driving point a%s", axisName(a)), OutputKind::Acceleration, sh.at, a, true});
  // The run's damping: the scene's, and none without `damping:` (simulate's), not frf's
  // default 1 %: an undamped run's travel is what the run will show.
  DampingSpec damping;
  damping.modal_ratio = 0;
  if (scene.damping) damping = *scene.damping;
  const LinearModel lm = buildLinearModel(scene, inputs, outputs, damping, /*prepare_responses=*/false);
  const double duration = scene.simulation.duration;
  const double dt_max = std::min(1 / scene.simulation.sample_rate_hz, f_max > 0 ? 1 / (20 * f_max) : 1 / scene.simulation.sample_rate_hz);
  // A CSV program's content reaches its rows' Nyquist frequency: the samples are capped
  // (the response costs O(samples x states^2)), and the note says when that binds.
  constexpr double kMaxSamples = 200000;
  const bool capped = duration / dt_max > kMaxSamples;
  const int steps = std::max(1, static_cast<int>(std::ceil(std::min(duration / dt_max, kMaxSamples))));
  const double dt = duration / steps;
  const Eigen::MatrixXd run = timeResponse(lm.full, [&](double t) {
    Eigen::VectorXd u(static_cast<Eigen::Index>(programs.size()));
    u[0] = programs[0]->position(t);
    for (std::size_t i = 1; i < programs.size(); ++i) u[static_cast<Eigen::Index>(i)] = programs[i]->acceleration(t);
    return u;
  }, dt, steps);
  double travel = 0, stinger = 0, at_t = 0;
  for (Eigen::Index k = 0; k < run.rows(); ++k) {
    const double t = static_cast<double>(k) * dt;
    double x = 0, a = 0;
    for (int d = 0; d < axes; ++d) x += sh.direction[static_cast<std::size_t>(d)] * run(k, d), a += sh.direction[static_cast<std::size_t>(d)] * run(k, axes + d);
    for (std::size_t i = 1; i < programs.size(); ++i)
      x += sh.direction[static_cast<std::size_t>(table_axis[i])] * (programs[i]->position(t) - programs[i]->position(0));
    if (std::abs(x) > travel) travel = std::abs(x), at_t = t;
    stinger = std::max(stinger, std::abs(programs[0]->position(t) - sh.hardware.armature_mass * a));
  }
  const std::string model = strf("flexible linear model with the %.3g kg armature, from rest over the scene's %.3g s run "
                                 "(%d samples%s)%s", sh.hardware.armature_mass, duration, steps + 1,
                                 capped ? strf(", capped: content above %.3g Hz is sampled under 20 points a period", 1 / (20 * dt)).c_str() : "",
                                 programs.size() > 1 ? ", the table's program included" : "");
  out.push_back(makeLine("shaker", "shaker.program_stroke", "the armature's travel under the shaker's program", travel, sh.hardware.stroke,
                         "m", strf("%s; largest at t = %.3g s; the stinger passes up to %.4g N", model.c_str(), at_t, stinger),
                         in.options.required_margin_pct));
}

}  // namespace

void addShakerLines(const CheckInputs& in, std::vector<CheckLine>& out) {
  const ArticleScene& scene = in.scene;
  if (!scene.shaker) return;
  if (scene.shaker->program) addProgramLines(in, out);
  const auto notChecked = [&](const std::string& why) {
    CheckLine l = makeLine("shaker", "shaker.levels", "the shaker's levels at the scene's accelerometers", 0, 0, "dB", why, 0);
    l.verdict = Verdict::NotChecked;
    out.push_back(l);
  };
  std::vector<ModeNumber> targets;
  for (const ModeInfo& m : in.modes.modes)
    if (m.stable && !m.rigid_body && m.frequency_hz >= in.options.band_min_hz && m.frequency_hz <= in.options.band_max_hz)
      targets.push_back(m.number);
  int accelerometers = 0;
  bool mixed = false;
  std::string off_links;
  const InstrumentSpec instrument = levelsInstrument(scene, accelerometers, mixed, off_links);
  if (targets.empty()) return notChecked(strf("no vibration mode in %g-%g Hz to excite", in.options.band_min_hz, in.options.band_max_hz));
  if (instrument.name.empty())
    return notChecked("the scene has no accelerometer to see the modes: `mmvlab place-sensors` plans the shaker on a proposed set");
  if (!off_links.empty()) return notChecked(off_links);
  PlacementOptions o;
  o.modes = targets;
  o.method = PlacementMethod::DrivingPointResidue;  // ranks only: the scene's sensors are the set
  o.keep_scene_sensors = true;
  o.count = accelerometers;
  o.instrument = instrument;
  ExciterStudy e;
  try {
    const PlacementStudy study = runPlacement(scene, o);
    e = runExciter(scene, study);
  } catch (const SceneError& err) {  // an undamped article: no level to state
    return notChecked(err.what());
  }
  const std::string where = strf("shaker at %s along [%.3g %.3g %.3g]%s", e.at.c_str(), e.direction[0], e.direction[1], e.direction[2],
                                 e.chosen ? " (the best-ranked attachment)" : "");
  // The armature moves with the driving point: its shift of each mode against the 2 %
  // beyond which the shaker tests another article (the ranking's rule).
  double worst = 0;
  int worst_mode = 0;
  for (const auto& m : e.modes) {
    const double shift = 100 * std::abs(m.loaded_hz / m.frequency_hz - 1);
    if (shift >= worst) worst = shift, worst_mode = m.mode.number();
  }
  CheckLine shift = makeLine("shaker", "shaker.armature_shift", where + ": the armature's largest shift of a mode in the band", worst,
                             2.0, "%", strf("mode %d; the %.3g kg armature moves with the driving point", worst_mode, e.hardware.armature_mass), 0);
  if (shift.verdict == Verdict::Fail) {
    shift.verdict = Verdict::Warn;
    shift.note += ": the test sees the article with the shaker on it (place-sensors ranks the attachments)";
  }
  out.push_back(shift);
  for (const auto& m : e.modes) {
    CheckLine l = makeLine("shaker", strf("shaker.mode%d", m.mode.number()),
                           strf("mode %d (%.4g Hz) seen above the resolution under a sine dwell", m.mode.number(), m.frequency_hz),
                           kSeenSnrDb, m.sine_snr_db, "dB",
                           strf("at %.3g N (set by %s), best %s, %d of %d sensors seen, stroke %.3g mm; random: %.1f dB", m.sine_force_n,
                                m.sine_limit.c_str(), m.best_channel.c_str(), m.channels_seen, accelerometers, 1e3 * m.sine_stroke_m,
                                m.random_snr_db),
                           0);
    // The demand is a floor here, the margin over it: seen (>= 20 dB) passes, under it
    // warns (a signal under the resolution, SNR <= 0 dB, included).
    l.capacity = m.sine_snr_db;
    l.has_capacity = true;
    l.margin_pct = (m.sine_snr_db - kSeenSnrDb) / kSeenSnrDb * 100;
    l.verdict = m.seen ? Verdict::Pass : Verdict::Warn;
    if (!m.seen) l.note += ": a stronger point, another direction or finer sensors";
    if (mixed) l.note += "; levels for the coarsest resolution and smallest range of the scene's accelerometers";
    out.push_back(l);
  }
}

}  // namespace mmv::plan
