// mmvlab frf and mmvlab rom: linear models for control design (sim/linear/state_space.hpp).
#include <algorithm>
#include <cmath>
#include <complex>
#include <ctime>
#include <map>
#include <optional>
#include <fstream>
#include <iostream>
#include <tuple>
#include <sstream>

#include <tbb/parallel_invoke.h>

#include "sim/cli/figures.hpp"
#include "sim/cli/commands.hpp"
#include "sim/core/progress.hpp"
#include "sim/io/output_dir.hpp"
#include "sim/io/mat_file.hpp"
#include "sim/io/linear_report.hpp"
#include "sim/io/report.hpp"
#include "sim/modes/converge.hpp"
#include "sim/modes/system_modes.hpp"
#include "sim/linear/state_space.hpp"
#include "sim/scene/stations.hpp"
#include "sim/core/text.hpp"

namespace mmv::cli {
namespace {

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> out;
  std::stringstream ss(s);
  for (std::string p; std::getline(ss, p, sep);) out.push_back(p);
  return out;
}

/// x, y, z (0..2) and, where `rotations`, rx, ry, rz (3..5: about world x, y, z). Out of
/// the plane (z, rx, ry) the spatial model only (checked with the model).
int axisOf(const std::string& a, const std::string& what, bool translations, bool rotations) {
  for (int k = translations ? 0 : 3; k < (rotations ? 6 : 3); ++k)
    if (a == axisName(k)) return k;
  const std::string allowed = !rotations ? "x, y or z" : !translations ? "rx, ry or rz" : "x, y, z, rx, ry or rz";
  throw UsageError(what + ": axis must be " + allowed + " (got " + a + ")");
}

InputSpec parseInput(const std::string& text) {
  const auto p = split(text, ':');
  if (text == "table_x" || text == "table_y" || text == "table_z")
    return {text, InputKind::BaseAcceleration, "", text == "table_x" ? 0 : text == "table_y" ? 1 : 2};
  if (p.size() == 2 && p[0] == "torque") return {text, InputKind::JointTorque, p[1], 0};
  if (p.size() == 3 && p[0] == "force") return {text, InputKind::PointForce, p[1], axisOf(p[2], "--input " + text, true, false)};
  if (p.size() == 3 && p[0] == "moment")
    return {text, InputKind::PointMoment, p[1], axisOf(p[2], "--input " + text, false, true)};
  throw UsageError("--input " + text +
                   ": expected table_x, table_y, table_z, torque:JOINT, force:POINT:x|y|z or moment:POINT:rx|ry|rz");
}

OutputSpec parseOutput(const std::string& text) {
  const auto p = split(text, ':');
  if (p.size() < 2 || p.size() > 3)
    throw UsageError("--output " + text + ": expected POINT:x|y|z|rx|ry|rz[:disp|vel|acc|acc_abs]");
  OutputSpec o{text, OutputKind::Acceleration, p[0], axisOf(p[1], "--output " + text, true, true), true};
  if (p.size() == 3) {
    if (p[2] == "disp") o = {text, OutputKind::Displacement, p[0], o.axis, false};
    else if (p[2] == "vel") o = {text, OutputKind::Velocity, p[0], o.axis, false};
    else if (p[2] == "acc") o = {text, OutputKind::Acceleration, p[0], o.axis, false};
    else if (p[2] != "acc_abs") throw UsageError("--output " + text + ": kind must be disp, vel, acc or acc_abs");
  }
  return o;
}

/// Checks the named points and joints against the scene before any model is built.
void checkNames(const ArticleScene& scene, const std::vector<InputSpec>& in, const std::vector<OutputSpec>& out) {
  const std::vector<std::string> points = articlePointNames(scene.article);
  const std::string how = " (points are <joint>, <link>.root, <link>.tip and <link>.h1 .. <link>.h<segments>; stations "
                          "<link>@<m>m or <link>@<fraction>)";
  // Empty when `p` is a point or a station of the scene, else why not.
  auto problem = [&](const std::string& p) -> std::string {
    std::string error;
    if (isStationName(p)) return parseStation(p, scene.article, error) ? "" : error;
    return std::find(points.begin(), points.end(), p) != points.end() ? "" : "unknown point '" + p + "'" + how;
  };
  for (const auto& i : in) {
    if ((i.kind == InputKind::PointForce || i.kind == InputKind::PointMoment) && !problem(i.target).empty())
      throw UsageError("--input " + i.name + ": " + problem(i.target));
    if (i.kind != InputKind::JointTorque) continue;
    const JointSpec* j = scene.article.findJoint(i.target);
    std::string joints;
    for (const auto& x : scene.article.joints) joints += (joints.empty() ? "" : ", ") + x.name;
    if (!j) throw UsageError("--input " + i.name + ": unknown joint '" + i.target + "' (known: " + joints + ")");
    if (j->hold == JointHold::Locked)
      throw UsageError("--input " + i.name + ": joint '" + i.target +
                       "' is locked (hold: locked), so a torque there moves nothing; use a free or servo joint");
  }
  for (const auto& o : out)
    if (!problem(o.point).empty()) throw UsageError("--output " + o.name + ": " + problem(o.point));
}

LinearModel build(const LinearArgs& args, const ArticleScene& scene, bool prepare_responses) {
  std::vector<InputSpec> in;
  std::vector<OutputSpec> out;
  for (const auto& t : args.inputs) in.push_back(parseInput(t));
  for (const auto& t : args.outputs) out.push_back(parseOutput(t));
  checkNames(scene, in, out);
  if (in.empty()) in = defaultInputs();
  if (out.empty()) out = defaultOutputs(scene);
  DampingSpec d;
  d.modal_ratio = args.damping_ratio;
  if (scene.damping && !args.damping_given) d = *scene.damping;
  return buildLinearModel(scene, in, out, d, prepare_responses);
}

}  // namespace

