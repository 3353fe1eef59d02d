#include "sim/io/convergence_fields.hpp"

#include <cmath>

namespace mmv {

namespace {

using json = nlohmann::ordered_json;
using Opt = std::optional<json>;

json finite(double x) { return std::isfinite(x) ? json(x) : json(nullptr); }  // JSON has no NaN

/// A field of the mode's own record, for a point of that mode.
Opt modeValue(const ConvergencePoint& p, const char* key) { return fieldValue(convergenceModeFields(), *p.mode, key); }

}  // namespace

const std::vector<Field<ConvergenceMode>>& convergenceModeFields() {
  using Mode = ConvergenceMode;
  // clang-format off
  static const std::vector<Field<Mode>> fields{
      {"number", "", "%d", "the mode (1: the lowest at each run)", [](const Mode& m) -> Opt { return json(m.number); }},
      {"frequency_hz_by_run", "Hz", nullptr, "its frequency at each run, coarsest first (null: the run has no such mode)",
       [](const Mode& m) -> Opt {
         json f = json::array();
         for (double x : m.frequency_hz) f.push_back(finite(x));
         return f;
       }},
      {"richardson_hz", "Hz", "%.10g", "f_N + (f_N - f_N/2) / 3 from the two finest runs (null: fewer than two)",
       [](const Mode& m) -> Opt { return m.has_estimate ? json(m.extrapolated_hz) : json(nullptr); }},
      {"estimated_relative_error", "1", "%.6g", "the finest run's estimated error (see check for how it was taken)",
       [](const Mode& m) -> Opt { return m.has_estimate ? json(m.estimated_relative_error) : json(nullptr); }},
      {"observed_order", "", "%.4g", "log2 of the ratio of the last two differences (null: fewer than three runs)",
       [](const Mode& m) -> Opt { return m.has_observed_order ? json(m.observed_order) : json(nullptr); }},
      {"check", "", "%s", "ok (order 2), order (another order > 0.5), unconverged, rigid, or unchecked (no estimate)",
       [](const Mode& m) -> Opt { return json(m.check.empty() ? std::string("unchecked") : m.check); }},
  };
  // clang-format on
  return fields;
}

const std::vector<Field<ConvergencePoint>>& convergencePointFields() {
  using P = ConvergencePoint;
  // clang-format off
  static const std::vector<Field<P>> fields{
      {"mode", "", "%d", "the mode (1: the lowest at each run)", [](const P& p) -> Opt { return modeValue(p, "number"); }},
      {"segments", "", "%d", "segments per flexible link of the run", [](const P& p) -> Opt { return json(p.run->segments); }},
      {"dofs", "", "%d", "the run's degrees of freedom", [](const P& p) -> Opt { return json(p.run->num_dofs); }},
      {"frequency_hz", "Hz", "%.10g", "the mode's frequency at the run",
       [](const P& p) -> Opt { return json(p.mode->frequency_hz[p.k]); }},
      {"relative_error", "1", "%.6g", "frequency_hz / richardson_hz - 1 (null: no Richardson value)",
       [](const P& p) -> Opt {
         if (!p.mode->has_estimate) return json(nullptr);
         return json((p.mode->frequency_hz[p.k] - p.mode->extrapolated_hz) / p.mode->extrapolated_hz);
       }},
      {"richardson_hz", "Hz", "%.10g", "the mode's Richardson value", [](const P& p) -> Opt { return modeValue(p, "richardson_hz"); }},
      {"observed_order", "", "%.4g", "the mode's observed order", [](const P& p) -> Opt { return modeValue(p, "observed_order"); }},
      {"check", "", "%s", "the mode's check", [](const P& p) -> Opt { return modeValue(p, "check"); }},
  };
  // clang-format on
  return fields;
}

std::vector<ConvergencePoint> convergencePoints(const ConvergenceStudy& c) {
  std::vector<ConvergencePoint> points;
  for (const auto& m : c.modes)
    for (std::size_t k = 0; k < c.runs.size() && k < m.frequency_hz.size(); ++k)
      if (std::isfinite(m.frequency_hz[k])) points.push_back({&m, &c.runs[k], k});  // else the run has no such mode
  return points;
}

std::string convergenceCsv(const ConvergenceStudy& c) {
  return fieldsCsv(convergencePointFields(), convergencePoints(c), [](const auto&) { return true; });
}

}  // namespace mmv
