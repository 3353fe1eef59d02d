#include "sim/io/loading_report.hpp"

#include <sstream>

#include "sim/core/text.hpp"

namespace mmv {

namespace {
using json = nlohmann::ordered_json;
using Opt = std::optional<json>;
}  // namespace

const std::vector<Field<SensorLoading::Mode>>& loadingModeFields() {
  using M = SensorLoading::Mode;
  // clang-format off
  static const std::vector<Field<M>> fields{
      {"mode", "", "%d", "the target mode, without the sensors", [](const M& m) -> Opt { return json(m.mode.number()); }},
      {"frequency_hz", "Hz", "%.8g", "its frequency without them", [](const M& m) -> Opt { return json(m.frequency_hz); }},
      {"loaded_mode", "", "%d", "the loaded model's mode it follows (largest MAC)", [](const M& m) -> Opt { return json(m.loaded_mode.number()); }},
      {"loaded_hz", "Hz", "%.8g", "that mode's frequency, with the sensors", [](const M& m) -> Opt { return json(m.loaded_hz); }},
      {"shift", "1", "%.6g", "loaded_hz / frequency_hz - 1", [](const M& m) -> Opt { return json(m.shift); }},
      {"first_order_shift", "1", "%.6g", "-1/2 sum m |u|^2 over the sensors (first-order perturbation)",
       [](const M& m) -> Opt { return json(m.first_order); }},
      {"mac", "1", "%.6f", "MAC of the two shapes over the coordinates, weighted by the unloaded mass matrix",
       [](const M& m) -> Opt { return json(m.mac); }},
      {"beyond_first_order", "", "%d", "the exact shift differs from first order by more than a fifth: the sensors are heavy for this mode",
       [](const M& m) -> Opt { return json(m.beyond_first_order); }},
      {"shared", "", "%d", "another target follows the same loaded mode: the sensors change the shapes",
       [](const M& m) -> Opt { return json(m.shared); }},
  };
  // clang-format on
  return fields;
}

json loadingJson(const SensorLoading& l) {
  json j = {{"sensor_mass_kg", l.sensor_mass_kg}, {"sensors", l.sensors}, {"added_kg", l.added_kg}};
  j["modes"] = json::array();
  for (const auto& m : l.modes) j["modes"].push_back(fieldsJson(loadingModeFields(), m, [](const auto&) { return true; }));
  return j;
}

std::string loadingText(const SensorLoading& l) {
  std::ostringstream os;
  os << strf("\nThe sensors' own mass: %d sensors of %.4g kg (%.4g kg in all) welded at their stations, the modes solved "
             "again\n",
             l.sensors, l.sensor_mass_kg, l.added_kg);
  Table t({"mode", "f_Hz", "loaded_mode", "loaded_Hz", "shift_%", "first_order_%", "MAC", "note"});
  int heavy = 0, shared = 0;
  for (const auto& m : l.modes) {  // the cells are the records' values (loadingModeFields)
    const json rec = fieldsJson(loadingModeFields(), m, [](const auto&) { return true; });
    const bool beyond = rec["beyond_first_order"].get<bool>(), same = rec["shared"].get<bool>();
    heavy += beyond, shared += same;
    t.add({std::to_string(rec["mode"].get<int>()), strf("%.4f", rec["frequency_hz"].get<double>()),
           std::to_string(rec["loaded_mode"].get<int>()), strf("%.4f", rec["loaded_hz"].get<double>()),
           strf("%+.3f", 100 * rec["shift"].get<double>()), strf("%+.3f", 100 * rec["first_order_shift"].get<double>()),
           strf("%.4f", rec["mac"].get<double>()),
           same ? "SHAPE CHANGED (shares its loaded mode)" : beyond ? "HEAVY (beyond first order)" : "-"});
  }
  os << t.text();
  if (heavy || shared)
    os << strf("warning: the sensors are heavy against %d target mode(s)%s: lighter sensors, fewer on the light links, or "
               "place with their masses in the model\n",
               std::max(heavy, shared), shared ? " and change the shapes of some" : "");
  return os.str();
}

}  // namespace mmv
