// Table, modal-content, lab and plausibility lines of `mmvlab check` (sim/plan/check.hpp).
#include <algorithm>
#include <cmath>

#include "facility/lab.hpp"
#include "facility/table_programs.hpp"
#include "sim/core/text.hpp"
#include "sim/model/article_builder.hpp"
#include "sim/plan/check_parts.hpp"
#include "sim/scene/plausibility.hpp"
#include "sim/scene/programs.hpp"

namespace mmv::plan {

namespace {

std::vector<double> bandFrequencies(const ModesReport& m, double lo, double hi) {
  std::vector<double> f;
  for (const auto& mode : m.modes)
    if (mode.stable && !mode.rigid_body && mode.frequency_hz >= lo && mode.frequency_hz <= hi) f.push_back(mode.frequency_hz);
  return f;
}

void addTablePayloadLines(const CheckInputs& in, std::vector<CheckLine>& out) {
  const ArticleScene& scene = in.scene;
  if (scene.article.base.type != BaseType::Table) return;
  const facility::TableSpec table;
  const double g = std::sqrt(scene.gravity[0] * scene.gravity[0] + scene.gravity[1] * scene.gravity[1] + scene.gravity[2] * scene.gravity[2]);
  const double carried = in.modes.model.total_mass_kg - scene.article.base.table_mass;
  double sensors_kg = 0;  // the scene's sensors' instruments, welded on the links by the reader
  for (const auto& l : scene.article.links)
    for (const auto& [x, m] : l.station_masses) sensors_kg += m;
  out.push_back(makeLine("table", "table.payload", "payload weight (article, torquers, gimbal)", carried * g, table.payload_n, "N",
                         sensors_kg > 0 ? strf("%.4g kg, the sensors' %.3g kg (instruments: mass_kg) included; cables are not in the model",
                                               carried, sensors_kg)
                                        : strf("%.4g kg; the sensors are massless (give their instruments' mass_kg) and cables are "
                                               "not in the model", carried),
                         in.options.required_margin_pct));
  const double margin = in.options.required_margin_pct;
  const auto& o = in.options;
  const auto f = bandFrequencies(in.modes, o.band_min_hz, o.band_max_hz);
  const long above = std::count_if(f.begin(), f.end(), [&](double x) { return x > table.bandwidth_hz; });
  CheckLine modes = makeLine("table", "table.modes_in_bandwidth", strf("modes in %.3g-%.3g Hz within the table's bandwidth", o.band_min_hz, o.band_max_hz),
                             f.empty() ? 0 : f.back(), table.bandwidth_hz, "Hz",
                             strf("%ld of %zu modes lie above %.3g Hz: the table cannot excite them (the 30 lb shaker can)", above,
                                  f.size(), table.bandwidth_hz), 0);
  makeAdvisory(modes);
  out.push_back(modes);
  // Each axis's program (the y axis across the plane: world z, spatial model only) against
  // the table's stroke and servo bandwidth.
  struct Axis {
    const std::optional<TableMotion>* motion;
    const char *id, *program;
  };
  for (const Axis& axis : {Axis{&scene.article.base.motion, "", "program"},
                           Axis{&scene.article.base.motion_z, "_z", "y-axis program (across the plane)"}}) {
    if (!*axis.motion) continue;
    const auto program = makeTableProgram(**axis.motion);
    const facility::ProgramCheck pc = facility::checkProgram(*program, table, scene.simulation.duration);
    out.push_back(makeLine("table", strf("table.stroke%s", axis.id), strf("stroke of the %s", axis.program), pc.peak_displacement,
                           table.stroke, "m", program->describe() + strf(", peak acceleration %.3g m/s^2", pc.peak_acceleration),
                           margin));
    CheckLine bw = makeLine("table", strf("table.program%s_bandwidth", axis.id),
                            strf("%s's highest frequency within the bandwidth", axis.program), program->maxFrequencyHz(),
                            table.bandwidth_hz, "Hz", "above it the servo loop attenuates the motion", 0);
    makeAdvisory(bw);
    out.push_back(bw);
  }
}

void addModeLines(const CheckInputs& in, std::vector<CheckLine>& out) {
  const auto& o = in.options;
  int unstable = 0, below = 0, above = 0;
  for (const auto& m : in.modes.modes) {
    if (!m.stable) ++unstable;
    else if (!m.rigid_body && m.frequency_hz < o.band_min_hz) ++below;
    else if (m.frequency_hz > o.band_max_hz) ++above;
  }
  if (unstable > 0) {
    CheckLine l = makeLine("modes", "modes.unstable", "stability of the held configuration", unstable, 0, "modes",
                           "negative stiffness: the article buckles or tips over here", 0);
    l.verdict = Verdict::Fail;
    out.push_back(l);
  }
  const auto f = bandFrequencies(in.modes, o.band_min_hz, o.band_max_hz);
  CheckLine count = makeLine("modes", "modes.in_band", strf("modes in %.3g-%.3g Hz", o.band_min_hz, o.band_max_hz), static_cast<double>(f.size()), 0,
                             "modes", "", 0);
  count.note = f.empty() ? "none: the article shows nothing a test in this band sees"
                         : strf("%.4g to %.4g Hz; %d below the band and %d above it, of the model's %zu", f.front(), f.back(), below,
                                above, in.modes.modes.size());
  count.verdict = f.empty() ? Verdict::Warn : Verdict::Info;
  out.push_back(count);
  if (f.size() < 2) return;
  const double zeta = in.scene.damping && in.scene.damping->kind == DampingSpec::Kind::Modal ? in.scene.damping->modal_ratio : 0.01;
  std::size_t k = 1;  // the closest pair, relative to the half-power bandwidth
  for (std::size_t i = 1; i < f.size(); ++i)
    if ((f[i] - f[i - 1]) / f[i] < (f[k] - f[k - 1]) / f[k]) k = i;
  const double spacing = f[k] - f[k - 1], half_power = 2 * zeta * f[k];
  CheckLine pair = makeLine("modes", "modes.closest_pair", "closest pair apart by more than its half-power bandwidth", half_power, spacing, "Hz",
                            strf("%.4g and %.4g Hz (%.2f %% apart); half-power bandwidth 2 zeta f at zeta = %.3g %%%s", f[k - 1], f[k],
                                 100 * spacing / f[k], 100 * zeta,
                                 in.scene.damping && in.scene.damping->kind == DampingSpec::Kind::Modal ? "" : " (assumed)"),
                            0);
  makeAdvisory(pair);
  out.push_back(pair);
}

}  // namespace

void addTableAndModeLines(const CheckInputs& in, std::vector<CheckLine>& out) {
  addTablePayloadLines(in, out);
  addModeLines(in, out);
}

void addLabLines(const CheckInputs& in, std::vector<CheckLine>& out) {
  if (!in.scene.lab) return;
  const auto& base = in.scene.article.base.position;
  const facility::LabSpec& lab = *in.scene.lab;
  const facility::LabLevels y = facility::labLevels(lab, base[1]);
  std::vector<std::array<double, 3>> pts;  // z: out of the plane (the spatial model)
  for (const auto& p : in.modes.points) pts.push_back({p.x, p.y, p.z});
  bool during_run = false;
  if (in.rigid_run && !in.rigid_run->states.rows.empty()) {  // every point of the rigid article, every sample (at most 2000)
    const auto model = buildArticleModel(in.rigid);
    SimTK::State s = model->getReferenceState();
    const auto& rows = in.rigid_run->states.rows;
    const std::size_t stride = std::max<std::size_t>(1, rows.size() / 2000);
    for (std::size_t r = 0; r < rows.size(); r += stride) {
      model->setQ(s, Eigen::Map<const Eigen::VectorXd>(rows[r].data() + 1, model->getNumCoordinates()));
      model->getSystem().realize(s, SimTK::Stage::Position);
      for (const auto& p : model->getPoints()) {
        const SimTK::Vec3 x = model->findPointLocation(s, p);
        pts.push_back({x[0], x[1], x[2]});
      }
    }
    during_run = true;
  }
  double lowest = INFINITY, highest = -INFINITY, reach = 0, in_hole = 0;
  const double underside = y.platform_top - lab.platform_thickness;
  for (const auto& p : pts) {
    lowest = std::min(lowest, p[1]);
    highest = std::max(highest, p[1]);
    reach = std::max(reach, std::abs(p[0] - base[0]));
    // the hole is square, centred on the base
    if (p[1] > underside) in_hole = std::max({in_hole, std::abs(p[0] - base[0]), std::abs(p[2] - base[2])});
  }
  const std::string when = during_run ? "at rest and during the scene's run (rigid links)" : "at rest";
  out.push_back(makeLine("lab", "lab.depth", "depth below the platform's top within its height above the floor", y.platform_top - lowest,
                         lab.platform_height, "m", strf("lowest point %.3g m above the floor, ", lowest - y.floor) + when, 0));
  out.push_back(makeLine("lab", "lab.ceiling", "height within the ceiling", highest - y.floor, lab.ceiling_height, "m", when, 0));
  out.push_back(makeLine("lab", "lab.hole", "points above the platform's underside within the hole", in_hole, 0.5 * lab.hole_side, "m",
                         "largest horizontal offset from the hole's centre of a point that rises into the platform, " + when, 0));
  out.push_back(makeLine("lab", "lab.reach", "horizontal reach within the floor", reach, 0.5 * lab.floor_length, "m",
                         "from the base, along the floor's length, " + when, 0));
}

}  // namespace mmv::plan

