#include "sim/io/linear_report.hpp"

#include <cmath>
#include <ctime>
#include <map>
#include <optional>
#include <sstream>

#include "sim/core/errors.hpp"
#include "sim/core/text.hpp"
#include "sim/model/stations.hpp"
#include "sim/io/report.hpp"
#include "sim/io/uff.hpp"
#include "sim/modes/damping.hpp"

namespace mmv {


std::string safeFileName(std::string s) {
  for (char& c : s)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '.' && c != '_' && c != '-') c = '_';
  return s;
}

std::string localErrorLine(const ModelError& err, const std::vector<std::string>& outputs,
                           const std::vector<std::string>& inputs) {
  const auto [o, i] = err.max_local_pair;
  if (err.local.size() == 0) return "";
  return strf("Largest local FRF error, relative to the full response at the same frequency: %.3g %% at %.4g Hz (%s / %s)\n",
              100 * err.max_local, err.max_local_hz, outputs[o].c_str(), inputs[i].c_str());
}

std::string modesNeededLine(const ModelError& err) {
  const auto& n = err.needed;
  if (!n.computed) return "";
  if (!n.reached)
    return strf("Modes a reduced model needs for %.3g %% of each pair's peak: more than %d (%.3g %% with %d)\n",
                100 * n.target, n.modes, 100 * n.error, n.modes);
  return strf("Modes a reduced model needs for %.3g %% of each pair's peak: %d (%.3g %%)\n", 100 * n.target, n.modes,
              100 * n.error);
}

void addModesNeeded(nlohmann::ordered_json& j, const ModelError& err) {
  const auto& n = err.needed;
  if (!n.computed) return;
  j["modes_for_target"] = {{"target", n.target}, {"reached", n.reached}, {"modes", n.modes}, {"error", n.error}};
}

void addLocalError(nlohmann::ordered_json& j, const ModelError& err, const std::vector<std::string>& outputs,
                   const std::vector<std::string>& inputs) {
  addModesNeeded(j, err);
  if (err.local.size() == 0) return;
  const auto [o, i] = err.max_local_pair;
  j["max_local_relative_frf_error"] = err.max_local;
  j["max_local_error_hz"] = err.max_local_hz;
  j["max_local_error_pair"] = {outputs[o], inputs[i]};
}

std::string linearSummaryText(const LinearModel& lm, const ReducedModel& red, const ModelError& err, const std::vector<double>& f,
                              const std::vector<Eigen::MatrixXcd>& hf) {
  std::ostringstream os;
  const StateSpace& s = lm.full;
  os << "Linear model about the equilibrium: " << s.numStates() << " states, " << s.B.cols() << " inputs, " << s.C.rows()
     << " outputs\n";
  os << "Reduced model: " << red.kept_modes << " modes (" << red.model.numStates() << " states), "
     << (red.residualized ? "statically residualized (every DC gain exact)" : "truncated") << "; kept modes (Hz):";
  for (double x : red.kept_frequencies_hz) os << strf(" %.3g", x);
  os << "\nDamping: " << describeDamping(lm.damping) << "; kept modes' ratios (%):";
  for (double z : red.kept_damping) os << strf(" %.3g", 100 * z);
  os << strf("\nLargest FRF error of the reduced model over %g-%g Hz, relative to each pair's peak: %.3g %%\n", f.front(),
             f.back(), 100 * err.max_relative);
  os << localErrorLine(err, s.output_names, s.input_names) << modesNeededLine(err) << "\n";
  os << "peak_zeta_%: the largest peak's half-power damping, (f2 - f1) / (2 f_peak) ('-': its half-power points are not both in the band)\n";
  if (err.zero.any())
    os << "zero pair: the full response stays below 1e-9 of the largest over the band (round-off; decoupled by symmetry)\n";
  Table t({"output", "unit", "input", "unit", "peak_Hz", "peak_dB", "peak_zeta_%", "at_10_Hz_dB", "rom_error_%", "rom_local_%",
           "local_at_Hz"});
  const PeakTable peaks = refinedPeaks(lm.second_order, f, hf);
  const Eigen::MatrixXcd h10 = lm.second_order.response(2 * M_PI * 10.0);
  for (Eigen::Index o = 0; o < s.C.rows(); ++o)
    for (Eigen::Index i = 0; i < s.B.cols(); ++i) {
      const double fpeak = peaks.hz(o, i);
      const double peak = 20 * std::log10(peaks.magnitude(o, i) + 1e-300);
      const double at10 = 20 * std::log10(std::abs(h10(o, i)) + 1e-300);
      const double zeta = peaks.half_power_damping(o, i);
      if (err.zero(o, i)) {  // round-off only: no peak, no error to speak of
        t.add({s.output_names[o], s.output_units[o], s.input_names[i], s.input_units[i], "-", strf("%.2f", peak), "-",
               strf("%.2f", at10), "zero pair", "-", "-"});
        continue;
      }
      t.add({s.output_names[o], s.output_units[o], s.input_names[i], s.input_units[i], strf("%.4g", fpeak),
             strf("%.2f", peak), zeta > 0 ? strf("%.3g", 100 * zeta) : "-", strf("%.2f", at10), strf("%.3g", 100 * err.relative(o, i)),
             strf("%.3g", 100 * err.local(o, i)), strf("%.4g", err.local_hz(o, i))});
    }
  os << t.text();
  return os.str();
}

