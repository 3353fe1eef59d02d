#include "sim/io/exciter_report.hpp"

#include <cmath>
#include <sstream>

#include "sim/core/text.hpp"

namespace mmv {

namespace {
using json = nlohmann::ordered_json;
using Opt = std::optional<json>;
using M = ExciterStudy::Mode;
const auto every = [](const auto&) { return true; };

std::vector<RankedExciter> ranked(const ExciterStudy& e, std::size_t n) {
  std::vector<RankedExciter> out;
  for (std::size_t i = 0; i < e.ranking.size() && i < n; ++i) out.push_back({static_cast<int>(i + 1), &e.ranking[i]});
  return out;
}

std::string vec(const std::array<double, 3>& v) { return strf("[%.4g %.4g %.4g]", v[0], v[1], v[2]); }
}  // namespace

namespace {

/// A level's stress cell: the link nearest its limit, its static and dwell stress and
/// the limit, MPa ("-": no link with an allowable).
std::string levelStressCell(const LevelStrength& s) {
  if (s.link.empty()) return "-";
  return strf("%s %.3g + %.3g of %.3g MPa", s.link.c_str(), 1e-6 * s.static_pa, 1e-6 * s.amplitude_pa, 1e-6 * s.limit_pa);
}

/// A dwell whose tip motion is no small deflection: said, with what to do.
std::string largeDeflectionNote(ModeNumber mode, const LevelStrength& s) {
  if (!(s.tip_link_m > 0 && s.tip_amplitude_m > kLargeDeflection * s.tip_link_m)) return "";
  return strf("  mode %d's dwell moves %s %.3g mm, %.0f %% of its link's length: beyond small deflections, where the linear "
              "model does not hold; state the article's limit (--max-deflection)\n",
              mode.number(), s.tip.c_str(), 1e3 * s.tip_amplitude_m, 100 * s.tip_amplitude_m / s.tip_link_m);
}

}  // namespace

const std::vector<Field<M>>& exciterModeFields() {
  // clang-format off
  static const std::vector<Field<M>> fields{
      {"mode", "", "%d", "the target mode of the article without the armature", [](const M& m) -> Opt { return json(m.mode.number()); }},
      {"frequency_hz", "Hz", "%.8g", "its frequency", [](const M& m) -> Opt { return json(m.frequency_hz); }},
      {"loaded_mode", "", "%d", "the mode of the article with the armature that follows it (largest MAC)", [](const M& m) -> Opt { return json(m.loaded_mode.number()); }},
      {"loaded_hz", "Hz", "%.8g", "that mode's frequency: the sine dwell's", [](const M& m) -> Opt { return json(m.loaded_hz); }},
      {"shift", "1", "%.6g", "loaded_hz / frequency_hz - 1", [](const M& m) -> Opt { return json(m.loaded_hz / m.frequency_hz - 1); }},
      {"mac", "1", "%.6f", "the MAC of the pairing (the unloaded mass matrix)", [](const M& m) -> Opt { return json(m.mac); }},
      {"zeta", "1", "%.6g", "the loaded mode's damping ratio (the diagonal of the modal damping)", [](const M& m) -> Opt { return json(m.zeta); }},
      {"sine_force_n", "N", "%.6g", "the sine dwell's force amplitude: the shaker's limit, lowered to the stroke or a sensor's range", [](const M& m) -> Opt { return json(m.sine_force_n); }},
      {"sine_limit", "", "%s", "what set it: force, stroke, range, stress (a link's allowable over its factor) or deflection (--max-deflection)", [](const M& m) -> Opt { return json(m.sine_limit); }},
      {"stress_link", "", "%s", "the link nearest its strength limit in the dwell (null: no link with an allowable)",
       [](const M& m) -> Opt { return m.strength.link.empty() ? json(nullptr) : json(m.strength.link); }},
      {"static_stress_pa", "Pa", "%.6g", "its static peak stress", [](const M& m) -> Opt { return m.strength.link.empty() ? json(nullptr) : json(m.strength.static_pa); }},
      {"stress_amplitude_pa", "Pa", "%.6g", "its bending stress amplitude in the dwell (peak over root, hinges, tip)",
       [](const M& m) -> Opt { return m.strength.link.empty() ? json(nullptr) : json(m.strength.amplitude_pa); }},
      {"stress_limit_pa", "Pa", "%.6g", "its allowable over its factor: static + amplitude stays within it",
       [](const M& m) -> Opt { return m.strength.link.empty() ? json(nullptr) : json(m.strength.limit_pa); }},
      {"tip", "", "%s", "the link tip that moves most", [](const M& m) -> Opt { return json(m.strength.tip); }},
      {"tip_amplitude_m", "m", "%.6g", "its motion's amplitude (held to --max-deflection when given)", [](const M& m) -> Opt { return json(m.strength.tip_amplitude_m); }},
      {"sine_acc", "m/s^2", "%.6g", "the acceleration amplitude at the sensor that sees the mode most", [](const M& m) -> Opt { return json(m.sine_acc); }},
      {"best_channel", "", "%s", "that sensor direction (station axis)", [](const M& m) -> Opt { return json(m.best_channel); }},
      {"sine_snr_db", "dB", "%.6g", "20 log10(sine_acc / the accelerometer's resolution)", [](const M& m) -> Opt { return json(m.sine_snr_db); }},
      {"channels_seen", "", "%d", "sensor directions at or above 20 dB in the dwell", [](const M& m) -> Opt { return json(m.channels_seen); }},
      {"sine_stroke_m", "m", "%.6g", "the driving point's displacement amplitude along the shaker", [](const M& m) -> Opt { return json(m.sine_stroke_m); }},
      {"random_snr_db", "dB", "%.6g", "random run: the best sensor's acceleration spectrum at loaded_hz over the quantization noise's", [](const M& m) -> Opt { return json(m.random_snr_db); }},
      {"seen", "", "%d", "sine_snr_db >= 20 dB", [](const M& m) -> Opt { return json(m.seen); }},
  };
  // clang-format on
  return fields;
}

const std::vector<Field<RankedExciter>>& exciterCandidateFields() {
  using R = RankedExciter;
  // clang-format off
  static const std::vector<Field<R>> fields{
      {"rank", "", "%d", "1: the best attachment", [](const R& r) -> Opt { return json(r.rank); }},
      {"station", "", "%s", "where the stinger attaches", [](const R& r) -> Opt { return json(r.c->station); }},
      {"axis", "", "%s", "along which of the station's axes it pushes: axial, transverse, normal", [](const R& r) -> Opt { return json(r.c->axis); }},
      {"node", "", "%d", "the station's test-geometry node", [](const R& r) -> Opt { return json(r.c->node); }},
      {"direction_x", "1", "%.6f", "the force's direction, world x", [](const R& r) -> Opt { return json(r.c->world[0]); }},
      {"direction_y", "1", "%.6f", "the force's direction, world y", [](const R& r) -> Opt { return json(r.c->world[1]); }},
      {"direction_z", "1", "%.6f", "the force's direction, world z", [](const R& r) -> Opt { return json(r.c->world[2]); }},
      {"score", "1", "%.6g", "the weakest target's driving-point residue over its best at an attachment that does not load the article (1: as well fed as anywhere usable)", [](const R& r) -> Opt { return json(r.c->score); }},
      {"weakest_mode", "", "%d", "that target mode", [](const R& r) -> Opt { return json(r.c->weakest.number()); }},
      {"max_shift", "1", "%.6g", "the armature's largest first-order frequency shift over the targets", [](const R& r) -> Opt { return json(r.c->max_shift); }},
      {"loads", "", "%d", "|max_shift| above 2 %: ranked after every attachment that does not", [](const R& r) -> Opt { return json(r.c->loads); }},
  };
  // clang-format on
  return fields;
}

json exciterJson(const ExciterStudy& e, std::size_t n) {
  json j;
  j["shaker"] = {{"force_limit_n", e.hardware.force_limit},
                 {"stroke_m", e.hardware.stroke},
                 {"armature_mass_kg", e.hardware.armature_mass},
                 {"crest_factor", e.hardware.crest_factor}};
  j["at"] = e.at;
  j["direction"] = e.direction;
  j["chosen_by_ranking"] = e.chosen;
  j["damping"] = e.damping;
  j["sensor"] = {{"resolution_m_per_s2", e.resolution}, {"range_m_per_s2", e.range}, {"sample_rate_hz", e.sample_rate_hz}};
  j["criteria"] = {{"seen_snr_db", kSeenSnrDb}, {"armature_shift_limit", kArmatureShiftLimit}};
  j["modes"] = json::array();
  for (const auto& m : e.modes) j["modes"].push_back(fieldsJson(exciterModeFields(), m, every));
  const auto& r = e.random;
  j["random"] = {{"f_min_hz", r.f_min_hz},       {"f_max_hz", r.f_max_hz},   {"rms_force_n", r.rms_force_n},
                 {"limit", r.limit},             {"rms_acc_m_per_s2", r.rms_acc}, {"rms_channel", r.rms_channel},
                 {"stroke_rms_m", r.stroke_rms_m}, {"grid_points", r.grid_points}};
  j["ranking"] = json::array();
  for (const auto& c : ranked(e, n)) j["ranking"].push_back(fieldsJson(exciterCandidateFields(), c, every));
  j["candidates"] = e.ranking.size();
  return j;
}

std::string exciterText(const ExciterStudy& e) {
  std::ostringstream os;
  int seen = 0;
  for (const auto& m : e.modes) seen += m.seen;
  os << strf("\nShaker (%.4g N, +-%.4g m stroke, %.4g kg armature) at %s along %s%s: %d of %zu target modes seen at >= %.0f dB\n",
             e.hardware.force_limit, e.hardware.stroke, e.hardware.armature_mass, e.at.c_str(), vec(e.direction).c_str(),
             e.chosen ? " (the best-ranked attachment)" : "", seen, e.modes.size(), kSeenSnrDb);
  os << "  damping: " << e.damping << strf("; sensors: resolution %.4g m/s^2, range +-%.4g m/s^2\n", e.resolution, e.range);
  Table t({"mode", "f_Hz", "loaded_Hz", "shift_%", "force_N", "limit", "tip_mm", "stress (static + dwell) / limit", "acc_m/s2",
           "best sensor", "SNR_dB", "seen_by", "stroke_mm", "random_dB"});
  for (const auto& m : e.modes)
    t.add({std::to_string(m.mode.number()), strf("%.4f", m.frequency_hz), strf("%.4f", m.loaded_hz),
           strf("%+.2f", 100 * (m.loaded_hz / m.frequency_hz - 1)), strf("%.3g", m.sine_force_n), m.sine_limit,
           strf("%.3g", 1e3 * m.strength.tip_amplitude_m), levelStressCell(m.strength),
           strf("%.3g", m.sine_acc), m.best_channel, strf("%.1f%s", m.sine_snr_db, m.seen ? "" : " LOW"),
           std::to_string(m.channels_seen), strf("%.3g", 1e3 * m.sine_stroke_m), strf("%.1f", m.random_snr_db)});
  os << t.text();
  for (const auto& m : e.modes) os << largeDeflectionNote(m.mode, m.strength);
  for (const auto& m : e.modes)
    if (std::abs(m.loaded_hz / m.frequency_hz - 1) > kArmatureShiftLimit)
      os << strf("  the armature moves mode %d by %+.2f %%: the test would see another article (a lighter armature, or an "
                 "attachment of the ranking)\n",
                 m.mode.number(), 100 * (m.loaded_hz / m.frequency_hz - 1));
  const auto& r = e.random;
  os << strf("  random %.3g-%.3g Hz at %.3g N RMS (set by %s): largest sensor RMS %.3g m/s^2 (%s), driving point %.3g mm RMS\n",
             r.f_min_hz, r.f_max_hz, r.rms_force_n, r.limit.c_str(), r.rms_acc, r.rms_channel.c_str(), 1e3 * r.stroke_rms_m);
  os << "  attachments ranked (score: the weakest target's driving-point residue over its best):\n";
  Table rank({"rank", "station", "axis", "score", "weakest", "armature_shift_%"});
  for (const auto& c : ranked(e, 5))
    rank.add({std::to_string(c.rank), c.c->station, c.c->axis, strf("%.3g", c.c->score), std::to_string(c.c->weakest.number()),
              strf("%+.2f%s", 100 * c.c->max_shift, c.c->loads ? " LOADS" : "")});
  os << rank.text();
  return os.str();
}

std::string exciterCsv(const ExciterStudy& e) { return fieldsCsv(exciterModeFields(), e.modes, every); }

std::string exciterRankingCsv(const ExciterStudy& e) {
  return fieldsCsv(exciterCandidateFields(), ranked(e, e.ranking.size()), every);
}

const std::vector<Field<TableLevels::Mode>>& tableLevelFields() {
  using T = TableLevels::Mode;
  // clang-format off
  static const std::vector<Field<T>> fields{
      {"mode", "", "%d", "the target mode", [](const T& m) -> Opt { return json(m.mode.number()); }},
      {"frequency_hz", "Hz", "%.8g", "its frequency: the table's sine dwell's", [](const T& m) -> Opt { return json(m.frequency_hz); }},
      {"axis", "", "%s", "the table's axis of the dwell (x in the plane, z across it): the one that shows the mode best", [](const T& m) -> Opt { return json(m.axis); }},
      {"table_acc", "m/s^2", "%.6g", "the table's acceleration amplitude: stroke x omega^2, lowered to a sensor's range", [](const T& m) -> Opt { return json(m.table_acc); }},
      {"table_amplitude_m", "m", "%.6g", "its displacement amplitude", [](const T& m) -> Opt { return json(m.table_amplitude_m); }},
      {"limit", "", "%s", "what set it: stroke, range, stress (a link's allowable over its factor) or deflection (--max-deflection)", [](const T& m) -> Opt { return json(m.limit); }},
      {"stress_link", "", "%s", "the link nearest its strength limit in the dwell (null: no link with an allowable)",
       [](const T& m) -> Opt { return m.strength.link.empty() ? json(nullptr) : json(m.strength.link); }},
      {"static_stress_pa", "Pa", "%.6g", "its static peak stress", [](const T& m) -> Opt { return m.strength.link.empty() ? json(nullptr) : json(m.strength.static_pa); }},
      {"stress_amplitude_pa", "Pa", "%.6g", "its bending stress amplitude in the dwell (peak over root, hinges, tip)",
       [](const T& m) -> Opt { return m.strength.link.empty() ? json(nullptr) : json(m.strength.amplitude_pa); }},
      {"stress_limit_pa", "Pa", "%.6g", "its allowable over its factor: static + amplitude stays within it",
       [](const T& m) -> Opt { return m.strength.link.empty() ? json(nullptr) : json(m.strength.limit_pa); }},
      {"tip", "", "%s", "the tip that moves most relative to the table", [](const T& m) -> Opt { return json(m.strength.tip); }},
      {"tip_amplitude_m", "m", "%.6g", "its motion's amplitude relative to the table (held to --max-deflection when given)",
       [](const T& m) -> Opt { return json(m.strength.tip_amplitude_m); }},
      {"acc", "m/s^2", "%.6g", "the absolute acceleration amplitude at the sensor that sees the mode most", [](const T& m) -> Opt { return json(m.acc); }},
      {"best_channel", "", "%s", "that sensor direction (station axis)", [](const T& m) -> Opt { return json(m.best_channel); }},
      {"snr_db", "dB", "%.6g", "20 log10(acc / the accelerometer's resolution)", [](const T& m) -> Opt { return json(m.snr_db); }},
      {"channels_seen", "", "%d", "sensor directions at or above 20 dB in the dwell", [](const T& m) -> Opt { return json(m.channels_seen); }},
      {"within_bandwidth", "", "%d", "the frequency is within the table's servo bandwidth", [](const T& m) -> Opt { return json(m.within_bandwidth); }},
      {"seen", "", "%d", "within the bandwidth and snr_db >= 20 dB", [](const T& m) -> Opt { return json(m.seen); }},
      {"random_snr_db", "dB", "%.6g", "the table's random program: the best sensor's acceleration spectrum at the mode over the quantization noise's (null: above the bandwidth, not in the program)",
       [](const T& m) -> Opt { return std::isfinite(m.random_snr_db) ? Opt(json(m.random_snr_db)) : std::nullopt; }},
  };
  // clang-format on
  return fields;
}

json tableLevelsJson(const TableLevels& t) {
  json j;
  j["table"] = {{"stroke_m", t.table.stroke}, {"bandwidth_hz", t.table.bandwidth_hz}};
  j["sensor"] = {{"resolution_m_per_s2", t.resolution}, {"range_m_per_s2", t.range}};
  j["criteria"] = {{"seen_snr_db", kSeenSnrDb}};
  j["max_deflection_m"] = t.max_deflection_m > 0 ? json(t.max_deflection_m) : json(nullptr);
  j["modes"] = json::array();
  for (const auto& m : t.modes) j["modes"].push_back(fieldsJson(tableLevelFields(), m, every));
  if (const auto& r = t.random; r.program)
    j["random"] = {{"f_min_hz", r.f_min_hz}, {"f_max_hz", r.f_max_hz}, {"rms_m", r.rms_m},
                   {"crest_factor", kTableCrestFactor}, {"limit", r.limit}, {"rms_acc", r.rms_acc},
                   {"rms_channel", r.rms_channel}, {"noise_psd", r.noise_psd}, {"grid_points", r.grid_points}};
  return j;
}

std::string tableLevelsText(const TableLevels& t) {
  std::ostringstream os;
  int seen = 0;
  for (const auto& m : t.modes) seen += m.seen;
  os << strf("\nBase table (+-%.4g m stroke, %.4g Hz bandwidth), a sine dwell per target mode at the stroke, lowered to the "
             "sensors' range, the links' allowables over their factors%s: %d of %zu target modes seen at >= %.0f dB\n",
             t.table.stroke, t.table.bandwidth_hz,
             t.max_deflection_m > 0 ? strf(" and the tips' %.4g mm (--max-deflection)", 1e3 * t.max_deflection_m).c_str() : "", seen,
             t.modes.size(), kSeenSnrDb);
  Table tab({"mode", "f_Hz", "axis", "table_m/s2", "table_mm", "limit", "tip_mm", "stress (static + dwell) / limit", "acc_m/s2",
             "best sensor", "SNR_dB", "seen_by", "random_dB"});
  for (const auto& m : t.modes)
    tab.add({std::to_string(m.mode.number()), strf("%.4f", m.frequency_hz), m.axis, strf("%.3g", m.table_acc),
             strf("%.3g", 1e3 * m.table_amplitude_m), m.limit, strf("%.3g", 1e3 * m.strength.tip_amplitude_m),
             levelStressCell(m.strength),
             strf("%.3g", m.acc), m.best_channel,
             strf("%.1f%s", m.snr_db, !m.within_bandwidth ? " ABOVE BANDWIDTH" : m.seen ? "" : " LOW"),
             std::to_string(m.channels_seen), std::isfinite(m.random_snr_db) ? strf("%.1f", m.random_snr_db) : "-"});
  os << tab.text();
  for (const auto& m : t.modes) os << largeDeflectionNote(m.mode, m.strength);
  if (const auto& r = t.random; r.program)
    os << strf("  random along x, %.3g-%.3g Hz, %.3g mm RMS (crest factor %.0f; set by the %s): largest sensor RMS %.3g "
               "m/s^2 (%s)\n",
               r.f_min_hz, r.f_max_hz, 1e3 * r.rms_m, kTableCrestFactor, r.limit.c_str(), r.rms_acc, r.rms_channel.c_str());
  return os.str();
}

}  // namespace mmv