ReductionOptions reductionOptions(const LinearArgs& args) {
  ReductionOptions o;
  o.modes = args.rom_modes;
  if (!args.band.empty()) {
    std::tie(o.band_min_hz, o.band_max_hz) = parseBand(args.band);
    o.modes = 0;
  }
  o.residualize = !args.no_residualize;
  return o;
}

namespace {

ReducedModel reduce(const LinearArgs& args, const StateSpace& full) { return reduceModal(full, reductionOptions(args)); }

struct Linear {
  LinearModel lm;
  ReducedModel red;
};

/// The linear model and its reduction; the full model's responses are prepared (one
/// Hessenberg reduction of the first-order matrix) on another core meanwhile.
Linear buildAndReduce(const LinearArgs& args, const ArticleScene& scene) {
  Linear r{build(args, scene, false), {}};
  const ProgressStage stage(strf("reducing: the state-space model's modes (%d states), the full model factorized beside it",
                                 r.lm.full.numStates()));
  tbb::parallel_invoke([&] { r.lm.second_order.prepare(); }, [&] { r.red = reduce(args, r.lm.full); });
  return r;
}

/// The response grid: --from..--to; with --band and no --from/--to, the band (from
/// --from's default where the band starts at 0): a model reduced to a band is judged
/// there, and its error and band_hz say so.
std::vector<double> frequencies(const LinearArgs& a) {
  if (!(a.f_min > 0) || !(a.f_max > a.f_min)) throw UsageError("--from/--to: need 0 < FROM < TO (Hz)");
  if (!a.band.empty() && !a.range_given) {
    const auto [lo, hi] = parseBand(a.band);
    const double from = lo > 0 ? lo : std::min(a.f_min, 0.01 * hi);
    return logFrequencies(from, hi, a.points);
  }
  return logFrequencies(a.f_min, a.f_max, a.points);
}

/// What frf and rom compute: the model at the segments used, its reduction, the grid
/// (every kept mode's half-power band resolved), the full responses and the errors.
struct Analysis {
  ArticleScene scene;
  LinearModel lm;
  ReducedModel red;
  std::vector<double> f, w;
  std::vector<Eigen::MatrixXcd> hf;
  ModelError err;
  std::optional<SegmentsChoice> segments;  ///< --target-error: how the segments were chosen
  /// The mesh's share of the FRF error near the peaks, which `err` (reduced against full
  /// on this mesh) does not see: near its peak a mode whose frequency is off by e
  /// (relative) moves the response by about |e / (e + i zeta)| ~ e / zeta of the peak.
  /// The worst over the vibration modes up to --to (capped at 1); -1: not estimated.
  double mesh_error = -1;
  int mesh_mode = 0;
  double mesh_mode_hz = 0, mesh_mode_error = 0, mesh_mode_zeta = 0;
  std::string mesh_note;  ///< why not estimated
};

/// Fills a.mesh_*: each vibration mode up to --to, its estimated frequency error
/// (estimateDiscretization: the scene at segments / 2 and / 4) over its damping ratio.
void estimateMeshError(const LinearArgs& args, Analysis& a) {
  const ProgressStage stage("the mesh's share of the FRF error (the modes again, and on a coarser mesh)");
  ModesOptions mo;
  mo.max_modes = 60;
  mo.with_shapes = false;
  mo.damping = a.lm.damping;
  const ModesReport rep = runModes(a.scene, mo);
  const DiscretizationEstimate d = estimateDiscretization(a.scene, rep);
  if (!d.available) {
    a.mesh_note = d.reason;
    return;
  }
  a.mesh_error = 0;
  for (std::size_t k = 0; k < rep.modes.size() && k < d.modes.size(); ++k) {
    const ModeInfo& m = rep.modes[k];
    if (!m.stable || m.rigid_body || !m.has_damping || m.frequency_hz > args.f_max || !d.modes[k].has_estimate) continue;
    const double e = d.modes[k].estimated_relative_error, z = std::max(m.damping_ratio, 1e-12);
    const double term = std::min(1.0, std::abs(e / std::complex<double>(e, z)));
    if (term > a.mesh_error)
      a.mesh_error = term, a.mesh_mode = m.number, a.mesh_mode_hz = m.frequency_hz, a.mesh_mode_error = e, a.mesh_mode_zeta = z;
  }
}

std::string meshText(const Analysis& a) {
  if (a.mesh_error < 0) return "\nThe mesh's share of the FRF error: not estimated (" + a.mesh_note + ")\n";
  std::string s = strf("\nThe mesh's share of the FRF error near the peaks (not in the reduced-model errors above, which compare "
                       "with the full model on this mesh; the two add): %.3g of the peak at mode %d (%.4g Hz: frequency "
                       "error %.2g over damping ratio %.3g)\n",
                       a.mesh_error, a.mesh_mode, a.mesh_mode_hz, a.mesh_mode_error, a.mesh_mode_zeta);
  if (a.segments && a.mesh_error > a.segments->target)
    s += strf("warning: --target-error %g holds each frequency within it, not the FRF near a lightly damped peak: mode "
              "%d's is about %.3g of its peak off the converged response (the FRF within %g needs that mode's frequency "
              "within %.2g); give more --segments or a larger target\n",
              a.segments->target, a.mesh_mode, a.mesh_error, a.segments->target, a.segments->target * a.mesh_mode_zeta);
  return s;
}

void addMeshJson(const Analysis& a, nlohmann::ordered_json& j) {
  j["mesh_frf_error_estimate"] = a.mesh_error >= 0 ? nlohmann::ordered_json(a.mesh_error) : nlohmann::ordered_json(nullptr);
  j["mesh_frf_error_mode"] = a.mesh_mode > 0 ? nlohmann::ordered_json(a.mesh_mode) : nlohmann::ordered_json(nullptr);
}

void respond(const LinearArgs& args, const std::vector<double>& grid, Analysis& a) {
  a.f = resolveResonances(grid, a.red.kept_frequencies_hz, a.red.kept_damping);
  a.w = a.f;
  for (double& x : a.w) x *= 2 * M_PI;
  a.hf = fullResponses(a.lm.second_order, a.w);
  a.err = compareResponses(a.hf, a.red.model, a.w);
  const ProgressStage stage("the reduced model's error: fewest modes within the target");
  if (args.rom_target > 0)  // how many modes the stated accuracy needs (a bisection over reductions)
    modesForTarget(a.lm.full, reductionOptions(args), a.hf, a.w, args.rom_target,
                   std::max(1, std::min(60, a.lm.full.numStates() / 2)), a.err);
}

/// --target-error E: the segments that hold every mode up to --to within E
/// (segmentsForTarget), then the fewest kept modes whose reduced model is within E of
/// each pair's peak (modesForTarget), the reduction redone with them.
Analysis analyse(LinearArgs args, ArticleScene scene, const std::vector<double>& grid) {
  Analysis a;
  if (args.target_error > 0) {
    if (args.segments > 0) throw UsageError("--target-error chooses the segments per link: drop --segments");
    if (!args.band.empty()) throw UsageError("--target-error chooses the modes kept: drop --band");
    const ModesSolve all = solveSceneModes(scene, {}, 0);
    int in_band = 0;
    for (Eigen::Index k = 0; k < all.frequencies_hz.size(); ++k) in_band += all.frequencies_hz[k] <= args.f_max;
    a.segments = segmentsForTarget(scene, std::clamp(in_band, 1, 60), args.target_error, kMaxTargetSegments, args.time_budget);
    overrideSegments(scene, a.segments->segments);
    args.rom_target = args.target_error;
    args.rom_modes = std::clamp(in_band, 1, 60);  // the candidates: the grid resolves each one's band
  } else if (args.time_budget > 0) {
    throw UsageError("--time-budget applies to --target-error only");
  }
  std::tie(a.lm, a.red) = [&] {
    Linear l = buildAndReduce(args, scene);
    return std::make_pair(std::move(l.lm), std::move(l.red));
  }();
  a.scene = std::move(scene);
  respond(args, grid, a);
  estimateMeshError(args, a);
  if (a.segments && a.err.needed.reached && a.err.needed.modes != args.rom_modes) {
    // The fewest modes within the target, compared on the same grid (it resolves every
    // candidate's half-power band, so the kept ones' too): no second full response.
    args.rom_modes = a.err.needed.modes;
    a.red = reduce(args, a.lm.full);
    const ModelError::ModesNeeded needed = a.err.needed;
    a.err = compareResponses(a.hf, a.red.model, a.w);
    a.err.needed = needed;
  } else if (a.segments && !a.err.needed.reached) {
    throw NumericalError(strf("--target-error %g: no reduced model of up to %d modes is within it of each pair's peak",
                              args.target_error, a.err.needed.modes));
  }
  return a;
}

/// The target's choices, after the summary.
std::string targetText(const Analysis& a) {
  if (!a.segments) return "";
  return segmentsChoiceText(*a.segments) +
         strf("Reduced model for the target: %d modes kept, the fewest within %g of each pair's peak\n",
              a.err.needed.modes, a.segments->target);
}

void addTargetJson(const Analysis& a, nlohmann::ordered_json& j) {
  if (!a.segments) return;
  nlohmann::ordered_json t = segmentsChoiceJson(*a.segments);
  t["rom_modes"] = a.err.needed.modes;
  t["mesh_frf_error_within_target"] = a.mesh_error >= 0 && a.mesh_error <= a.segments->target;
  j["target_error"] = t;
}

}  // namespace

