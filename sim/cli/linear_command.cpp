// mmvlab frf and mmvlab rom: linear models for control design (sim/linear/state_space.hpp).
#include <cmath>
#include <ctime>
#include <map>
#include <fstream>
#include <iostream>
#include <sstream>

#include "renders/plot.hpp"
#include "sim/cli/commands.hpp"
#include "sim/io/output_dir.hpp"
#include "sim/io/mat_file.hpp"
#include "sim/io/report.hpp"
#include "sim/linear/state_space.hpp"
#include "sim/core/text.hpp"
#include "sim/io/uff.hpp"

namespace mmv::cli {
namespace {

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> out;
  std::stringstream ss(s);
  for (std::string p; std::getline(ss, p, sep);) out.push_back(p);
  return out;
}

int axisOf(const std::string& a, const std::string& what) {
  if (a == "x") return 0;
  if (a == "y") return 1;
  throw UsageError(what + ": axis must be x or y (got " + a + ")");
}

InputSpec parseInput(const std::string& text) {
  const auto p = split(text, ':');
  if (text == "table_x" || text == "table_y") return {text, InputKind::BaseAcceleration, "", text == "table_y"};
  if (p.size() == 2 && p[0] == "torque") return {text, InputKind::JointTorque, p[1], 0};
  if (p.size() == 3 && p[0] == "force") return {text, InputKind::PointForce, p[1], axisOf(p[2], "--input " + text)};
  throw UsageError("--input " + text + ": expected table_x, table_y, torque:JOINT or force:POINT:x|y");
}

OutputSpec parseOutput(const std::string& text) {
  const auto p = split(text, ':');
  if (p.size() < 2 || p.size() > 3) throw UsageError("--output " + text + ": expected POINT:x|y[:disp|vel|acc|acc_abs]");
  OutputSpec o{text, OutputKind::Acceleration, p[0], axisOf(p[1], "--output " + text), true};
  if (p.size() == 3) {
    if (p[2] == "disp") o = {text, OutputKind::Displacement, p[0], o.axis, false};
    else if (p[2] == "vel") o = {text, OutputKind::Velocity, p[0], o.axis, false};
    else if (p[2] == "acc") o = {text, OutputKind::Acceleration, p[0], o.axis, false};
    else if (p[2] != "acc_abs") throw UsageError("--output " + text + ": kind must be disp, vel, acc or acc_abs");
  }
  return o;
}

LinearModel build(const LinearArgs& args, const ArticleScene& scene) {
  std::vector<InputSpec> in;
  std::vector<OutputSpec> out;
  for (const auto& t : args.inputs) in.push_back(parseInput(t));
  for (const auto& t : args.outputs) out.push_back(parseOutput(t));
  if (in.empty()) in = defaultInputs();
  if (out.empty()) out = defaultOutputs(scene);
  DampingSpec d;
  d.modal_ratio = args.damping_ratio;
  if (scene.damping && !args.damping_given) d = *scene.damping;
  return buildLinearModel(scene, in, out, d);
}

}  // namespace

ReductionOptions reductionOptions(const LinearArgs& args) {
  ReductionOptions o;
  o.modes = args.rom_modes;
  if (!args.band.empty()) {
    const auto b = split(args.band, ':');
    char *e1 = nullptr, *e2 = nullptr;
    if (b.size() != 2) throw UsageError("--band: expected F_MIN_HZ:F_MAX_HZ");
    o.band_min_hz = std::strtod(b[0].c_str(), &e1);
    o.band_max_hz = std::strtod(b[1].c_str(), &e2);
    if (*e1 || *e2 || !(o.band_max_hz > o.band_min_hz) || o.band_min_hz < 0) throw UsageError("--band: expected 0 <= F_MIN_HZ < F_MAX_HZ");
    o.modes = 0;
  }
  o.residualize = !args.no_residualize;
  return o;
}

namespace {

ReducedModel reduce(const LinearArgs& args, const StateSpace& full) { return reduceModal(full, reductionOptions(args)); }

std::vector<double> frequencies(const LinearArgs& a) {
  if (!(a.f_min > 0) || !(a.f_max > a.f_min)) throw UsageError("--from/--to: need 0 < FROM < TO (Hz)");
  return logFrequencies(a.f_min, a.f_max, a.points);
}

std::string safe(std::string s) {
  for (char& c : s)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '.' && c != '_' && c != '-') c = '_';
  return s;
}

