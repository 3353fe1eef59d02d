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
      {"lost", "", "%d", "no loaded mode up to 1.5 times its frequency resembles it (MAC < 0.5): loaded_hz is only the nearest shape's",
       [](const M& m) -> Opt { return json(m.lost); }},
  };
  // clang-format on
  return fields;
}

const std::vector<Field<LoadedIteration>>& loadedIterationFields() {
  using I = LoadedIteration;
  // clang-format off
  static const std::vector<Field<I>> fields{
      {"pass", "", "%d", "placement on the model carrying the previous pass's set (pass 1: the bare model's)", [](const I& i) -> Opt { return json(i.pass); }},
      {"changed", "", "%d", "chosen blocks not in the set the pass's model carried", [](const I& i) -> Opt { return json(i.changed); }},
      {"tie", "", "%d", "another set exactly as informative as the one carried (Fisher determinants within 1e-6): a tie between equivalent points", [](const I& i) -> Opt { return json(i.tie); }},
      {"settled", "", "%d", "no block changed, or a tie: the set carries itself", [](const I& i) -> Opt { return json(i.settled); }},
      {"repeats", "", "%d", "a set an earlier pass chose: the passes cycle", [](const I& i) -> Opt { return json(i.repeats); }},
  };
  // clang-format on
  return fields;
}

namespace {

/// How the passes ended: "settled", "cycle" or "limit" (kMaxLoadedIterations passes).
std::string iterationOutcome(const SensorLoading& l) {
  const LoadedIteration& last = l.iterations.back();
  return last.settled ? "settled" : last.repeats ? "cycle" : "limit";
}

}  // namespace

json loadingJson(const SensorLoading& l) {
  json j = {{"sensor_mass_kg", l.sensor_mass_kg}, {"sensors", l.sensors}, {"added_kg", l.added_kg}};
  if (l.weight_in_stiffness) j["weight_in_stiffness"] = true;  // the isolator's: the springs carry their weight
  j["modes"] = json::array();
  for (const auto& m : l.modes) j["modes"].push_back(fieldsJson(loadingModeFields(), m, [](const auto&) { return true; }));
  if (!l.iterations.empty()) {
    j["iterations"] = json::array();
    for (const auto& i : l.iterations) j["iterations"].push_back(fieldsJson(loadedIterationFields(), i, [](const auto&) { return true; }));
    j["iteration_outcome"] = iterationOutcome(l);
  }
  return j;
}

std::string loadingText(const SensorLoading& l) {
  std::ostringstream os;
  os << strf("\nThe sensors' own mass: %d sensors of %.4g kg (%.4g kg in all) welded at their stations, %sthe modes solved "
             "again\n",
             l.sensors, l.sensor_mass_kg, l.added_kg,
             l.weight_in_stiffness ? "their weight on the springs (gravity's stiffness feels it; first order counts the inertia "
                                     "only), "
                                   : "");
  if (!l.iterations.empty()) {
    os << "  placed again on the model carrying them:";
    for (const auto& i : l.iterations) os << strf(" pass %d, %d changed%s;", i.pass, i.changed, i.tie ? " (a tie: as informative as the set carried)" : "");
    const std::string outcome = iterationOutcome(l);
    os << (outcome == "settled" ? " the set carries itself (placed on the model it loads)\n"
           : outcome == "cycle"  ? "\nwarning: the passes cycle between sets (the choice turns on the sensors' masses): the last is kept\n"
                                 : strf("\nwarning: no set carried itself in %d passes: the last is kept\n", kMaxLoadedIterations));
  }
  Table t({"mode", "f_Hz", "loaded_mode", "loaded_Hz", "shift_%", "first_order_%", "MAC", "note"});
  int heavy = 0, shared = 0;
  for (const auto& m : l.modes) {  // the cells are the records' values (loadingModeFields)
    const json rec = fieldsJson(loadingModeFields(), m, [](const auto&) { return true; });
    const bool beyond = rec["beyond_first_order"].get<bool>(), same = rec["shared"].get<bool>(), lost = rec["lost"].get<bool>();
    heavy += beyond || lost, shared += same;
    t.add({std::to_string(rec["mode"].get<int>()), strf("%.4f", rec["frequency_hz"].get<double>()),
           std::to_string(rec["loaded_mode"].get<int>()), strf("%.4f", rec["loaded_hz"].get<double>()),
           strf("%+.3f", 100 * rec["shift"].get<double>()), strf("%+.3f", 100 * rec["first_order_shift"].get<double>()),
           strf("%.4f", rec["mac"].get<double>()),
           lost   ? "NO COUNTERPART (no loaded mode resembles it)"
           : same ? "SHAPE CHANGED (shares its loaded mode)"
           : beyond ? "HEAVY (beyond first order)"
                    : "-"});
  }
  os << t.text();
  if ((heavy || shared) && l.weight_in_stiffness)
    os << strf("warning: the sensors move %d target mode(s) beyond their inertia's first-order shift%s: their weight on "
               "the gravity-tuned springs counts; trim the isolator for it (as its load is set), or use lighter sensors\n",
               std::max(heavy, shared), shared ? " and change the shapes of some" : "");
  else if (heavy || shared)
    os << strf("warning: the sensors are heavy against %d target mode(s)%s: lighter sensors, fewer on the light links, or "
               "place on the model carrying them (--iterate-loaded)\n",
               std::max(heavy, shared), shared ? " and change the shapes of some" : "");
  return os.str();
}

}  // namespace mmv