int runFrfCommand(const LinearArgs& args) {
  return guarded([&]() -> int {
    const Scene loaded = loadScene(args);
    const std::vector<double> grid = frequencies(args);
    if (const auto* h = std::get_if<HamsasScene>(&loaded)) {
      if (args.target_error > 0) throw UsageError("--target-error applies to the article's scenes (HAM-SAS has no segments)");
      return runHamsasFrf(args, *h, grid);
    }
    if (!args.vary.empty()) throw UsageError("--vary applies to HAM-SAS scenes only");
    std::unique_ptr<OutputDir> out;
    if (!args.out.empty()) out = std::make_unique<OutputDir>(args.out, args.force);
    const Analysis a = analyse(args, std::get<ArticleScene>(loaded), grid);
    const ArticleScene& scene = a.scene;
    const LinearModel& lm = a.lm;
    const ReducedModel& red = a.red;
    const std::vector<double>& f = a.f;
    const std::vector<double>& w = a.w;
    const std::vector<Eigen::MatrixXcd>& hf = a.hf;
    const ModelError& err = a.err;
    if (out) {
      const StateSpace& s = lm.full;
      std::vector<Eigen::MatrixXcd> hr;
      for (double x : w) hr.push_back(red.model.response(x));
      std::vector<double> markers;  // the kept modes, on the plot's frequency axis
      for (double fk : red.kept_frequencies_hz) markers.push_back(args.rad ? 2 * M_PI * fk : fk);
      for (Eigen::Index o = 0; o < s.C.rows(); ++o)
        for (Eigen::Index i = 0; i < s.B.cols(); ++i) {
          const std::string base = safeFileName(s.output_names[o]) + "__" + safeFileName(s.input_names[i]);
          render::BodeTrace full{"full model (" + std::to_string(s.numStates()) + " states)"}, rom{
              "reduced (" + std::to_string(red.model.numStates()) + " states)"};
          rom.dashed = true;
          for (std::size_t k = 0; k < f.size(); ++k) {
            const std::complex<double> a = hf[k](o, i), b = hr[k](o, i);
            const double fa = 20 * std::log10(std::abs(a) + 1e-300), fb = 20 * std::log10(std::abs(b) + 1e-300);
            const double x = args.rad ? w[k] : f[k];
            full.frequency.push_back(x);
            full.magnitude_db.push_back(fa);
            full.phase_deg.push_back(std::arg(a) * 180 / M_PI);
            rom.frequency.push_back(x);
            rom.magnitude_db.push_back(fb);
            rom.phase_deg.push_back(std::arg(b) * 180 / M_PI);
          }
          out->write("frf_" + base + ".csv", frfCsv(s, o, i, f, hf, hr));
          try {
            figures::bode(out->stage("bode_" + base + ".png"), {full, rom},
                          s.output_names[o] + " / " + s.input_names[i] + " (" + s.output_units[o] + " per " +
                              s.input_units[i] + "): " + scene.name,
                          args.rad ? "frequency (rad/s)" : "frequency (Hz)", markers);
          } catch (const std::runtime_error& e) {
            throw OutputError(e.what());
          }
        }
      out->write("frf.uff", frfUff(lm, scene, f, hf));
    }
    const std::string text = args.json ? "" : linearSummaryText(lm, red, err, f, hf) + meshText(a) + targetText(a);
    nlohmann::ordered_json json = args.json ? linearSummaryJson(lm, red, err, f, hf, scene.name) : nlohmann::ordered_json();
    if (args.json) addTargetJson(a, json), addMeshJson(a, json);
    if (out) {
      args.json ? checkResultFinite(json) : checkResultFinite(text);  // before any file is committed
      out->commit();  // reported as written when the command succeeds
    }
    args.json ? emitResult(json) : emitResult(text);
    return kOk;
  });
}

