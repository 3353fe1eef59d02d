#include "sim/io/update_report.hpp"

#include <cmath>
#include <sstream>

#include "sim/core/text.hpp"
#include "sim/io/report.hpp"

namespace mmv {
namespace {

using json = nlohmann::ordered_json;
using Opt = std::optional<json>;

json finiteOrNull(double v) { return std::isfinite(v) ? json(v) : json(nullptr); }

const auto kAll = [](const auto&) { return true; };

/// "+0.707 materials.x.youngs_modulus -0.707 materials.x.density": a combination's parts of 0.05 or more.
std::string combination(const ModelUpdateResult& r, const Eigen::VectorXd& v) {
  std::string out;
  for (Eigen::Index k = 0; k < v.size(); ++k)
    if (std::abs(v(k)) >= 0.05) out += strf("%s%+.3f %s", out.empty() ? "" : " ", v(k), r.parameters[static_cast<std::size_t>(k)].key.c_str());
  return out;
}

nlohmann::ordered_json combinationJson(const ModelUpdateResult& r, const Eigen::VectorXd& v) {
  nlohmann::ordered_json c = nlohmann::ordered_json::object();
  for (Eigen::Index k = 0; k < v.size(); ++k) c[r.parameters[static_cast<std::size_t>(k)].key] = v(k);
  return c;
}

bool undetermined(const ModelUpdateResult& r, Eigen::Index i) {
  for (const int u : r.fit.identifiability.undetermined)
    if (u == i) return true;
  return false;
}

std::string residualsLine(const ModelUpdateResult& r) {
  const auto& o = r.options;
  return strf("%zu measured modes tracked: frequency errors weighted 1 / %.3g", r.pairs.size(), o.frequency_sigma) +
         (o.mac_residuals ? strf(", (1 - MAC) weighted 1 / %.3g", o.mac_sigma) : std::string(", MAC not in the residuals")) +
         (o.regularization > 0 ? strf(", pull toward the nominal %.3g per 100 %% change", o.regularization) : std::string());
}

}  // namespace

const std::vector<Field<UpdatedParameter>>& updateParameterFields() {
  using Row = UpdatedParameter;
  // clang-format off
  static const std::vector<Field<Row>> fields{
      {"key", "", "%s", "the scene key (as --set names it)", [](const Row& p) -> Opt { return json(p.key); }},
      {"line", "", "%d", "its line in the scene file", [](const Row& p) -> Opt { return json(p.line); }},
      {"nominal", "", "%.17g", "the file's value", [](const Row& p) -> Opt { return json(p.nominal); }},
      {"lower", "", "%.17g", "the lower bound", [](const Row& p) -> Opt { return json(p.lower); }},
      {"upper", "", "%.17g", "the upper bound", [](const Row& p) -> Opt { return json(p.upper); }},
      {"updated", "", "%.17g", "the updated value (as the updated scene writes it)", [](const Row& p) -> Opt { return json(p.updated); }},
      {"change", "1", "%.6g", "updated / nominal - 1 (null: a nominal of 0)",
       [](const Row& p) -> Opt { return p.nominal != 0 ? json(p.updated / p.nominal - 1) : json(nullptr); }},
      {"standard_error", "", "%.6g", "from the residual variance (null: not determined, or no more residuals than parameters)",
       [](const Row& p) -> Opt { return finiteOrNull(p.standard_error); }},
      {"interval_low", "", "%.10g", "the 95 % interval's low end (Student's t)",
       [](const Row& p) -> Opt { return finiteOrNull(p.updated - p.interval_half_width); }},
      {"interval_high", "", "%.10g", "the 95 % interval's high end",
       [](const Row& p) -> Opt { return finiteOrNull(p.updated + p.interval_half_width); }},
      {"at_bound", "", "%d", "the updated value is on a bound: the data pull it beyond", [](const Row& p) -> Opt { return json(p.at_bound); }},
      {"determined", "", "%d", "not part of a combination the data do not determine", [](const Row& p) -> Opt { return json(p.determined); }},
  };
  // clang-format on
  return fields;
}

const std::vector<Field<UpdatePair>>& updatePairFields() {
  using Row = UpdatePair;
  // clang-format off
  static const std::vector<Field<Row>> fields{
      {"test", "", "%s", "the measured mode (T1: a measured set's first; a HAM-SAS feature by name)", [](const Row& p) -> Opt { return json(p.test); }},
      {"test_hz", "Hz", "%.8g", "its frequency", [](const Row& p) -> Opt { return json(p.test_hz); }},
      {"before_model", "", "%s", "the nominal model's mode it pairs with", [](const Row& p) -> Opt { return json(strf("M%d", p.before_model.number())); }},
      {"before_hz", "Hz", "%.8g", "that mode's frequency", [](const Row& p) -> Opt { return json(p.before_hz); }},
      {"before_error", "1", "%.6g", "before_hz / test_hz - 1", [](const Row& p) -> Opt { return json(p.before_hz / p.test_hz - 1); }},
      {"before_mac", "1", "%.6f", "MAC with the nominal model's mode", [](const Row& p) -> Opt { return json(p.before_mac); }},
      {"after_model", "", "%s", "the updated model's mode it pairs with", [](const Row& p) -> Opt { return json(strf("M%d", p.after_model.number())); }},
      {"after_hz", "Hz", "%.8g", "that mode's frequency", [](const Row& p) -> Opt { return json(p.after_hz); }},
      {"after_error", "1", "%.6g", "after_hz / test_hz - 1", [](const Row& p) -> Opt { return json(p.after_hz / p.test_hz - 1); }},
      {"after_mac", "1", "%.6f", "MAC with the updated model's mode", [](const Row& p) -> Opt { return json(p.after_mac); }},
  };
  // clang-format on
  return fields;
}

nlohmann::ordered_json updateJson(const ModelUpdateResult& r) {
  json j;
  j["mmvlab_version"] = mmvlabVersion();
  j["command"] = "update";
  j["scene"] = {{"name", r.scene}, {"source", r.scene_source}};
  j["measured"] = r.measured;
  j["converged"] = r.fit.converged;
  j["stop"] = r.fit.stop;
  j["evaluations"] = r.fit.evaluations;
  j["residuals"] = {{"tracked_test_modes", r.pairs.size()},
                    {"count", r.fit.residuals.size()},
                    {"frequency_sigma", r.options.frequency_sigma},
                    {"mac_sigma", r.options.mac_residuals ? json(r.options.mac_sigma) : json(nullptr)},
                    {"regularization", r.options.regularization}};
  j["rms_frequency_error_before"] = r.rms_frequency_error_before;
  j["rms_frequency_error_after"] = r.rms_frequency_error_after;
  json params = json::array(), pairs = json::array();
  for (const auto& p : r.parameters) params.push_back(fieldsJson(updateParameterFields(), p, kAll));
  for (const auto& p : r.pairs) pairs.push_back(fieldsJson(updatePairFields(), p, kAll));
  j["parameters"] = params;
  j["pairs"] = pairs;
  const Identifiability& id = r.fit.identifiability;
  json dirs = json::array(), collinear = json::array();
  for (Eigen::Index i = 0; i < id.singular_values.size(); ++i)
    dirs.push_back({{"singular_value", id.singular_values(i)}, {"determined", !undetermined(r, i)},
                    {"combination", combinationJson(r, id.directions.col(i))}});
  for (const auto& [index, v] : id.collinear)
    collinear.push_back({{"collinearity_index", std::isfinite(index) ? json(index) : json(nullptr)}, {"combination", combinationJson(r, v)}});
  json corr = json::array();
  for (Eigen::Index k = 0; k < id.correlation.rows(); ++k) {
    json row = json::array();
    for (Eigen::Index m = 0; m < id.correlation.cols(); ++m) row.push_back(finiteOrNull(id.correlation(k, m)));
    corr.push_back(row);
  }
  j["identifiability"] = {{"criterion_undetermined_below", id.undetermined_below},
                          {"criterion_collinearity_above", id.collinearity_above},
                          {"directions", dirs},
                          {"collinear", collinear},
                          {"residual_variance", id.residual_variance ? json(*id.residual_variance) : json(nullptr)},
                          {"degrees_of_freedom", id.degrees_of_freedom},
                          {"correlation", corr}};
  json its = json::array();
  for (const auto& it : r.fit.iterations) {
    json p = json::array();
    for (Eigen::Index k = 0; k < it.p.size(); ++k) p.push_back(it.p(k));
    its.push_back({{"iteration", it.iteration}, {"cost", it.cost}, {"damping", it.damping}, {"evaluations", it.evaluations}, {"parameters", p}});
  }
  j["iterations"] = its;
  j["notes"] = r.notes;
  return j;
}

std::string updateText(const ModelUpdateResult& r) {
  std::ostringstream os;
  os << "Model update: " << r.scene << " against " << r.measured << "\n  " << residualsLine(r) << "\n";
  os << strf("  %s after %zu iterations (%d model evaluations): %s\n", r.fit.converged ? "converged" : "NOT converged",
             r.fit.iterations.size() - 1, r.fit.evaluations, r.fit.stop.c_str());
  os << strf("  RMS frequency error %.3f %% before, %.3f %% after\n\nParameters\n", 100 * r.rms_frequency_error_before,
             100 * r.rms_frequency_error_after);
  Table t({"key", "nominal", "updated", "change_%", "95%_interval", "bounds", "note"});
  for (const auto& p : r.parameters) {
    const auto v = [&p](const char* key) { return fieldValue(updateParameterFields(), p, key); };
    const Opt low = v("interval_low"), high = v("interval_high"), change = v("change");
    t.add({p.key, strf("%.6g", v("nominal")->get<double>()), strf("%.6g", v("updated")->get<double>()),
           change->is_number() ? strf("%+.3f", 100 * change->get<double>()) : "-",
           low->is_number() ? strf("%.5g .. %.5g", low->get<double>(), high->get<double>()) : "-",
           strf("%.4g .. %.4g", p.lower, p.upper),
           !p.determined ? "not determined" : p.at_bound ? "at its bound" : std::string()});
  }
  os << t.text() << "\nMeasured modes: before and after\n";
  Table pt({"test", "test_Hz", "before", "before_Hz", "error_%", "MAC", "after", "after_Hz", "error_%", "MAC"});
  for (const auto& p : r.pairs) {
    const auto v = [&p](const char* key) { return fieldValue(updatePairFields(), p, key); };
    pt.add({v("test")->get<std::string>(), strf("%.4f", p.test_hz), v("before_model")->get<std::string>(), strf("%.4f", p.before_hz),
            strf("%+.3f", 100 * v("before_error")->get<double>()), strf("%.4f", p.before_mac), v("after_model")->get<std::string>(),
            strf("%.4f", p.after_hz), strf("%+.3f", 100 * v("after_error")->get<double>()), strf("%.4f", p.after_mac)});
  }
  os << pt.text();
  const Identifiability& id = r.fit.identifiability;
  os << strf("\nIdentifiability: combinations of relative parameter changes and s, how far a 100 %% change along each "
             "moves the weighted residuals (1 sigma of the data per unit); below %.3g: not determined (less than the "
             "data's stated uncertainty)\n",
             id.undetermined_below);
  Table it({"verdict", "s", "1_sigma_%", "combination"});
  for (Eigen::Index i = 0; i < id.singular_values.size(); ++i)
    it.add({undetermined(r, i) ? "NOT determined" : "determined", strf("%.4g", id.singular_values(i)),
            id.singular_values(i) > 0 ? strf("%.3g", 100 / id.singular_values(i)) : "inf", combination(r, id.directions.col(i))});
  os << it.text();
  for (const auto& [index, v] : id.collinear)
    os << strf("  collinear (index %.3g, above %.3g): %s: their sensitivities nearly repeat one another; only the "
               "other combinations are determined\n",
               index, id.collinearity_above, combination(r, v).c_str());
  if (!id.undetermined.empty() || !id.collinear.empty())
    os << "  the values of parameters not determined moved along a valley of the fit: fix one parameter of each such "
          "combination (or pull toward the nominal with --regularization) and update again\n";
  if (!id.residual_variance) os << "  no intervals: as many parameters as residuals (no residual variance)\n";
  for (const auto& n : r.notes) os << "note: " << n << '\n';
  return os.str();
}

std::string updateParametersCsv(const ModelUpdateResult& r) { return fieldsCsv(updateParameterFields(), r.parameters, kAll); }

std::string updatePairsCsv(const ModelUpdateResult& r) { return fieldsCsv(updatePairFields(), r.pairs, kAll); }

std::string updateIterationsCsv(const ModelUpdateResult& r) {
  std::ostringstream os;
  os << "iteration,cost,damping,evaluations";
  for (const auto& p : r.parameters) os << ',' << csvColumnName(p.key);
  os << '\n';
  for (const auto& it : r.fit.iterations) {
    os << it.iteration << ',' << strf("%.10g,%.6g", it.cost, it.damping) << ',' << it.evaluations;
    for (Eigen::Index k = 0; k < it.p.size(); ++k) os << ',' << strf("%.17g", it.p(k));
    os << '\n';
  }
  return os.str();
}

}  // namespace mmv