std::string summary(const LinearModel& lm, const ReducedModel& red, const ModelError& err, const std::vector<double>& f) {
  std::ostringstream os;
  const StateSpace& s = lm.full;
  os << "Linear model about the equilibrium: " << s.numStates() << " states, " << s.B.cols() << " inputs, " << s.C.rows()
     << " outputs\n";
  os << "Reduced model: " << red.kept_modes << " modes (" << red.model.numStates() << " states), "
     << (red.residualized ? "statically residualized (every DC gain exact)" : "truncated") << "; kept modes (Hz):";
  for (double x : red.kept_frequencies_hz) os << strf(" %.3g", x);
  os << strf("\nLargest FRF error of the reduced model over %g-%g Hz, relative to each pair's peak: %.3g %%\n\n", f.front(),
             f.back(), 100 * err.max_relative);
  Table t({"output", "unit", "input", "unit", "peak_Hz", "peak_dB", "at_10_Hz_dB", "rom_error_%"});
  for (Eigen::Index o = 0; o < s.C.rows(); ++o)
    for (Eigen::Index i = 0; i < s.B.cols(); ++i) {
      auto mag = [&](double hz) { return std::abs(lm.second_order.response(2 * M_PI * hz)(o, i)); };
      std::size_t best = 0;
      std::vector<double> m(f.size());
      for (std::size_t k = 0; k < f.size(); ++k) {
        m[k] = mag(f[k]);
        if (m[k] > m[best]) best = k;
      }
      // Refine the grid's maximum between its neighbours (golden section on |H|), so a
      // coarse grid does not misplace a lightly damped peak.
      double lo = f[best > 0 ? best - 1 : 0], hi = f[std::min(best + 1, f.size() - 1)];
      const double g = 0.5 * (std::sqrt(5.0) - 1);
      for (int it = 0; it < 60 && hi - lo > 1e-9 * hi; ++it) {
        const double a = hi - g * (hi - lo), b = lo + g * (hi - lo);
        (mag(a) > mag(b) ? hi : lo) = mag(a) > mag(b) ? b : a;
      }
      double fpeak = 0.5 * (lo + hi);
      double peak_mag = mag(fpeak);
      if (m[best] > peak_mag) fpeak = f[best], peak_mag = m[best];
      const double peak = 20 * std::log10(peak_mag + 1e-300);
      const double at10 = 20 * std::log10(std::abs(lm.second_order.response(2 * M_PI * 10.0)(o, i)) + 1e-300);
      t.add({s.output_names[o], s.output_units[o], s.input_names[i], s.input_units[i], strf("%.4g", fpeak),
             strf("%.2f", peak), strf("%.2f", at10), strf("%.3g", 100 * err.relative(o, i))});
    }
  os << t.text();
  return os.str();
}