int runRomCommand(const LinearArgs& args) {
  return guarded([&]() -> int {
    if (args.out.empty()) throw UsageError("rom: --out DIR is required (it writes rom.mat and full.mat)");
    const Scene loaded = loadScene(args);
    const std::vector<double> grid = frequencies(args);
    if (const auto* h = std::get_if<HamsasScene>(&loaded)) {
      if (args.target_error > 0) throw UsageError("--target-error applies to the article's scenes (HAM-SAS has no segments)");
      return runHamsasRom(args, *h, grid);
    }
    OutputDir out(args.out, args.force);
    const Analysis a = analyse(args, std::get<ArticleScene>(loaded), grid);
    const LinearModel& lm = a.lm;
    const ReducedModel& red = a.red;
    try {
      writeStateSpaceMat(out.stage("rom.mat"), red.model);
      writeStateSpaceMat(out.stage("full.mat"), lm.full);
    } catch (const std::runtime_error& e) {
      throw OutputError(e.what());
    }
    nlohmann::ordered_json rom_json = romJson(lm, red, a.err, a.f);
    addTargetJson(a, rom_json);
    addMeshJson(a, rom_json);
    checkResultFinite(rom_json);  // before any file is committed
    out.write("rom.json", rom_json.dump(2) + "\n");
    // The text for stdout is made before --out is committed: nothing long runs after it.
    const std::string text = args.json ? "" : linearSummaryText(lm, red, a.err, a.f, a.hf) + meshText(a) + targetText(a);
    out.commit();  // reported as written when the command succeeds
    args.json ? emitResult(rom_json) : emitResult(text);
    return kOk;
  });
}

}  // namespace mmv::cli
