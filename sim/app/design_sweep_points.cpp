// The rows of `mmvlab sweep` (sim/app/design_sweep_points.hpp).
#include "sim/app/design_sweep_points.hpp"
#include "sim/scene/key_units.hpp"
#include "sim/core/progress.hpp"

#include "sim/core/files.hpp"
#include "sim/core/integrators.hpp"
#include "sim/core/text.hpp"

#include <fstream>
#include <optional>
#include <sstream>

#include "sim/core/text.hpp"
#include "sim/io/check_report.hpp"
#include "sim/io/report.hpp"
#include "sim/modes/tracking.hpp"
#include "sim/plan/check.hpp"

namespace mmv {

namespace {

bool wants(const DesignSweepSpec& s, const std::string& o) { return std::find(s.outputs.begin(), s.outputs.end(), o) != s.outputs.end(); }

/// `name` is `link` or one of its branches (link3 -> link3a, link3b): a symmetric
/// pair's modes put equal strain in both branches, so either may come out on top.
bool isLinkOrBranch(const std::string& name, const std::string& link) {
  return name == link || (name.size() == link.size() + 1 && name.rfind(link, 0) == 0 && std::islower(static_cast<unsigned char>(name.back())));
}

std::string cell(double v) { return std::isfinite(v) ? shortest(v) : ""; }

/// A cell cannot hold the CSV's separators.
std::string clean(std::string s) {
  for (char& c : s)
    if (c == ',' || c == '\n' || c == '\r') c = c == ',' ? ';' : ' ';
  return s;
}

/// A reader's message about an override ("--set KEY=VALUE: what") without the
/// command-line wording, for an entry that came from the spec's file.
std::string withoutSetPrefix(const std::string& message, const std::string& set) {
  const std::string prefix = "--set " + set + ": ";
  return message.rfind(prefix, 0) == 0 ? message.substr(prefix.size()) : message;
}

ArticleScene sceneAt(const DesignSweepContext& c, const std::vector<std::string>& extra) {
  std::vector<std::string> sets = c.spec.sets;
  sets.insert(sets.end(), extra.begin(), extra.end());
  Scene s = parseScene(c.scene_text, c.scene_source, sets);
  auto* a = std::get_if<ArticleScene>(&s);
  if (!a) throw SceneError(c.spec.scene_where + ": scene " + c.scene_source + " is a HAM-SAS isolator; sweeps take article scenes");
  if (c.spec.segments > 0) overrideSegments(*a, c.spec.segments);
  return std::move(*a);
}

/// The stable vibration modes' shapes at the named points (2 rows per point, 3 on the
/// spatial model: ux, uy, uz), first `count`.
Eigen::MatrixXd pointShapes(const ModesReport& r, int count, std::vector<double>* hz) {
  std::vector<const ModeInfo*> modes;
  for (const auto& m : r.modes)
    if (m.stable && !m.rigid_body && static_cast<int>(modes.size()) < count) modes.push_back(&m);
  const Eigen::Index d = r.spatial ? 3 : 2;
  const Eigen::Index rows = modes.empty() ? 0 : d * static_cast<Eigen::Index>(modes.front()->shape.size());
  Eigen::MatrixXd s(rows, static_cast<Eigen::Index>(modes.size()));
  for (std::size_t k = 0; k < modes.size(); ++k) {
    for (std::size_t p = 0; p < modes[k]->shape.size(); ++p) {
      const PointMotion& u = modes[k]->shape[p];
      s(d * p, k) = u.ux;
      s(d * p + 1, k) = u.uy;
      if (d == 3) s(d * p + 2, k) = u.uz;
    }
    if (hz) hz->push_back(modes[k]->frequency_hz);
  }
  return s;
}

std::string jsonCell(const nlohmann::ordered_json& j, const std::string& pointer) {
  const nlohmann::ordered_json::json_pointer p(pointer);
  if (!j.contains(p)) return "";
  const auto& v = j.at(p);
  if (v.is_null()) return "";  // defined but without a value here (an order not observed): no value, as a failed point
  if (v.is_number()) return cell(v.get<double>());
  if (v.is_string()) return clean(v.get<std::string>());
  return clean(v.dump());
}

}  // namespace

struct SweepPointResult {
  ModesReport modes;
  CheckReport check;
  // What several of a point's columns read, made on the first's demand (a point is one thread's).
  mutable std::optional<nlohmann::ordered_json> modes_json, check_json;
  mutable std::optional<std::vector<std::string>> tracked;  ///< mode<k>_hz, mode<k>_mac cells in turn.
};

namespace {

SweepPointResult analyse(const DesignSweepContext& c, const ArticleScene& scene) {
  SweepPointResult r;
  ModesOptions mo;
  mo.with_shapes = true;
  r.modes = runModes(scene, mo);
  if (wants(c.spec, "check")) r.check = runCheck(scene, {}, &r.modes);
  return r;
}

/// The nominal modes tracked to this point: hz and MAC cells of each (empty: no match).
const std::vector<std::string>& trackedCells(const SweepPointResult& r, const Eigen::MatrixXd& reference, int modes) {
  if (r.tracked) return *r.tracked;
  const Eigen::Index k = reference.cols();
  std::vector<std::string> cells(2 * static_cast<std::size_t>(k));
  std::vector<double> hz;
  const Eigen::MatrixXd now = pointShapes(r.modes, modes + 6, &hz);
  if (now.rows() == reference.rows() && now.cols() > 0) {
    Eigen::MatrixXd padded = Eigen::MatrixXd::Zero(now.rows(), std::max(now.cols(), k));
    padded.leftCols(now.cols()) = now;
    const ModeMatch m = matchModes(reference, padded);
    for (Eigen::Index t = 0; t < k; ++t)
      if (m.index[t] < now.cols()) cells[2 * t] = cell(hz[m.index[t]]), cells[2 * t + 1] = strf("%.4f", m.mac[t]);
  }
  return *(r.tracked = std::move(cells));
}

using Cell = std::function<std::string(const SweepPointResult&)>;

void addColumn(DesignSweepContext& c, std::string key, std::string unit, std::string meaning, bool number, Cell cell) {
  c.columns.push_back({std::move(key), std::move(unit), std::move(meaning), number, std::move(cell)});
}

void addFrequencyColumns(DesignSweepContext& c, const SweepPointResult& nominal) {
  c.reference_shapes = pointShapes(nominal.modes, c.spec.modes, nullptr);
  const auto reference = std::make_shared<const Eigen::MatrixXd>(c.reference_shapes);
  const int modes = c.spec.modes;
  for (Eigen::Index k = 0; k < c.reference_shapes.cols(); ++k) {
    const long n = static_cast<long>(k) + 1;
    for (int part = 0; part < 2; ++part)
      addColumn(c, strf(part ? "mode%ld_mac" : "mode%ld_hz", n), part ? "1" : "Hz",
                part ? strf("MAC of the nominal scene's mode %ld with the mode it was tracked to (below 0.5: it changed character)", n)
                     : strf("frequency of the nominal scene's mode %ld tracked to this point by MAC (empty: no mode matched)", n),
                true, [reference, modes, k, part](const SweepPointResult& r) {
                  return trackedCells(r, *reference, modes)[2 * static_cast<std::size_t>(k) + part];
                });
  }
}

void addCheckColumns(DesignSweepContext& c, const SweepPointResult& nominal) {
  addColumn(c, "check_overall", "", "check's overall verdict at this point", false,
            [](const SweepPointResult& r) { return std::string(verdictName(r.check.overall)); });
  for (const auto& l : nominal.check.lines) {
    if (l.group == "plausibility") continue;
    c.check_ids.push_back(l.id);
    const auto line = [id = l.id](const SweepPointResult& r) -> const CheckLine* {
      for (const auto& x : r.check.lines)
        if (x.id == id) return &x;
      return nullptr;
    };
    addColumn(c, l.id + "_demand", l.unit, "check line " + l.id + ": what the test needs", true, [line](const SweepPointResult& r) {
      const CheckLine* x = line(r);
      return x && !x->unit.empty() ? cell(x->demand) : std::string();
    });
    addColumn(c, l.id + "_margin_pct", "%", "check line " + l.id + ": margin to its capacity", true, [line](const SweepPointResult& r) {
      const CheckLine* x = line(r);
      return x && x->has_capacity ? cell(x->margin_pct) : std::string();
    });
  }
  addColumn(c, "plausibility_warnings", "", "how many plausibility warnings the scene draws at this point", true,
            [](const SweepPointResult& r) {
              int warnings = 0;
              for (const auto& l : r.check.lines) warnings += l.id == "plausibility.warning";
              return std::to_string(warnings);
            });
}

void addFirstModeColumn(DesignSweepContext& c, std::size_t i) {
  const std::string& o = c.spec.outputs[i];
  const std::string link = o.substr(11);
  bool known = false;
  std::string names;
  for (const auto& l : sceneAt(c, {}).article.links)
    known = known || isLinkOrBranch(l.name, link), names += (names.empty() ? "" : ", ") + l.name;
  if (!known) throw SceneError(c.spec.output_where[i] + ": output '" + o + "': no link '" + link + "' (known: " + names + ")");
  addColumn(c, "first_mode_" + link + "_hz", "Hz", "the lowest vibration mode whose strain energy is mostly in " + link, true,
            [link](const SweepPointResult& r) {
              for (const auto& m : r.modes.modes)
                if (m.stable && !m.rigid_body && isLinkOrBranch(m.dominant_link_strain, link)) return cell(m.frequency_hz);
              return std::string();
            });
}

void addJsonColumn(DesignSweepContext& c, std::size_t i, const SweepPointResult& nominal) {
  const std::string& o = c.spec.outputs[i];
  const bool modes = o.rfind("json:modes/", 0) == 0;
  const std::string pointer = o.substr(10);
  const nlohmann::ordered_json j = modes ? modesToJson(nominal.modes) : checkJson(nominal.check);
  try {
    if (!j.contains(nlohmann::ordered_json::json_pointer(pointer)))
      throw SceneError(c.spec.output_where[i] + ": output '" + o + "': the nominal scene's JSON has no such field");
  } catch (const nlohmann::json::exception& e) {
    throw SceneError(c.spec.output_where[i] + ": output '" + o + "' is not a JSON pointer (/key/0/key): " + e.what());
  }
  // A number column when the nominal scene's value is a number, or null (undefined there,
  // a number where defined); a null anywhere is an empty cell, never the text "null".
  const auto& nominal_value = j.at(nlohmann::ordered_json::json_pointer(pointer));
  const bool number = nominal_value.is_number() || nominal_value.is_null();
  addColumn(c, o.substr(5), "", std::string("field ") + pointer + " of " + (modes ? "`modes --json`" : "`check --json`") + " (its unit is the key's)",
            number, [modes, pointer](const SweepPointResult& r) {
              auto& cached = modes ? r.modes_json : r.check_json;
              if (!cached) cached = modes ? modesToJson(r.modes) : checkJson(r.check);
              return jsonCell(*cached, pointer);
            });
}

std::string fnv1a(const std::string& s) {
  std::uint64_t h = 1469598103934665603ull;
  for (unsigned char ch : s) h = (h ^ ch) * 1099511628211ull;
  return strf("%016llx", static_cast<unsigned long long>(h));
}

void layOut(DesignSweepContext& c, const SweepPointResult& nominal) {
  addColumn(c, "point", "", "the point's index in the design (0-based)", true, nullptr);
  for (const auto& p : c.spec.parameters)
    addColumn(c, p.key, sceneKeyUnit(p.key), "scene key " + p.key + " at this point, in the scene's own unit for it", true, nullptr);
  addColumn(c, "status", "", "ok, or what went wrong at this point (the scene refused a value, the equilibrium failed)", false, nullptr);
  for (std::size_t i = 0; i < c.spec.outputs.size(); ++i) {
    const std::string& o = c.spec.outputs[i];
    if (o == "frequencies") {
      addFrequencyColumns(c, nominal);
    } else if (o == "mass") {
      addColumn(c, "mass_kg", "kg", "the article's total mass", true,
                [](const SweepPointResult& r) { return cell(r.modes.model.total_mass_kg); });
    } else if (o == "deflection") {
      addColumn(c, "max_deflection_m", "m", "the largest static deflection of a named point", true, [](const SweepPointResult& r) {
        double d = 0;
        for (const auto& p : r.modes.points) d = std::max(d, std::hypot(p.dx, p.dy));
        return cell(d);
      });
    } else if (o.rfind("first_mode:", 0) == 0) {
      addFirstModeColumn(c, i);
    } else if (o == "check") {
      addCheckColumns(c, nominal);
    } else {
      addJsonColumn(c, i, nominal);
    }
  }
  // Scene keys and JSON pointers as column names every CSV reader keeps (no '.', '/').
  for (auto& col : c.columns) c.header.push_back(col.key = csvColumnName(col.key));
}

}  // namespace

DesignSweepContext prepareDesignSweep(const DesignSweepSpec& spec) {
  DesignSweepContext c;
  c.spec = spec;
  if (spec.scene_path.empty()) {
    c.scene_text = defaultSceneYaml();
    c.scene_source = "<default scene>";
  } else {
    std::string why;
    if (!readInputFile(spec.scene_path, limits::kMaxSceneBytes, c.scene_text, why))
      throw SceneFileError(spec.source + ": scene " + printable(spec.scene_path) + ": cannot read scene file: " + why);
    c.scene_source = spec.scene_path;
  }
  if (spec.outputs.empty()) throw SceneError(spec.source + ": outputs: name at least one");
  // The scene alone (its own errors carry its own positions; a HAM-SAS scene is named
  // at the spec's scene: key), then each set: entry in turn, then each parameter alone:
  // an error points at the spec's line that caused it.
  DesignSweepContext bare = c;
  bare.spec.sets.clear();
  (void)sceneAt(bare, {});
  for (std::size_t i = 0; i < spec.sets.size(); ++i) {
    try {
      bare.spec.sets.push_back(spec.sets[i]);
      (void)sceneAt(bare, {});
    } catch (const std::exception& e) {
      throw SceneError(spec.set_where.at(i) + ": set[" + std::to_string(i) + "] '" + spec.sets[i] + "': " + withoutSetPrefix(e.what(), spec.sets[i]));
    }
  }
  for (std::size_t k = 0; k < spec.parameters.size(); ++k) {  // each key, alone, as in a file
    const SweepParameter& p = spec.parameters[k];
    const std::string set = p.key + "=" + shortest(p.gridValues().empty() ? p.at(0) : p.gridValues().front());
    try {
      (void)sceneAt(c, {set});
    } catch (const std::exception& e) {
      throw SceneError(p.where + ": parameters[" + std::to_string(k) + "] '" + p.key + "': " + withoutSetPrefix(e.what(), set));
    }
  }
  const SweepPointResult nominal = [&] {
    const ProgressStage stage("the nominal scene (before the points)");
    return analyse(c, sceneAt(c, {}));
  }();
  layOut(c, nominal);
  c.points = sweepPoints(spec);
  std::string id = std::string(mmvlabVersion()) + "\n" + spec.text + "\n" + c.scene_text + "\n" + std::to_string(spec.segments) + "\n";
  for (const auto& h : c.header) id += h + ",";
  c.fingerprint = fnv1a(id + std::to_string(c.points.size()));
  return c;
}

std::vector<std::string> evaluateDesignSweepPoint(const DesignSweepContext& c, long index) {
  const std::vector<double>& x = c.points.at(static_cast<std::size_t>(index));
  std::vector<std::string> cells;
  for (double v : x) cells.push_back(cell(v));
  std::string status = "ok";
  std::optional<SweepPointResult> r;
  try {
    r = analyse(c, sceneAt(c, pointOverrides(c.spec, x)));
  } catch (const SceneError& e) {
    status = "scene error: " + std::string(e.what());
  } catch (const NumericalError& e) {
    status = "numerical failure: " + std::string(e.what());
  }
  cells.push_back(clean(status));
  for (std::size_t k = x.size() + 2; k < c.columns.size(); ++k) cells.push_back(r ? c.columns[k].cell(*r) : "");
  if (cells.size() + 1 != c.columns.size()) throw InternalError("a sweep point's cells do not match its columns");
  return cells;
}

nlohmann::ordered_json sweepFieldsJson(const std::vector<SweepColumn>& columns) {
  nlohmann::ordered_json out = nlohmann::ordered_json::array();
  for (const auto& col : columns)
    out.push_back({{"key", col.key}, {"unit", col.unit}, {"number", col.number}, {"meaning", col.meaning}});
  return out;
}

}  // namespace mmv