/// The UFF file for a linear model: nodes at the equilibrium's named points, a trace
/// line per link, the first mode shapes, and every FRF (or transmissibility) pair.
std::string uffFor(const LinearModel& lm, const ArticleScene& scene, const std::vector<double>& f,
                   const std::vector<Eigen::MatrixXcd>& h) {
  const Model& model = *lm.solved.model;
  uff::File file;
  file.model_name = scene.name;
  file.description = "mmvlab frf: " + scene.source;
  {
    const std::time_t now = std::time(nullptr);
    std::tm tm{};
    gmtime_r(&now, &tm);
    char d[16], t[16];
    std::strftime(d, sizeof d, "%d-%b-%y", &tm);
    std::strftime(t, sizeof t, "%H:%M:%S", &tm);
    file.date = d;
    for (char& c : file.date) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    file.time = t;
  }
  std::map<std::string, int> label;
  SimTK::State st = lm.solved.equilibrium.state;
  model.getSystem().realize(st, SimTK::Stage::Position);
  for (const auto& p : model.getPoints()) {
    const SimTK::Vec3 x = model.findPointLocation(st, p);
    const int id = static_cast<int>(file.nodes.size()) + 1;
    label[p.name] = id;
    file.nodes.push_back({id, {x[0], x[1], x[2]}});
  }
  int trace = 1;
  for (const auto& l : scene.article.links) {
    uff::TraceLine t{trace++, l.name, {}};
    t.nodes.push_back(label[l.name + ".root"]);
    for (int k = 1; !l.rigid && k <= l.segments; ++k) t.nodes.push_back(label[l.name + ".h" + std::to_string(k)]);
    t.nodes.push_back(label[l.name + ".tip"]);
    file.trace_lines.push_back(t);
  }
  const Eigen::MatrixXd P = pointTranslationMatrix(model, st, lm.solved.linearized.dofs);
  const ModalSolution& modes = lm.solved.modes;
  for (int k = 0; k < std::min<int>(12, static_cast<int>(modes.omega2.size())); ++k) {
    uff::ModeShape m;
    m.mode = k + 1;
    m.frequency_hz = modes.frequencyHz(k);
    m.modal_mass = 1.0;
    const Eigen::VectorXd u = P * modes.shapes.col(k);
    for (std::size_t p = 0; p < model.getPoints().size(); ++p) {
      m.nodes.push_back(static_cast<int>(p) + 1);
      m.translations.push_back({u[2 * p], u[2 * p + 1], 0.0});
    }
    file.modes.push_back(m);
  }
  const StateSpace& s = lm.full;
  const int spec_out[] = {8, 11, 12}, spec_in[] = {12, 0, 13};  // displacement, velocity, acceleration; force
  for (Eigen::Index o = 0; o < s.C.rows(); ++o)
    for (Eigen::Index i = 0; i < s.B.cols(); ++i) {
      const OutputSpec& out = lm.outputs[o];
      const InputSpec& in = lm.inputs[i];
      uff::Function fn;
      const bool transmissibility = in.kind == InputKind::BaseAcceleration && out.kind == OutputKind::Acceleration && out.absolute;
      fn.function_type = transmissibility ? 5 : 4;
      fn.id1 = s.output_names[o] + " / " + s.input_names[i];
      fn.id2 = scene.name;
      fn.response_node = label[out.point];
      fn.response_direction = out.axis + 1;
      fn.reference_node = in.kind == InputKind::PointForce ? label[in.target] : in.kind == InputKind::JointTorque ? label[in.target] : 0;
      fn.reference_direction = in.kind == InputKind::JointTorque ? 6 : in.axis + 1;
      fn.ordinate_type = spec_out[static_cast<int>(out.kind)];
      fn.ordinate_length_exp = 1;
      fn.ordinate_label = s.output_names[o];
      fn.ordinate_units = s.output_units[o];
      fn.denominator_type = spec_in[static_cast<int>(in.kind)];
      fn.denominator_length_exp = in.kind == InputKind::BaseAcceleration ? 1 : in.kind == InputKind::JointTorque ? 1 : 0;
      fn.denominator_force_exp = in.kind == InputKind::BaseAcceleration ? 0 : 1;
      fn.denominator_label = s.input_names[i];
      fn.denominator_units = s.input_units[i];
      for (std::size_t k = 0; k < f.size(); ++k) {
        fn.frequency_hz.push_back(f[k]);
        fn.values.push_back(h[k](o, i));
      }
      file.functions.push_back(fn);
    }
  return uff::write(file);
}

}  // namespace

