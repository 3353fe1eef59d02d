#include "sim/app/linear_study.hpp"

#include "sim/app/modes_study.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <sstream>

#include <tbb/parallel_invoke.h>
#include <tbb/task_group.h>

#include "sim/core/progress.hpp"
#include "sim/core/text.hpp"
#include "sim/io/linear_report.hpp"
#include "sim/io/report.hpp"
#include "sim/modes/system_modes.hpp"
#include "sim/scene/stations.hpp"

namespace mmv::app {
namespace {

/// x, y, z (0..2) and, where `rotations`, rx, ry, rz (3..5: about world x, y, z). Out of
/// the plane (z, rx, ry) the spatial model only (checked with the model).
int axisOf(const std::string& a, const std::string& what, bool translations, bool rotations) {
  for (int k = translations ? 0 : 3; k < (rotations ? 6 : 3); ++k)
    if (a == axisName(k)) return k;
  const std::string allowed = !rotations ? "x, y or z" : !translations ? "rx, ry or rz" : "x, y, z, rx, ry or rz";
  throw UsageError(what + ": axis must be " + allowed + " (got " + a + ")");
}

InputSpec parseInput(const std::string& text, const std::string& option, const ArticleScene& scene) {
  const auto p = split(text, ':');
  const std::string what = option + " " + text;
  if (text == "shaker") {
    if (!scene.shaker) throw UsageError(what + ": the scene has no shaker: add `shaker:` (docs/scene-format.md) with its station and direction");
    if (scene.shaker->autoAt())
      throw UsageError(what + ": the scene's shaker.at is 'auto', which place-sensors chooses: give the station and direction "
                              "it ranked first (or another)");
    InputSpec in{text, InputKind::PointForce, scene.shaker->at, -1};
    in.direction = scene.shaker->direction;
    in.armature_kg = scene.shaker->hardware.armature_mass;
    return in;
  }
  if (text == "table_x" || text == "table_y" || text == "table_z")
    return {text, InputKind::BaseAcceleration, "", text == "table_x" ? 0 : text == "table_y" ? 1 : 2};
  if (p.size() == 2 && p[0] == "torque") return {text, InputKind::JointTorque, p[1], 0};
  if (p.size() == 3 && p[0] == "force") return {text, InputKind::PointForce, p[1], axisOf(p[2], what, true, false)};
  if (p.size() == 3 && p[0] == "moment") return {text, InputKind::PointMoment, p[1], axisOf(p[2], what, false, true)};
  throw UsageError(what + ": expected table_x, table_y, table_z, torque:JOINT, force:POINT:x|y|z, moment:POINT:rx|ry|rz or shaker");
}

/// strain:A:B[:in|out], two stations of one link and the bending read (sim/linear/
/// state_space.hpp, OutputSpec::span_end): the span and the face's distance from the
/// neutral axis, from the scene.
OutputSpec strainOutput(const ArticleScene& scene, const std::string& text, const std::vector<std::string>& p,
                        const std::string& what) {
  const std::optional<bool> out = p.size() == 4 ? strainBendsOutOfPlane(p[3]) : std::optional<bool>(false);
  if (p.size() < 3 || p.size() > 4 || !out)
    throw UsageError(what + ": expected strain:STATION:STATION[:in|out], two stations of one link and the bending read (in "
                            "the plane, the default, or out of it), e.g. strain:link3a@0.1m:link3a@0.3m");
  std::string why;
  const std::optional<StrainSpan> span = strainSpan(scene.article, p[1], p[2], why, *out);
  if (!span) throw UsageError(what + ": " + why);
  OutputSpec o{text, OutputKind::Displacement, p[1], 5, false};
  o.span_end = p[2];
  o.surface_m = span->surface_m;
  o.span_m = span->x_b - span->x_a;
  o.out_of_plane = *out;
  return o;
}

/// stress:STATION[:face], a station of a flexible link and the face read (+y, the
/// default, -y, +z, -z; sim/linear/state_space.hpp, OutputSpec::stress_face).
OutputSpec stressOutput(const ArticleScene& scene, const std::string& text, const std::vector<std::string>& p,
                        const std::string& what) {
  const std::string face = p.size() == 3 ? p[2] : "+y";
  if (p.size() < 2 || p.size() > 3 || (face != "+y" && face != "-y" && face != "+z" && face != "-z"))
    throw UsageError(what + ": expected stress:STATION[:+y|-y|+z|-z], a station of a flexible link and the face read (+y, "
                            "the default), e.g. stress:link3a@0.1m or stress:link1@0:-y");
  std::string why;
  const auto at = pointAlongLink(scene.article, p[1], why);
  if (!at) throw UsageError(what + ": " + why);
  const LinkSpec& l = *scene.article.findLink(at->first);
  const Section& section = *scene.article.findSection(l.section);
  if (l.rigid) throw UsageError(what + ": link '" + l.name + "' is rigid: it has no hinges whose springs carry a stress");
  const bool out = face[1] == 'z';
  if (out && !scene.article.bendsOutOfPlane(l))
    throw UsageError(what + ": the " + face + " face reads bending out of the plane, which link '" + l.name +
                     "' does not do (model: spatial, and the link not planar)");
  if (!((out ? sectionFibreDistanceOut(section) : sectionFibreDistance(section)) > 0))
    throw UsageError(what + ": link '" + l.name + "''s section '" + section.name + "' gives no fibre distance (an explicit " +
                     "section: state fibre_distance" + (out ? "_out" : "") + ")");
  OutputSpec o{text, OutputKind::Displacement, p[1], 5, false};
  o.stress_face = face;
  o.stress_link = l.name;
  o.stress_x_m = at->second;
  return o;
}

OutputSpec parseOutput(const std::string& text, const std::string& option, const ArticleScene& scene) {
  const auto p = split(text, ':');
  const std::string what = option + " " + text;
  if (p[0] == "strain") return strainOutput(scene, text, p, what);
  if (p[0] == "stress") return stressOutput(scene, text, p, what);
  if (p.size() < 2 || p.size() > 3)
    throw UsageError(what + ": expected POINT:x|y|z|rx|ry|rz[:disp|vel|acc|acc_abs], strain:STATION:STATION[:in|out] or "
                            "stress:STATION[:+y|-y|+z|-z]");
  OutputSpec o{text, OutputKind::Acceleration, p[0], axisOf(p[1], what, true, true), true};
  if (p.size() == 3) {
    if (p[2] == "disp") o = {text, OutputKind::Displacement, p[0], o.axis, false};
    else if (p[2] == "vel") o = {text, OutputKind::Velocity, p[0], o.axis, false};
    else if (p[2] == "acc") o = {text, OutputKind::Acceleration, p[0], o.axis, false};
    else if (p[2] != "acc_abs") throw UsageError(what + ": kind must be disp, vel, acc or acc_abs");
  }
  return o;
}

/// Checks the named points and joints against the scene before any model is built
/// (points and stations as every option naming them: checkedPoints).
void checkNames(const ArticleScene& scene, const std::vector<InputSpec>& in, const std::vector<OutputSpec>& out,
                const std::string& in_option, const std::string& out_option) {
  for (const auto& i : in) {
    if (i.kind == InputKind::PointForce || i.kind == InputKind::PointMoment)
      checkedPoints({i.target}, scene.article, in_option + " " + i.name);
    if (i.kind != InputKind::JointTorque) continue;
    const JointSpec* j = scene.article.findJoint(i.target);
    std::string joints;
    for (const auto& x : scene.article.joints) joints += (joints.empty() ? "" : ", ") + x.name;
    if (!j) throw UsageError(in_option + " " + i.name + ": unknown joint '" + i.target + "' (known: " + joints + ")");
    if (j->hold == JointHold::Locked)
      throw UsageError(in_option + " " + i.name + ": joint '" + i.target +
                       "' is locked (hold: locked), so a torque there moves nothing; use a free or servo joint");
  }
  for (const auto& o : out) checkedPoints({o.point}, scene.article, out_option + " " + o.name);  // a strain's: stations, checked
  if (scene.article.model == ArticleModel::Spatial) return;
  const std::string planar = " is out of the plane, where the planar model does not move (model: spatial)";
  for (const auto& i : in)
    if (i.kind != InputKind::JointTorque && leavesThePlane(i.axis))
      throw UsageError(in_option + " " + i.name + ": " + axisName(i.axis) + planar);
  for (const auto& o : out)
    if (leavesThePlane(o.axis)) throw UsageError(out_option + " " + o.name + ": " + axisName(o.axis) + planar);
}

/// The damping the request's model gets: --damping-ratio when given, else the scene's,
/// else every mode's 1 %.
DampingSpec requestDamping(const LinearRequest& r, const ArticleScene& scene) {
  DampingSpec d;
  d.modal_ratio = r.damping_ratio;
  if (scene.damping && !r.damping_given) d = *scene.damping;
  return d;
}

LinearModel build(const LinearRequest& r, const ArticleScene& scene, bool prepare_responses) {
  const std::string in_option = optionName(r.front, "--input"), out_option = optionName(r.front, "--output");
  std::vector<InputSpec> in;
  std::vector<OutputSpec> out;
  for (const auto& t : r.inputs) in.push_back(parseInput(t, in_option, scene));
  if (std::count(r.inputs.begin(), r.inputs.end(), std::string("shaker")) > 1)
    throw UsageError(in_option + " shaker: given twice (the scene has one shaker, and its armature would count twice)");
  for (const auto& t : r.outputs) out.push_back(parseOutput(t, out_option, scene));
  checkNames(scene, in, out, in_option, out_option);
  if (in.empty()) in = defaultInputs();
  if (out.empty()) out = defaultOutputs(scene);
  return buildLinearModel(scene, in, out, requestDamping(r, scene), prepare_responses);
}

/// The mesh's share (LinearStudy::mesh_*): each vibration mode up to f_max, its
/// estimated frequency error (estimateDiscretization: the scene at segments / 2 and / 4)
/// over its damping ratio. Reads the request and a.scene only (it runs beside the
/// linear model's construction): the damping is the request's, as the linear model's.
void estimateMeshError(const LinearRequest& r, LinearStudy& a) {
  const ProgressStage stage("the mesh's share of the FRF error (the modes again, and on a coarser mesh)");
  ModesOptions mo;
  mo.max_modes = 60;  // the modes up to f_max are picked below
  mo.with_shapes = false;
  mo.damping = requestDamping(r, a.scene);
  const ModesReport rep = runModes(a.scene, mo);
  const DiscretizationEstimate d = estimateDiscretization(a.scene, rep);
  if (!d.available) {
    a.mesh_note = d.reason;
    return;
  }
  a.mesh_error = 0;
  for (std::size_t k = 0; k < rep.modes.size() && k < d.modes.size(); ++k) {
    const ModeInfo& m = rep.modes[k];
    if (!m.stable || m.rigid_body || !m.has_damping || m.frequency_hz > r.f_max || !d.modes[k].has_estimate) continue;
    const double e = d.modes[k].estimated_relative_error, z = std::max(m.damping_ratio, 1e-12);
    const double term = std::min(1.0, std::abs(e / std::complex<double>(e, z)));
    if (term > a.mesh_error)
      a.mesh_error = term, a.mesh_mode = m.number, a.mesh_mode_hz = m.frequency_hz, a.mesh_mode_error = e, a.mesh_mode_zeta = z;
  }
}

void respond(const LinearRequest& r, const std::vector<double>& grid, LinearStudy& a) {
  a.f = resolveResonances(grid, a.red.kept_frequencies_hz, a.red.kept_damping);
  a.w = a.f;
  for (double& x : a.w) x *= 2 * M_PI;
  a.hf = fullResponses(a.lm.second_order, a.w);
  a.err = compareResponses(a.hf, a.red.model, a.w);
  const ProgressStage stage("the reduced model's error: fewest modes within the target");
  if (r.rom_target > 0)  // how many modes the stated accuracy needs (a bisection over reductions)
    modesForTarget(a.lm.full, reductionOptions(r, a.lm), a.hf, a.w, r.rom_target,
                   std::max(1, std::min(60, a.lm.full.numStates() / 2)), a.err);
}

/// The finest mesh frf's and rom's --target-error try: at 256 segments per link the
/// full responses and the search for the fewest kept modes take minutes (a 10 % FRF
/// target on the table scene needs 64, 5 % 128; docs/accuracy.md).
constexpr int kMaxFrfTargetSegments = 128;

/// target_error E bounds the FRF near every peak up to f_max: half of it for the mesh,
/// half for the reduced model (the two add). A mode whose frequency is off by e
/// (relative) moves its peak's response by |e / (e + i zeta)| of it, within E/2 when
/// e <= (E/2) zeta / sqrt(1 - E^2/4): the segments hold every mode up to f_max to that,
/// zeta the least damped one's (segmentsForTarget); the request then asks for the fewest
/// kept modes within E/2 of each pair's peak.
void chooseForTarget(LinearRequest& r, ArticleScene& scene, LinearStudy& a) {
  ModesOptions mo;
  mo.max_modes = 60;
  mo.with_shapes = false;
  mo.damping = requestDamping(r, scene);
  const ModesReport rep = runModes(scene, mo);
  int in_band = 0;
  double zeta = 1;
  for (const ModeInfo& m : rep.modes) {
    if (m.frequency_hz > r.f_max) continue;
    ++in_band;
    if (m.stable && !m.rigid_body && m.has_damping) zeta = std::min(zeta, m.damping_ratio);
  }
  const double half = 0.5 * r.target_error;
  a.frf_target = r.target_error;
  a.frequency_target = half * std::max(zeta, 1e-9) / std::sqrt(1 - half * half);
  a.least_damping = zeta;
  try {
    a.segments = segmentsForTarget(scene, std::clamp(in_band, 1, 60), a.frequency_target, kMaxFrfTargetSegments,
                                   r.time_budget);
  } catch (const NumericalError& e) {
    const std::string why = e.what(), from = "cannot be met";
    throw NumericalError(strf("%s %g of each pair's peak: the mesh's half needs every frequency up to %g Hz within "
                              "%.2g (%g x the least damping ratio %.3g), which ",
                              optionName(r.front, "--target-error").c_str(), r.target_error, r.f_max,
                              a.frequency_target, half, zeta) +
                         why.substr(std::min(why.find(from), why.size())) +
                         "; give a larger target, a lower " + optionName(r.front, "--to") + " or more damping");
  }
  overrideSegments(scene, a.segments->segments);
  r.rom_target = half;
  r.rom_modes = std::clamp(in_band, 1, 60);  // the candidates: the grid resolves each one's band
}

}  // namespace

std::vector<double> checkLinearRequest(const LinearRequest& r) {
  const auto opt = [&](const char* flag) { return optionName(r.front, flag); };
  if (!(r.f_min > 0) || !(r.f_max > r.f_min) || !std::isfinite(r.f_max))
    throw UsageError(opt("--from") + "/" + opt("--to") + ": need 0 < FROM < TO (Hz)");
  checkRange(r.front, "--points", r.points, 2, 100000);
  checkRange(r.front, "--rom-modes", r.rom_modes, 1, 10000);
  checkRange(r.front, "--damping", r.damping_ratio, 0, 1);
  checkRange(r.front, "--rom-target", r.rom_target, 0, 1);
  if (r.target_error != 0) checkRange(r.front, "--target-error", r.target_error, 1e-12, 0.5);
  if (r.time_budget != 0) checkRange(r.front, "--time-budget", r.time_budget, 0, kUnbounded, /*open_low=*/true);
  if (r.band && (!(r.band->first >= 0) || !(r.band->second > r.band->first) || !std::isfinite(r.band->second)))
    throw UsageError(strf("%s: expected 0 <= F_MIN_HZ < F_MAX_HZ (got %g:%g)", opt("--band").c_str(), r.band->first,
                          r.band->second));
  if (r.target_error > 0) {
    if (r.segments_given) throw UsageError(opt("--target-error") + " chooses the segments per link: drop " + opt("--segments"));
    if (r.band) throw UsageError(opt("--target-error") + " chooses the modes kept: drop " + opt("--band"));
  } else if (r.time_budget > 0) {
    throw UsageError(opt("--time-budget") + " applies to " + opt("--target-error") + " only");
  }
  // A band alone sets the grid too: a model reduced to a band is judged there.
  if (r.band && !r.range_given) {
    const double from = r.band->first > 0 ? r.band->first : std::min(r.f_min, 0.01 * r.band->second);
    return logFrequencies(from, r.band->second, r.points);
  }
  return logFrequencies(r.f_min, r.f_max, r.points);
}

ReductionOptions reductionOptions(const LinearRequest& r) {
  ReductionOptions o;
  o.modes = r.rom_modes;
  if (r.band) {
    std::tie(o.band_min_hz, o.band_max_hz) = *r.band;
    o.modes = 0;
  }
  o.residualize = r.residualize;
  return o;
}

ReductionOptions reductionOptions(const LinearRequest& r, const LinearModel& lm) {
  ReductionOptions o = reductionOptions(r);
  o.proportional = lm.proportional;
  return o;
}

LinearStudy runLinearStudy(const ArticleScene& scene_in, const LinearRequest& request) {
  const std::vector<double> grid = checkLinearRequest(request);
  if (!request.vary.empty()) throw UsageError(optionName(request.front, "--vary") + " applies to HAM-SAS scenes only");
  LinearRequest r = request;
  LinearStudy a;
  ArticleScene scene = scene_in;
  if (r.target_error > 0) chooseForTarget(r, scene, a);
  a.scene = std::move(scene);
  // The mesh's share (the scene solved again, and on coarser meshes: serial work) on
  // another core from the start, beside the linear model's construction (the other core
  // idles there otherwise), the reduction, the test geometry and the responses, which
  // stay on this thread (its progress stages); each writes its own fields.
  tbb::task_group mesh;
  mesh.run([&] { estimateMeshError(r, a); });
  try {
    a.lm = build(r, a.scene, false);
    {
      // The full model's responses are prepared (one Hessenberg reduction of the
      // first-order matrix) on another core while the reduction runs.
      const ProgressStage stage(strf("reducing: the state-space model's modes (%d states), the full model factorized beside it",
                                     a.lm.full.numStates()));
      tbb::parallel_invoke([&] { a.lm.second_order.prepare(); }, [&] { a.red = reduceModal(a.lm.full, reductionOptions(r, a.lm)); });
    }
    a.geometry = linearTestGeometry(a.lm, a.scene, kLinearModelModes);
    respond(r, grid, a);
  } catch (...) {
    try {
      mesh.wait();  // nothing may outlive `a`; this error, not the estimate's, is told
    } catch (...) {
    }
    throw;
  }
  mesh.wait();
  if (a.segments && a.err.needed.reached && a.err.needed.modes != r.rom_modes) {
    // The fewest modes within the target, compared on the same grid (it resolves every
    // candidate's half-power band, so the kept ones' too): no second full response.
    r.rom_modes = a.err.needed.modes;
    a.red = reduceModal(a.lm.full, reductionOptions(r, a.lm));
    const ModelError::ModesNeeded needed = a.err.needed;
    a.err = compareResponses(a.hf, a.red.model, a.w);
    a.err.needed = needed;
  } else if (a.segments && !a.err.needed.reached) {
    throw NumericalError(strf("%s %g: no reduced model of up to %d modes is within %g (its half) of each pair's peak",
                              optionName(r.front, "--target-error").c_str(), r.target_error, a.err.needed.modes,
                              r.rom_target));
  }
  return a;
}

std::string LinearStudy::summaryText() const {
  std::string s = linearSummaryText(lm, red, err, f, hf);
  if (mesh_error < 0) {
    s += "\nThe mesh's share of the FRF error: not estimated (" + mesh_note + ")\n";
  } else {
    s += strf("\nThe mesh's share of the FRF error near the peaks (not in the reduced-model errors above, which compare "
              "with the full model on this mesh; the two add): %.3g of the peak",
              mesh_error) +
         (mesh_mode ? strf(" at mode %d (%.4g Hz: frequency error %.2g over damping ratio %.3g)\n", mesh_mode->number(), mesh_mode_hz,
                           mesh_mode_error, mesh_mode_zeta)
                    : std::string(" (no damped vibration mode in the band has a mesh estimate)\n"));
    if (segments && mesh_error > 0.5 * frf_target)
      s += strf("warning: the mesh's share %.3g exceeds half the target %g although every frequency up to the band's "
                "end was held within %.2g: its estimate at the finer mesh is above the coarser meshes' trend\n",
                mesh_error, frf_target, frequency_target);
  }
  if (segments)
    s += strf("\nTarget error %g of each pair's peak: half for the mesh (every frequency up to the band's end within "
              "%.2g = %g x the least damping ratio %.3g / sqrt(1 - %g^2)), half for the reduced model",
              frf_target, frequency_target, 0.5 * frf_target, least_damping, 0.5 * frf_target) +
         segmentsChoiceText(*segments) + strf("Reduced model for the target: %d modes kept, the fewest within %g of each pair's peak\n",
                                              err.needed.modes, 0.5 * frf_target);
  return s;
}

namespace {

void addTargetAndMesh(const LinearStudy& a, nlohmann::ordered_json& j) {
  if (a.segments) {
    nlohmann::ordered_json t = segmentsChoiceJson(*a.segments);
    t["frf_target_relative_error"] = a.frf_target;
    t["least_damping_ratio"] = a.least_damping;
    t["rom_modes"] = a.err.needed.modes;
    t["mesh_frf_error_within_target"] = a.mesh_error >= 0 && a.mesh_error <= 0.5 * a.frf_target;
    j["target_error"] = t;
  }
  j["mesh_frf_error_estimate"] = a.mesh_error >= 0 ? nlohmann::ordered_json(a.mesh_error) : nlohmann::ordered_json(nullptr);
  j["mesh_frf_error_mode"] = a.mesh_mode ? nlohmann::ordered_json(*a.mesh_mode) : nlohmann::ordered_json(nullptr);
}

}  // namespace

nlohmann::ordered_json LinearStudy::frfJson() const {
  nlohmann::ordered_json j = linearSummaryJson(lm, red, err, f, hf, scene.name);
  addTargetAndMesh(*this, j);
  return j;
}

nlohmann::ordered_json LinearStudy::romJson() const {
  nlohmann::ordered_json j = mmv::romJson(lm, red, err, f);
  addTargetAndMesh(*this, j);
  return j;
}

}  // namespace mmv::app