nlohmann::ordered_json linearSummaryJson(const LinearModel& lm, const ReducedModel& red, const ModelError& err,
                                         const std::vector<double>& f, const std::vector<Eigen::MatrixXcd>& hf,
                                         const std::string& scene_name) {
  using json = nlohmann::ordered_json;
  const StateSpace& s = lm.full;
  json j;
  j["mmvlab_version"] = mmvlabVersion();
  j["command"] = "frf";
  j["scene"] = scene_name;
  j["full_states"] = s.numStates();
  j["reduced_states"] = red.model.numStates();
  j["kept_frequencies_hz"] = red.kept_frequencies_hz;
  j["kept_damping_ratios"] = red.kept_damping;
  j["damping_model"] = describeDamping(lm.damping);
  j["band_hz"] = {f.front(), f.back()};
  j["max_relative_frf_error"] = err.max_relative;
  addLocalError(j, err, s.output_names, s.input_names);
  const PeakTable peaks = refinedPeaks(lm.second_order, f, hf);
  const Eigen::MatrixXcd h10 = lm.second_order.response(2 * M_PI * 10.0);
  json pairs = json::array();
  for (Eigen::Index o = 0; o < s.C.rows(); ++o)
    for (Eigen::Index i = 0; i < s.B.cols(); ++i) {
      const double zeta = peaks.half_power_damping(o, i);
      pairs.push_back({{"output", s.output_names[o]},
                       {"output_unit", s.output_units[o]},
                       {"input", s.input_names[i]},
                       {"input_unit", s.input_units[i]},
                       {"peak_hz", peaks.hz(o, i)},
                       {"peak_db", 20 * std::log10(peaks.magnitude(o, i) + 1e-300)},
                       {"peak_half_power_damping", zeta > 0 ? json(zeta) : json(nullptr)},
                       {"at_10_hz_db", 20 * std::log10(std::abs(h10(o, i)) + 1e-300)},
                       {"rom_relative_error", err.relative(o, i)},
                       {"rom_local_error", err.local(o, i)},
                       {"rom_local_error_hz", err.local_hz(o, i)},
                       {"zero_pair", static_cast<bool>(err.zero(o, i))}});
    }
  j["pairs"] = pairs;
  return j;
}

namespace {


/// A force along a direction (the shaker) in UFF's terms: +-1..3 along a world axis, else
/// 0 (a direction UFF cannot name without a local coordinate system).
int shakerDirection(const InputSpec& in) {
  for (int a = 0; a < 3; ++a)
    if (std::abs(std::abs(in.direction[static_cast<std::size_t>(a)]) - 1) < 1e-12) return in.direction[static_cast<std::size_t>(a)] > 0 ? a + 1 : -(a + 1);
  return 0;
}

/// One dataset 58 per output-input pair: FRF (type 4) or transmissibility (type 5).
void addFunctions(const LinearModel& lm, const ArticleScene& scene, const std::vector<double>& f,
                  const std::vector<Eigen::MatrixXcd>& h, std::map<std::string, int>& label, uff::File& file) {
  const StateSpace& s = lm.full;
  // displacement, velocity, acceleration; table acceleration, joint torque, force, moment
  const int spec_out[] = {8, 11, 12}, spec_in[] = {12, 0, 13, 13};
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
      const bool scalar = out.isStrain() || out.isStress();
      fn.response_direction = scalar ? 0 : out.axis + 1;  // a strain (a stress) is a scalar at its span's start (its station)
      // The table's acceleration is referred to the base node, which the file defines.
      fn.reference_node = in.kind == InputKind::BaseAcceleration ? label.at(kBaseNode) : label.at(in.target);
      fn.reference_direction = in.kind == InputKind::JointTorque ? 6 : in.axis >= 0 ? in.axis + 1 : shakerDirection(in);
      fn.ordinate_type = out.isStrain() ? 3 : out.isStress() ? 2 : spec_out[static_cast<int>(out.kind)];  // 3: strain, 2: stress
      fn.ordinate_length_exp = out.isStress() ? -2 : isRotationAxis(out.axis) ? 0 : 1;  // Pa: force / length^2; rad, m/m: no length
      if (out.isStress()) fn.ordinate_force_exp = 1;
      fn.ordinate_label = s.output_names[o];
      fn.ordinate_units = s.output_units[o];
      fn.denominator_type = spec_in[static_cast<int>(in.kind)];
      fn.denominator_length_exp =
          in.kind == InputKind::BaseAcceleration || in.kind == InputKind::JointTorque || in.kind == InputKind::PointMoment ? 1 : 0;
      fn.denominator_force_exp = in.kind == InputKind::BaseAcceleration ? 0 : 1;
      fn.denominator_label = s.input_names[i];
      fn.denominator_units = s.input_units[i];
      for (std::size_t k = 0; k < f.size(); ++k) {
        fn.frequency_hz.push_back(f[k]);
        fn.values.push_back(h[k](o, i));
      }
      file.functions.push_back(fn);
    }
}

}  // namespace

