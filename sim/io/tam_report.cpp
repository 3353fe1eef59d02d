#include "sim/io/tam_report.hpp"

#include <sstream>

#include "sim/core/text.hpp"

namespace mmv {

namespace {
using json = nlohmann::ordered_json;
using Opt = std::optional<json>;
const TamModeCheck& check(const TamModeRow& r) { return r.tam->modes[r.j]; }

json matrix(const Eigen::MatrixXd& m) {
  json rows = json::array();
  for (Eigen::Index i = 0; i < m.rows(); ++i) {
    json row = json::array();
    for (Eigen::Index k = 0; k < m.cols(); ++k) row.push_back(m(i, k));
    rows.push_back(row);
  }
  return rows;
}
}  // namespace

std::vector<TamModeRow> tamModeRows(const PlacementStudy& s) {
  std::vector<TamModeRow> rows;
  for (const auto& t : s.tams)
    for (std::size_t j = 0; j < t.modes.size(); ++j) rows.push_back({&t, j, s.target_modes[j], s.target_frequencies_hz[j]});
  return rows;
}

const std::vector<Field<TamModeRow>>& tamModeFields() {
  using R = TamModeRow;
  // clang-format off
  static const std::vector<Field<R>> fields{
      {"method", "", "%s", "the reduction: guyan (static), irs or serep", [](const R& r) -> Opt { return json(tamMethodName(r.tam->method)); }},
      {"mode", "", "%d", "the target mode of the full model", [](const R& r) -> Opt { return json(r.mode.number()); }},
      {"frequency_hz", "Hz", "%.8g", "its frequency", [](const R& r) -> Opt { return json(r.frequency_hz); }},
      {"tam_mode", "", "%d", "the TAM mode it pairs with (largest cross-orthogonality)",
       [](const R& r) -> Opt { return json(check(r).tam_mode); }},
      {"tam_frequency_hz", "Hz", "%.8g", "that TAM mode's frequency", [](const R& r) -> Opt { return json(check(r).tam_frequency_hz); }},
      {"frequency_error", "1", "%.6g", "tam_frequency_hz / frequency_hz - 1", [](const R& r) -> Opt { return json(check(r).frequency_error); }},
      {"self_diagonal", "1", "%.6f", "phi_a^T M_tam phi_a of the mass-normalised mode (1: the TAM carries its whole mass)",
       [](const R& r) -> Opt { return json(check(r).self_diagonal); }},
      {"self_off_diagonal", "1", "%.6f", "its largest normalised self-orthogonality with another target (criterion <= 0.1)",
       [](const R& r) -> Opt { return json(check(r).self_off_diagonal); }},
      {"cross_diagonal", "1", "%.6f", "|cross-orthogonality| with its TAM mode (criterion >= 0.9)",
       [](const R& r) -> Opt { return json(check(r).cross_diagonal); }},
      {"cross_off_diagonal", "1", "%.6f", "its TAM mode's largest |cross-orthogonality| with another target (criterion <= 0.1)",
       [](const R& r) -> Opt { return json(check(r).cross_off_diagonal); }},
      {"pass", "", "%d", "every criterion met", [](const R& r) -> Opt { return json(check(r).pass); }},
      {"reason", "", "%s", "the first criterion it fails (empty: passes)", [](const R& r) -> Opt { return json(check(r).reason); }},
  };
  // clang-format on
  return fields;
}

json tamJson(const PlacementStudy& s) {
  json j;
  j["channels"] = s.channels;
  j["criteria"] = {{"cross_diagonal_min", kTamDiagonalMin}, {"off_diagonal_max", kTamOffDiagonalMax},
                   {"source", "NASA-STD-5002, MIL-HDBK-340A"}};
  j["models"] = json::array();
  const std::vector<TamModeRow> rows = tamModeRows(s);
  const auto record = [](const auto& f) { return std::string(f.key) != "method"; };  // the rows sit under it
  for (const auto& t : s.tams) {
    json m = {{"method", tamMethodName(t.method)}, {"sensors", t.sensors}, {"coordinates", t.coordinates}, {"pass", t.pass}};
    m["modes"] = json::array();
    for (const auto& r : rows)
      if (r.tam == &t) m["modes"].push_back(fieldsJson(tamModeFields(), r, record));
    m["self_orthogonality"] = matrix(t.self);
    m["cross_orthogonality"] = matrix(t.cross);
    j["models"].push_back(m);
  }
  return j;
}

std::string tamText(const PlacementStudy& s) {
  if (s.tams.empty()) return "";
  std::ostringstream os;
  os << strf("\nTest-analysis models on the %zu chosen sensor directions (criteria, NASA-STD-5002: cross-orthogonality "
             "diagonal >= %.1f, off-diagonal and self-orthogonality <= %.1f)\n",
             s.channels.size(), kTamDiagonalMin, kTamOffDiagonalMax);
  const std::vector<TamModeRow> rows = tamModeRows(s);
  for (const auto& t : s.tams) {
    Table table({"mode", "f_Hz", "tam_mode", "tam_Hz", "err_%", "self_diag", "self_off", "cross_diag", "cross_off", "verdict"});
    int failing = 0;
    for (const auto& r : rows) {
      if (r.tam != &t) continue;
      const json rec = fieldsJson(tamModeFields(), r, [](const auto&) { return true; });
      failing += !rec["pass"].get<bool>();
      table.add({std::to_string(rec["mode"].get<int>()), strf("%.4f", rec["frequency_hz"].get<double>()),
                 std::to_string(rec["tam_mode"].get<int>()), strf("%.4f", rec["tam_frequency_hz"].get<double>()),
                 strf("%+.3f", 100 * rec["frequency_error"].get<double>()), strf("%.3f", rec["self_diagonal"].get<double>()),
                 strf("%.3f", rec["self_off_diagonal"].get<double>()), strf("%.3f", rec["cross_diagonal"].get<double>()),
                 strf("%.3f", rec["cross_off_diagonal"].get<double>()),
                 rec["pass"].get<bool>() ? "pass" : "FAIL: " + rec["reason"].get<std::string>()});
    }
    os << strf("%s (%d readings, %d coordinates): %s\n", tamMethodName(t.method), t.sensors, t.coordinates,
               t.pass ? "every target mode passes" : strf("%d of %zu target modes FAIL", failing, t.modes.size()).c_str())
       << table.text();
  }
  return os.str();
}

std::string tamCsv(const PlacementStudy& s) {
  return fieldsCsv(tamModeFields(), tamModeRows(s), [](const auto&) { return true; });
}

MatContents tamMat(const PlacementStudy& s) {
  MatContents c;
  std::vector<std::string> methods;
  for (const auto& t : s.tams) {
    const std::string m = tamMethodName(t.method);
    methods.push_back(m);
    c.matrices.emplace_back("M_" + m, t.M_tam);
    c.matrices.emplace_back("K_" + m, t.K_tam);
    c.matrices.emplace_back("T_" + m, t.T);
  }
  std::vector<char> kept(s.candidates.size(), 0);
  for (int b : s.result.kept_blocks) kept[static_cast<std::size_t>(b)] = 1;
  const Eigen::Index k = static_cast<Eigen::Index>(s.target_modes.size());
  std::vector<Eigen::Index> rows;
  for (std::size_t r = 0; r < s.directions.size(); ++r)
    if (kept[static_cast<std::size_t>(s.directions[r].block)]) rows.push_back(static_cast<Eigen::Index>(r));
  const Eigen::Index a = static_cast<Eigen::Index>(rows.size());
  Eigen::MatrixXd node(a, 1), dir(a, 3), phi(a, k), modes(1, k), hz(1, k);
  for (Eigen::Index i = 0; i < a; ++i) {
    const PlacementDirection& d = s.directions[static_cast<std::size_t>(rows[static_cast<std::size_t>(i)])];
    const PlacementCandidate& cand = s.candidates[static_cast<std::size_t>(d.block)];
    node(i, 0) = cand.node;
    for (int x = 0; x < 3; ++x) dir(i, x) = d.world[static_cast<std::size_t>(x)];
    for (Eigen::Index j = 0; j < k; ++j) {
      const auto& u = cand.shape[static_cast<std::size_t>(j)];
      phi(i, j) = u[0] * d.world[0] + u[1] * d.world[1] + u[2] * d.world[2];
    }
  }
  for (Eigen::Index j = 0; j < k; ++j) modes(0, j) = s.target_modes[static_cast<std::size_t>(j)].number(), hz(0, j) = s.target_frequencies_hz[static_cast<std::size_t>(j)];
  c.matrices.emplace_back("ChannelNode", node);
  c.matrices.emplace_back("ChannelDirection", dir);
  c.matrices.emplace_back("TargetMode", modes);
  c.matrices.emplace_back("TargetFrequencyHz", hz);
  c.matrices.emplace_back("PhiA", phi);
  c.strings.emplace_back("Method", methods);
  c.strings.emplace_back("Channel", s.channels);
  return c;
}

}  // namespace mmv