std::vector<std::string> mmv::plausibilityWarnings(const ArticleScene& scene, const ModesReport& modes) {
  const ArticleSpec& a = scene.article;
  std::vector<std::string> warnings = scenePlausibility(scene);  // the rules every command warns with
  double deflection = 0, size = 0;
  for (const auto& p : modes.points) deflection = std::max(deflection, std::hypot(p.dx, p.dy));
  for (const auto& l : a.links) size += l.length;
  if (size > 0 && deflection > 0.1 * size)
    warnings.push_back(strf("the static deflection %.3g m is %.0f %% of the article's length: far from small (check the units of sections and moduli if unexpected)", deflection, 100 * deflection / size));
  for (const auto& mode : modes.modes)
    if (mode.stable && !mode.rigid_body && mode.frequency_hz > 0) {
      if (mode.frequency_hz < 0.01 || mode.frequency_hz > 1e4)
        warnings.push_back(strf("the first flexible mode at %.4g Hz is outside any lab article's range: check the units", mode.frequency_hz));
      break;
    }
  return warnings;
}

namespace mmv::plan {

void addPlausibilityLines(const CheckInputs& in, std::vector<CheckLine>& out) {
  const std::vector<std::string> warnings = plausibilityWarnings(in.scene, in.modes);
  double deflection = 0;
  for (const auto& p : in.modes.points) deflection = std::max(deflection, std::hypot(p.dx, p.dy));
  for (const auto& w : warnings) {
    CheckLine l = makeLine("plausibility", "plausibility.warning", w, 0, 0, "", "likely a unit mistake", 0);
    l.verdict = Verdict::Warn;
    out.push_back(l);
  }
  if (warnings.empty()) {
    CheckLine l = makeLine("plausibility", "plausibility", "masses, lengths, sections, moduli, deflection and frequencies", 0, 0, "",
                           strf("in a lab article's range (largest static deflection %.3g m)", deflection), 0);
    l.verdict = Verdict::Pass;
    out.push_back(l);
  }
}

}  // namespace mmv::plan