int runFrfCommand(const LinearArgs& args) {
  return guarded([&]() -> int {
    const Scene loaded = loadScene(args);
    const std::vector<double> f = frequencies(args);
    if (const auto* h = std::get_if<HamsasScene>(&loaded)) return runHamsasFrf(args, *h, f);
    const ArticleScene& scene = std::get<ArticleScene>(loaded);
    if (!args.vary.empty()) throw UsageError("--vary applies to HAM-SAS scenes only");
    std::unique_ptr<OutputDir> out;
    if (!args.out.empty()) out = std::make_unique<OutputDir>(args.out, args.force);
    const LinearModel lm = build(args, scene);
    const ReducedModel red = reduce(args, lm.full);
    std::vector<double> w(f);
    for (double& x : w) x *= 2 * M_PI;
    const ModelError err = compareResponses(lm.full, red.model, w);
    if (out) {
      const StateSpace& s = lm.full;
      std::vector<Eigen::MatrixXcd> hf, hr;
      for (double x : w) {
        hf.push_back(lm.second_order.response(x));
        hr.push_back(red.model.response(x));
      }
      for (Eigen::Index o = 0; o < s.C.rows(); ++o)
        for (Eigen::Index i = 0; i < s.B.cols(); ++i) {
          const std::string base = safe(s.output_names[o]) + "__" + safe(s.input_names[i]);
          std::ostringstream csv;
          csv << "frequency_hz,magnitude_db,phase_deg,magnitude_" << safe(s.output_units[o]) << "_per_"
              << safe(s.input_units[i]) << ",rom_magnitude_db,rom_phase_deg\n";
          render::BodeTrace full{"full model (" + std::to_string(s.numStates()) + " states)"}, rom{
              "reduced (" + std::to_string(red.model.numStates()) + " states)"};
          rom.dashed = true;
          for (std::size_t k = 0; k < f.size(); ++k) {
            const std::complex<double> a = hf[k](o, i), b = hr[k](o, i);
            const double fa = 20 * std::log10(std::abs(a) + 1e-300), fb = 20 * std::log10(std::abs(b) + 1e-300);
            csv << strf("%.8g,%.8g,%.8g,%.8g,%.8g,%.8g\n", f[k], fa, std::arg(a) * 180 / M_PI, std::abs(a), fb,
                        std::arg(b) * 180 / M_PI);
            const double x = args.rad ? w[k] : f[k];
            full.frequency.push_back(x);
            full.magnitude_db.push_back(fa);
            full.phase_deg.push_back(std::arg(a) * 180 / M_PI);
            rom.frequency.push_back(x);
            rom.magnitude_db.push_back(fb);
            rom.phase_deg.push_back(std::arg(b) * 180 / M_PI);
          }
          std::ofstream(out->stage("frf_" + base + ".csv"), std::ios::binary) << csv.str();
          try {
            render::writeBodePng(out->stage("bode_" + base + ".png"), {full, rom},
                                 s.output_names[o] + " / " + s.input_names[i] + " (" + s.output_units[o] + " per " +
                                     s.input_units[i] + ")",
                                 args.rad ? "frequency (rad/s)" : "frequency (Hz)");
          } catch (const std::runtime_error& e) {
            throw OutputError(e.what());
          }
        }
      std::ofstream(out->stage("frf.uff"), std::ios::binary) << uffFor(lm, scene, f, hf);
      for (const auto& path : out->commit()) std::cerr << "mmvlab: wrote " << path << '\n';
    }
    std::cout << summary(lm, red, err, f) << std::flush;
    return kOk;
  });
}

int runRomCommand(const LinearArgs& args) {
  return guarded([&]() -> int {
    if (args.out.empty()) throw UsageError("rom: --out DIR is required (it writes rom.mat and full.mat)");
    const Scene loaded = loadScene(args);
    const std::vector<double> f = frequencies(args);
    if (const auto* h = std::get_if<HamsasScene>(&loaded)) return runHamsasRom(args, *h, f);
    const ArticleScene& scene = std::get<ArticleScene>(loaded);
    OutputDir out(args.out, args.force);
    const LinearModel lm = build(args, scene);
    const ReducedModel red = reduce(args, lm.full);
    std::vector<double> w(f);
    for (double& x : w) x *= 2 * M_PI;
    const ModelError err = compareResponses(lm.full, red.model, w);
    try {
      writeStateSpaceMat(out.stage("rom.mat"), red.model);
      writeStateSpaceMat(out.stage("full.mat"), lm.full);
    } catch (const std::runtime_error& e) {
      throw OutputError(e.what());
    }
    nlohmann::ordered_json j;
    j["mmvlab_version"] = mmvlabVersion();
    j["command"] = "rom";
    j["full_states"] = lm.full.numStates();
    j["reduced_states"] = red.model.numStates();
    j["kept_modes"] = red.kept_modes;
    j["kept_frequencies_hz"] = red.kept_frequencies_hz;
    j["residualized"] = red.residualized;
    j["band_hz"] = {f.front(), f.back()};
    j["max_relative_frf_error"] = err.max_relative;
    j["inputs"] = lm.full.input_names;
    j["input_units"] = lm.full.input_units;
    j["outputs"] = lm.full.output_names;
    j["output_units"] = lm.full.output_units;
    std::ofstream(out.stage("rom.json"), std::ios::binary) << j.dump(2) << '\n';
    for (const auto& path : out.commit()) std::cerr << "mmvlab: wrote " << path << '\n';
    std::cout << summary(lm, red, err, f) << std::flush;
    return kOk;
  });
}

}  // namespace mmv::cli
