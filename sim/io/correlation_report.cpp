#include "sim/io/correlation_report.hpp"

#include <cmath>
#include <sstream>

#include "sim/core/text.hpp"
#include "sim/io/report.hpp"
#include "sim/modes/tam.hpp"

namespace mmv {

MeasuredSet measuredSet(const uff::File& file, const std::string& source) {
  MeasuredSet m;
  m.source = source;
  for (const auto& n : file.nodes) m.nodes.push_back({n.label, n.xyz});
  for (const auto& s : file.modes) {
    MeasuredMode t{s.mode, s.frequency_hz, s.damping_ratio, s.nodes, {}};
    for (std::size_t k = 0; k < s.translations.size(); ++k) {
      std::array<std::complex<double>, 3> v;
      for (int d = 0; d < 3; ++d) v[d] = {s.translations[k][d], s.translations_imag.empty() ? 0.0 : s.translations_imag[k][d]};
      t.shape.push_back(v);
    }
    m.modes.push_back(t);
  }
  for (const auto& f : file.functions)
    m.frfs.push_back({f.id1, f.line, f.function_type, f.response_node, f.response_direction, f.reference_node,
                      f.reference_direction, f.ordinate_type, f.denominator_type, f.frequency_hz, f.values});
  return m;
}

std::string modeLabel(char prefix, int number, double frequency_hz) {
  return strf("%c%d %.4g Hz", prefix, number, frequency_hz);
}

namespace {

std::string percent(double x) { return strf("%.3g", 100 * x); }

}  // namespace

std::string correlationText(const ArticleScene& scene, const CorrelationResult& r) {
  std::ostringstream os;
  os << "Test-analysis correlation: " << scene.name << " against the measured set\n";
  int paired = 0;
  for (const auto& n : r.nodes) paired += !n.station.empty();
  os << strf("Points: %d of %zu measured nodes on the article\n", paired, r.nodes.size());
  Table nodes({"node", "x_m", "y_m", "z_m", "station", "distance_mm", "by"});
  for (const auto& n : r.nodes)
    nodes.add({std::to_string(n.node), strf("%.4f", n.xyz[0]), strf("%.4f", n.xyz[1]), strf("%.4f", n.xyz[2]),
               n.station.empty() ? "-" : n.station, strf("%.2f", 1e3 * n.distance_m), n.by_name ? "name" : n.by_number ? "number" : "position"});
  os << nodes.text();
  os << strf("\nModes: %zu measured, %zu of the model (damping: %s); test band %.4g-%.4g Hz; MAC over %d translations\n",
             r.test_modes.size(), r.model_modes.size(), r.model_damped ? r.damping_model.c_str() : "none in the scene",
             r.band_min_hz, r.band_max_hz, r.shape_dofs);
  // The table's cells are the pair fields' values (correlationPairFields), in the text's units.
  Table pairs({"test", "test_Hz", "test_zeta_%", "model", "model_Hz", "model_zeta_%", "freq_error_%", "MAC"});
  for (const auto& p : correlationPairRows(r)) {
    const auto value = [&p](const char* key) { return fieldValue(correlationPairFields(), p, key); };
    const auto ratio = [&value](const char* key) {
      const auto v = value(key);
      return v && v->is_number() ? percent(v->get<double>()) : std::string("-");
    };
    pairs.add({value("test")->get<std::string>(), strf("%.4f", value("test_hz")->get<double>()), ratio("test_damping_ratio"),
               value("model")->get<std::string>(), strf("%.4f", value("model_hz")->get<double>()),
               ratio("model_damping_ratio"), strf("%+.2f", 100 * value("frequency_error")->get<double>()),
               strf("%.3f", value("mac")->get<double>())});
  }
  if (!pairs.empty()) os << pairs.text();
  else os << "  no test mode pairs with a model mode at the MAC threshold\n";
  for (int j : r.model_not_seen)
    os << strf("  model mode M%d (%.4f Hz) is in the test band but no test mode pairs with it: not seen by the test\n",
               r.model_modes[j].number.number(), r.model_modes[j].frequency_hz);
  for (int i : r.test_not_predicted)
    os << strf("  test mode T%d (%.4f Hz) pairs with no model mode: not predicted by the model\n", i + 1,
               r.test_modes[i].frequency_hz);
  if (!r.frfs.empty()) {
    os << strf("\nFrequency responses: FRAC of the model's against each measured one (1: the same response; at or above "
               "%.2g: consistent, below: differs, in level, phase or a peak's frequency; a 1 %% shift of a lightly damped "
               "peak alone can halve it: see the Bode overlays)\n",
               kFracThreshold);
    Table t({"function", "id", "output", "input", "FRAC", "verdict", "test_peak_Hz", "model_peak_Hz"});
    for (const auto& f : r.frfs)
      if (f.skipped.empty())
        t.add({std::to_string(f.index + 1), f.id.empty() ? "-" : f.id, f.output, f.input, strf("%.4f", f.frac),
               f.frac >= kFracThreshold ? "consistent" : "differs", strf("%.4g", f.test_peak_hz), strf("%.4g", f.model_peak_hz)});
    os << t.text();
    for (const auto& f : r.frfs)
      if (!f.skipped.empty()) os << strf("  function %d (%s) not modelled: %s\n", f.index + 1, f.id.c_str(), f.skipped.c_str());
  }
  for (const auto& n : r.notes) os << "note: " << n << '\n';
  for (const auto& w : r.warnings) os << "warning: " << w << '\n';
  return os.str();
}

nlohmann::ordered_json correlationJson(const ArticleScene& scene, const CorrelationResult& r) {
  using json = nlohmann::ordered_json;
  json j;
  j["mmvlab_version"] = mmvlabVersion();
  j["command"] = "correlate";
  j["scene"] = {{"name", scene.name}, {"source", scene.source}};
  json nodes = json::array();
  for (const auto& n : r.nodes) {
    json nj = {{"node", n.node}, {"xyz_m", n.xyz}, {"distance_m", n.distance_m}, {"by_name", n.by_name}, {"by_number", n.by_number}};
    nj["station"] = n.station.empty() ? json(nullptr) : json(n.station);
    nodes.push_back(nj);
  }
  j["nodes"] = nodes;
  j["band_hz"] = {r.band_min_hz, r.band_max_hz};
  j["damping_model"] = r.model_damped ? r.damping_model : "none";
  json tm = json::array(), mm = json::array();
  for (std::size_t i = 0; i < r.test_modes.size(); ++i)
    tm.push_back({{"label", strf("T%zu", i + 1)}, {"file_mode_number", r.test_modes[i].number},
                  {"frequency_hz", r.test_modes[i].frequency_hz}, {"damping_ratio", r.test_modes[i].damping_ratio}});
  for (const auto& m : r.model_modes) {
    json x = {{"label", strf("M%d", m.number.number())}, {"frequency_hz", m.stable ? json(m.frequency_hz) : json(nullptr)},
              {"rigid_body", m.rigid_body}};
    if (r.model_damped && m.stable && !m.rigid_body && m.has_damping) x["damping_ratio"] = m.damping_ratio;
    mm.push_back(x);
  }
  j["test_modes"] = tm;
  j["model_modes"] = mm;
  json mac = json::array();
  for (Eigen::Index i = 0; i < r.mac.rows(); ++i) {
    json row = json::array();
    for (Eigen::Index k = 0; k < r.mac.cols(); ++k) row.push_back(std::isnan(r.mac(i, k)) ? json(nullptr) : json(r.mac(i, k)));
    mac.push_back(row);  // null: undefined (a shape zero at the paired points)
  }
  j["mac"] = mac;
  j["mac_translations"] = r.shape_dofs;
  json pairs = json::array();
  for (const auto& p : correlationPairRows(r))
    pairs.push_back(fieldsJson(correlationPairFields(), p, [](const auto&) { return true; }));
  j["pairs"] = pairs;
  json seen = json::array(), unpredicted = json::array();
  for (int k : r.model_not_seen) seen.push_back(strf("M%d", r.model_modes[k].number.number()));
  for (int k : r.test_not_predicted) unpredicted.push_back(strf("T%d", k + 1));
  j["model_modes_not_seen"] = seen;
  j["test_modes_not_predicted"] = unpredicted;
  json frfs = json::array();
  for (const auto& f : r.frfs) {
    json x = {{"function", f.index + 1}, {"id", f.id}};
    if (f.skipped.empty()) {
      x["output"] = f.output;
      x["input"] = f.input;
      x["frac"] = f.frac;
      x["frac_threshold"] = kFracThreshold;
      x["frac_verdict"] = f.frac >= kFracThreshold ? "consistent" : "differs";
      x["test_peak_hz"] = f.test_peak_hz;
      x["model_peak_hz"] = f.model_peak_hz;
    } else {
      x["skipped"] = f.skipped;
    }
    frfs.push_back(x);
  }
  j["frfs"] = frfs;
  j["warnings"] = r.warnings;
  j["notes"] = r.notes;
  return j;
}

std::string macCsv(const CorrelationResult& r) {
  std::ostringstream os;
  os << "test_mode,test_frequency_hz,model_mode,model_frequency_hz,mac\n";
  for (Eigen::Index i = 0; i < r.mac.rows(); ++i)
    for (Eigen::Index k = 0; k < r.mac.cols(); ++k)
      os << "T" << i + 1 << ',' << strf("%.8g", r.test_modes[i].frequency_hz) << ",M" << r.model_modes[k].number << ','
         << strf("%.8g", r.model_modes[k].frequency_hz) << ','
         << (std::isnan(r.mac(i, k)) ? std::string() : strf("%.6f", r.mac(i, k))) << '\n';  // empty: undefined
  return os.str();
}

std::vector<CorrelationPairRow> correlationPairRows(const CorrelationResult& r) {
  std::vector<CorrelationPairRow> rows;
  for (const auto& p : r.pairs) {
    const MeasuredMode& t = r.test_modes[p.test];
    const ModeInfo& m = r.model_modes[p.model];
    CorrelationPairRow row;
    row.test = strf("T%d", p.test + 1);
    row.model = strf("M%d", m.number.number());
    row.test_hz = t.frequency_hz;
    row.model_hz = m.frequency_hz;
    row.mac = p.mac;
    row.test_damping_ratio = t.damping_ratio;
    if (r.model_damped && m.has_damping) row.model_damping_ratio = m.damping_ratio;
    rows.push_back(row);
  }
  return rows;
}

const std::vector<Field<CorrelationPairRow>>& correlationPairFields() {
  using json = nlohmann::ordered_json;
  using Opt = std::optional<json>;
  using Row = CorrelationPairRow;
  // clang-format off
  static const std::vector<Field<Row>> fields{
      {"test", "", "%s", "the test mode (T1 is the measured set's first)", [](const Row& r) -> Opt { return json(r.test); }},
      {"model", "", "%s", "the model mode it pairs with (M1 is the lowest)", [](const Row& r) -> Opt { return json(r.model); }},
      {"test_hz", "Hz", "%.8g", "the test mode's frequency", [](const Row& r) -> Opt { return json(r.test_hz); }},
      {"model_hz", "Hz", "%.8g", "the model mode's frequency", [](const Row& r) -> Opt { return json(r.model_hz); }},
      {"frequency_error", "1", "%.6g", "model_hz / test_hz - 1",
       [](const Row& r) -> Opt { return json((r.model_hz - r.test_hz) / r.test_hz); }},
      {"mac", "1", "%.6f", "the modal assurance criterion of the two shapes over the paired points",
       [](const Row& r) -> Opt { return json(r.mac); }},
      {"test_damping_ratio", "1", "%.6g", "the test mode's damping ratio, as measured",
       [](const Row& r) -> Opt { return json(r.test_damping_ratio); }},
      {"model_damping_ratio", "1", "%.6g", "the model mode's damping ratio (null: the model is undamped)",
       [](const Row& r) -> Opt { return r.model_damping_ratio ? json(*r.model_damping_ratio) : json(nullptr); }},
  };
  // clang-format on
  return fields;
}

std::string correlationPairsCsv(const CorrelationResult& r) {
  return fieldsCsv(correlationPairFields(), correlationPairRows(r), [](const auto&) { return true; });
}

nlohmann::ordered_json testOrthogonalityJson(const TestOrthogonality& t) {
  nlohmann::ordered_json j;
  j["tam"] = t.source;
  j["method"] = t.method;
  j["channels"] = t.channels;
  j["criterion_off_diagonal_max"] = kTamOffDiagonalMax;
  j["pass"] = t.all_pass;
  j["modes"] = nlohmann::ordered_json::array();
  for (std::size_t i = 0; i < t.modes.size(); ++i)
    j["modes"].push_back({{"test_mode", t.modes[i]},
                          {"frequency_hz", t.frequencies_hz[i]},
                          {"max_off_diagonal", t.max_off_diagonal[i]},
                          {"pass", t.pass[i] != 0}});
  nlohmann::ordered_json rows = nlohmann::ordered_json::array();
  for (Eigen::Index i = 0; i < t.matrix.rows(); ++i) {
    nlohmann::ordered_json row = nlohmann::ordered_json::array();
    for (Eigen::Index k = 0; k < t.matrix.cols(); ++k) row.push_back(t.matrix(i, k));
    rows.push_back(row);
  }
  j["matrix"] = rows;
  j["left_out"] = t.left_out;
  return j;
}

std::string testOrthogonalityText(const TestOrthogonality& t) {
  int failing = 0;
  for (char p : t.pass) failing += !p;
  std::string out = strf("\nTest orthogonality under the %s TAM of %s (%d channels; criterion: off-diagonal <= %.1f): %s\n",
                         t.method.c_str(), t.source.c_str(), t.channels, kTamOffDiagonalMax,
                         t.all_pass ? "every measured mode passes" : strf("%d of %zu measured modes FAIL", failing, t.modes.size()).c_str());
  Table table({"test_mode", "f_Hz", "max_off_diagonal", "verdict"});
  for (std::size_t i = 0; i < t.modes.size(); ++i)
    table.add({std::to_string(t.modes[i]), strf("%.4f", t.frequencies_hz[i]), strf("%.3f", t.max_off_diagonal[i]), t.pass[i] ? "pass" : "FAIL"});
  out += table.text();
  for (const auto& l : t.left_out) out += "  left out: " + l + "\n";
  return out;
}

}  // namespace mmv