/// The UFF file for a linear model: its test geometry (nodes, a trace line per link, the
/// first mode shapes) and every FRF (or transmissibility) pair.
std::string frfUff(const LinearModel& lm, const TestGeometry& g, const ArticleScene& scene, const std::vector<double>& f,
                   const std::vector<Eigen::MatrixXcd>& h) {
  uff::File file;
  file.model_name = scene.name;
  file.description = "mmvlab frf: " + scene.source;
  uff::stampNow(file);
  for (const auto& n : g.nodes) file.nodes.push_back({n.id, n.xyz});
  for (const auto& t : g.traces) file.trace_lines.push_back({t.id, t.name, t.nodes});
  for (const auto& s : g.modes) {
    uff::ModeShape m;
    m.mode = s.mode.number();
    m.frequency_hz = s.frequency_hz;
    m.modal_mass = 1.0;
    m.damping_ratio = s.damping_ratio;
    for (std::size_t p = 0; p < s.translation.size(); ++p) m.nodes.push_back(static_cast<int>(p) + 1);
    m.translations = s.translation;
    m.rotations = s.rotation;
    file.modes.push_back(m);
  }
  std::map<std::string, int> label = g.id_of;
  addFunctions(lm, scene, f, h, label, file);
  return uff::write(file);
}

std::string frfCsv(const StateSpace& s, Eigen::Index o, Eigen::Index i, const std::vector<double>& f,
                   const std::vector<Eigen::MatrixXcd>& full, const std::vector<Eigen::MatrixXcd>& reduced) {
  std::ostringstream csv;
  // The magnitude in the pair's units: "magnitude_ratio" for m/s^2 per m/s^2, else
  // "magnitude_m_s2_per_n" (output unit per input unit).
  const std::string unit = s.output_units[o] == s.input_units[i]
                               ? "ratio"
                               : unitSlug(s.output_units[o]) + "_per_" + unitSlug(s.input_units[i]);
  csv << "frequency_hz,magnitude_db,phase_deg,magnitude_" << unit << ",rom_magnitude_db,rom_phase_deg\n";
  for (std::size_t k = 0; k < f.size(); ++k) {
    const std::complex<double> a = full[k](o, i), b = reduced[k](o, i);
    const double fa = 20 * std::log10(std::abs(a) + 1e-300), fb = 20 * std::log10(std::abs(b) + 1e-300);
    csv << strf("%.8g,%.8g,%.8g,%.8g,%.8g,%.8g\n", f[k], fa, std::arg(a) * 180 / M_PI, std::abs(a), fb,
                std::arg(b) * 180 / M_PI);
  }
  return csv.str();
}

nlohmann::ordered_json romJson(const LinearModel& lm, const ReducedModel& red, const ModelError& err,
                               const std::vector<double>& f) {
  nlohmann::ordered_json j;
  j["mmvlab_version"] = mmvlabVersion();
  j["command"] = "rom";
  j["full_states"] = lm.full.numStates();
  j["reduced_states"] = red.model.numStates();
  j["kept_modes"] = red.kept_modes;
  j["kept_frequencies_hz"] = red.kept_frequencies_hz;
  j["kept_damping_ratios"] = red.kept_damping;
  j["damping_model"] = describeDamping(lm.damping);
  j["state_names"] = red.model.state_names;
  j["residualized"] = red.residualized;
  j["band_hz"] = {f.front(), f.back()};
  j["max_relative_frf_error"] = err.max_relative;
  addLocalError(j, err, lm.full.output_names, lm.full.input_names);
  j["inputs"] = lm.full.input_names;
  j["input_units"] = lm.full.input_units;
  j["outputs"] = lm.full.output_names;
  j["output_units"] = lm.full.output_units;
  return j;
}

}  // namespace mmv
